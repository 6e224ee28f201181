/**
 * @class   vtkVolGridSurfacePrep
 * @brief   Makes surfaces meshable (VolGrid paper, section 6): merge parts, repair, orient, diagnose, and
 *          add a far-field enclosure.
 *
 * Input port 0 is repeatable and optional: each connection is a part (a vtkPolyData, any other data set's
 * 2D cells, or every leaf of a composite data set such as a vtkMultiBlockDataSet). Polygons and strips are
 * triangulated. With no input, the filter is a source that makes just the enclosure.
 *
 * Steps (VolGrid Core, exact predicates): weld points closer than MergeTolerance times the bounding-box
 * diagonal (or exactly coincident points only), remove zero-area and duplicate triangles, stitch parts
 * along shared boundaries, fill boundary loops of at most MaxHoleEdges edges with a refined, faired patch,
 * orient every shell consistently, then (after the enclosure is added) orient closed shells away from
 * the domain: the outermost shell outward, bodies inside it inward, cavities of bodies outward again.
 *
 * Output port 0: the clean surface (triangles, double points) with the cell arrays
 *  - PatchId: the part index (parts in connection order, composite leaves in order); when a part has a
 *    cell array named PatchId its values are kept, shifted past the ids of earlier parts. The enclosure
 *    gets the next id (see GetEnclosurePatchId).
 *  - DefectFlags: the bits of volgrid::SurfaceTriangleFlag; and 0/1 arrays OpenEdge, NonManifoldEdge,
 *    SelfIntersecting (crossing a triangle of its own or of another shell), Degenerate; ShellId.
 *  point array NonManifoldVertex (0/1); and field data: the counts of every defect class before
 *  ("Input..." arrays) and after the repair, what the repair did (WeldedPoints, RemovedDegenerate,
 *  RemovedDuplicates, StitchedPoints, LoopsFilled, LoopsLeftOpen, TrianglesAdded, TrianglesFlipped,
 *  ShellsFlipped), Meshable (1 when VolGrid Tetrahedralize accepts the surface), and the report as text
 *  (string array SurfacePrepReport).
 * Output port 1: a vtkTable summary, one row per defect class or repair action: Category, Item, Input
 *  (count before), Output (count after, or the repair count), FirstIds (the first offending triangle,
 *  edge or point ids of the output, as text).
 * Output port 2: the defective edges of the output as lines (same points) with the cell arrays EdgeFlags
 *  (volgrid::SurfaceEdgeFlag bits) and Valence, to show open and non-manifold edges in colour.
 *
 * Defects the filter cannot repair (self-intersections, intersecting shells, non-manifold edges, holes
 * larger than MaxHoleEdges) are reported with counts and first ids by a warning and in the field data;
 * the cleaned surface is still produced. Progress is reported and the filter stops when aborted.
 */
#ifndef vtkVolGridSurfacePrep_h
#define vtkVolGridSurfacePrep_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkVolGridFiltersModule.h" // for export macro

class vtkTable;

class VTKVOLGRIDFILTERS_EXPORT vtkVolGridSurfacePrep : public vtkPolyDataAlgorithm
{
public:
  static vtkVolGridSurfacePrep* New();
  vtkTypeMacro(vtkVolGridSurfacePrep, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum EnclosureTypes
  {
    ENCLOSURE_NONE = 0,
    ENCLOSURE_BOX = 1,
    ENCLOSURE_SPHERE = 2,
    ENCLOSURE_CYLINDER = 3,
    ENCLOSURE_HEMISPHERE = 4,
    ENCLOSURE_ELLIPSOID = 5
  };

  ///@{
  /**
   * Points on open edges closer than MergeTolerance times the input's bounding-box diagonal are welded
   * (points of closed parts never are: they are distinct vertices), and parts are stitched along boundary
   * points that close (range [0, 0.01], default 1e-6). ExactMergeOnly (default
   * off) merges only exactly coincident points, whatever the tolerance.
   */
  vtkSetClampMacro(MergeTolerance, double, 0.0, 0.01);
  vtkGetMacro(MergeTolerance, double);
  vtkSetMacro(ExactMergeOnly, bool);
  vtkGetMacro(ExactMergeOnly, bool);
  vtkBooleanMacro(ExactMergeOnly, bool);
  ///@}

  ///@{
  /** Remove zero-area triangles (default on) and triangles repeating another's points (default on). */
  vtkSetMacro(RemoveDegenerate, bool);
  vtkGetMacro(RemoveDegenerate, bool);
  vtkBooleanMacro(RemoveDegenerate, bool);
  vtkSetMacro(RemoveDuplicates, bool);
  vtkGetMacro(RemoveDuplicates, bool);
  vtkBooleanMacro(RemoveDuplicates, bool);
  ///@}

  ///@{
  /**
   * Fill boundary loops (holes) of at most MaxHoleEdges edges (default on, 200; range [3, 1000000]): scan
   * holes are filled, large openings (a half model's symmetry plane) are left open and reported.
   * The patch follows the surrounding surface and has edges as long as the loop's.
   */
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);
  vtkSetClampMacro(MaxHoleEdges, int, 3, 1000000);
  vtkGetMacro(MaxHoleEdges, int);
  ///@}

  ///@{
  /**
   * Orient every shell consistently and closed shells away from the domain (default on).
   */
  vtkSetMacro(OrientShells, bool);
  vtkGetMacro(OrientShells, bool);
  vtkBooleanMacro(OrientShells, bool);
  ///@}

  ///@{
  /** Look for self-intersecting triangles with exact predicates (default on). */
  vtkSetMacro(CheckIntersections, bool);
  vtkGetMacro(CheckIntersections, bool);
  vtkBooleanMacro(CheckIntersections, bool);
  ///@}

  ///@{
  /**
   * Add the diagnostic arrays to the surface: cell arrays DefectFlags (bit mask), OpenEdge,
   * NonManifoldEdge, SelfIntersecting, Degenerate and the point array NonManifoldVertex. Default off: they
   * diagnose this surface only, and would otherwise ride on into the volume mesh and every export.
   * ShellId and PatchId are always there; PatchId is the active scalar.
   */
  vtkSetMacro(DiagnosticArrays, bool);
  vtkGetMacro(DiagnosticArrays, bool);
  vtkBooleanMacro(DiagnosticArrays, bool);
  ///@}

  ///@{
  /** The far-field enclosure added around the input (default ENCLOSURE_NONE). */
  vtkSetClampMacro(Enclosure, int, ENCLOSURE_NONE, ENCLOSURE_ELLIPSOID);
  vtkGetMacro(Enclosure, int);
  ///@}

  ///@{
  /**
   * Size of the enclosure as a factor of the input's bounding box (range [1, 1e6], default 10): 1 just
   * encloses the box (sphere of the half diagonal, the box itself, the ellipsoid through its corners, the
   * cylinder around it along EnclosureAxis); the hemisphere's disk lies on the box's minimum face along
   * EnclosureAxis (a half model's symmetry plane).
   */
  vtkSetClampMacro(EnclosureScale, double, 1.0, 1.0e6);
  vtkGetMacro(EnclosureScale, double);
  ///@}

  ///@{
  /**
   * Use EnclosureCenter and EnclosureDimensions instead of EnclosureScale (default off; always the case
   * with no input). Dimensions: box edge lengths; sphere and hemisphere radius (first value); cylinder
   * radius and height (first two values); ellipsoid semi-axes.
   */
  vtkSetMacro(ExplicitEnclosure, bool);
  vtkGetMacro(ExplicitEnclosure, bool);
  vtkBooleanMacro(ExplicitEnclosure, bool);
  vtkSetVector3Macro(EnclosureCenter, double);
  vtkGetVector3Macro(EnclosureCenter, double);
  vtkSetVector3Macro(EnclosureDimensions, double);
  vtkGetVector3Macro(EnclosureDimensions, double);
  ///@}

  ///@{
  /** Axis of the cylinder and of the hemisphere's dome (0 x, 1 y, 2 z; default 2). */
  vtkSetClampMacro(EnclosureAxis, int, 0, 2);
  vtkGetMacro(EnclosureAxis, int);
  ///@}

  ///@{
  /** Target edge length of the enclosure's triangles (0, the default: about 1/16 of its size). */
  vtkSetClampMacro(EnclosureEdgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EnclosureEdgeLength, double);
  ///@}

  /** After an update: the enclosure's PatchId (-1 without enclosure), and whether the mesher accepts the output. */
  vtkGetMacro(EnclosurePatchId, int);
  vtkGetMacro(Meshable, bool);

protected:
  vtkVolGridSurfacePrep();
  ~vtkVolGridSurfacePrep() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // The filter's work; under MPI (controller set) the parts are gathered and only rank 0 works on them.
  int Prepare(vtkInformationVector** inputVector, vtkInformationVector* outputVector,
              class vtkMultiProcessController* controller);

  double MergeTolerance = 1.0e-6;
  bool ExactMergeOnly = false;
  bool RemoveDegenerate = true;
  bool RemoveDuplicates = true;
  bool FillHoles = true;
  int MaxHoleEdges = 200;
  bool OrientShells = true;
  bool CheckIntersections = true;
  bool DiagnosticArrays = false;
  int Enclosure = ENCLOSURE_NONE;
  double EnclosureScale = 10.0;
  bool ExplicitEnclosure = false;
  double EnclosureCenter[3] = { 0.0, 0.0, 0.0 };
  double EnclosureDimensions[3] = { 1.0, 1.0, 1.0 };
  int EnclosureAxis = 2;
  double EnclosureEdgeLength = 0.0;
  int EnclosurePatchId = -1;
  bool Meshable = false;

private:
  vtkVolGridSurfacePrep(const vtkVolGridSurfacePrep&) = delete;
  void operator=(const vtkVolGridSurfacePrep&) = delete;
};

#endif
