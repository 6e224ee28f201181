/**
 * @class   vtkVolGridTetrahedralize
 * @brief   VolGrid's tetrahedral mesher: closed surfaces -> boundary-conforming tets; points -> Delaunay.
 *
 * Surface mode (the input has triangles or polygons; polygons are triangulated with a warning): the
 * volume enclosed by one or more closed shells, nested to any depth (e.g. an aircraft inside a far-field
 * sphere), is tetrahedralized so that the boundary of the mesh is exactly the input: same points, same
 * triangles, no point added on the boundary (interior Steiner points may be added and are counted).
 * Output port 0: the tets with the cell array `Region` (active scalars) and `BlockId` = Region + 1 (for the
 * EnSight writer); input point i (after exact merging) is output
 * point i, added points follow; input point data is passed for the input points. Output port 1: the
 * boundary triangles on the same points with `PatchId` (the input's PatchId cell array, else the shell
 * index) and the input's cell data when the input was all triangles.
 *
 * Point mode (no 2D cells, or InputMode = Points): the points of any vtkPointSet are tetrahedralized with
 * the exact Delaunay kernel (adaptive exact predicates with Simulation of Simplicity, so cospherical and
 * coplanar inputs give a valid, unique triangulation). Exactly coincident points are merged: the output
 * keeps one point per distinct location, in input order, and `InputPointId` maps each output point to
 * the first input point at that location. Port 1 is empty.
 *
 * Grid control and quality (surface mode; paper 7.2 and 7.6), on by default:
 *  - Density: Weatherill-Hassan field points (FieldPoints, Alpha, Beta) following the boundary's point
 *    spacing, with a bounded size growth (Gradation) and optional global caps (MaxEdgeLength, MaxVolume).
 *  - Clustering and sizing: an optional second input "Sources" (any vtkDataSet). With
 *    ClusterSourcePoints its points are inserted into the volume (points outside the domain are skipped)
 *    and, when the point array SourceSizeArray exists, each one densifies its neighbourhood to that
 *    target edge length. With SizingFromSources the same array is a sizing field interpolated in space
 *    (e.g. a coarse background mesh, or a CFD solution's error estimate).
 *  - Quality: optimisation (flips, edge removal and smoothing that never touch the boundary) towards a
 *    minimum dihedral angle TargetMinDihedral, at most MaxPasses passes.
 * The boundary stays exactly the input's in every case.
 *
 * Under MPI (pvbatch --mpi, pvserver with several ranks) the pieces of the input on all ranks are gathered
 * onto rank 0 and meshed there once; the tets are then handed out to the ranks in spatially compact pieces
 * with the point array GlobalPointIds and the cell array GlobalCellIds (ids in the one-process mesh), so
 * that downstream filters run in parallel on exactly the one-process mesh. Port 1 stays on rank 0.
 *
 * Bad input (no points, NaN/Inf, all points coplanar; open or self-intersecting surfaces, non-manifold
 * edges, degenerate or duplicate triangles, intersecting shells) gives an error that names the defect,
 * its count and the first ids, and an empty output.
 */
#ifndef vtkVolGridTetrahedralize_h
#define vtkVolGridTetrahedralize_h

#include "vtkUnstructuredGridAlgorithm.h"
#include "vtkVolGridFiltersModule.h" // for export macro

#include <cstdint> // for the patch names
#include <map>     // for the patch names
#include <string>  // for the patch names

class vtkAlgorithmOutput;
class vtkDataSet;
class vtkPointSet;
class vtkPolyData;
struct VolGridSurfaceConversionInfo;
namespace volgrid
{
struct ImprovementOptions;
struct MesherOptions;
struct MesherResult;
struct SurfaceMesh;
}

class VTKVOLGRIDFILTERS_EXPORT vtkVolGridTetrahedralize : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkVolGridTetrahedralize* New();
  vtkTypeMacro(vtkVolGridTetrahedralize, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum InputModes
  {
    AUTOMATIC = 0, // surface mode when the input has 2D cells, point mode otherwise
    POINTS = 1,    // Delaunay of the points, cells ignored
    SURFACE = 2    // boundary-conforming mesh of the enclosed volume
  };
  enum RegionRules
  {
    EVEN_ODD = 0,    // inside the outermost shells, outside the bodies they contain (any orientation)
    ORIENTATION = 1, // facet normals point away from the domain (the paper's rule)
    KEEP_ALL = 2     // every enclosed region, labelled in Region
  };

  ///@{
  /** How the input is read (see InputModes). Default AUTOMATIC. */
  vtkSetClampMacro(InputMode, int, AUTOMATIC, SURFACE);
  vtkGetMacro(InputMode, int);
  ///@}

  ///@{
  /** Which enclosed regions form the domain in surface mode (see RegionRules). Default EVEN_ODD. */
  vtkSetClampMacro(RegionRule, int, EVEN_ODD, KEEP_ALL);
  vtkGetMacro(RegionRule, int);
  ///@}

  ///@{
  /**
   * Surface mode: let boundary recovery add interior Steiner points where flips cannot recover a boundary
   * edge or facet (default on). Off: flips only, which fails on some inputs (reported, never hidden).
   */
  vtkSetMacro(AllowSteinerPoints, bool);
  vtkGetMacro(AllowSteinerPoints, bool);
  vtkBooleanMacro(AllowSteinerPoints, bool);
  ///@}

  ///@{
  /**
   * Insert points in Hilbert/BRIO order (default on). Off inserts them in input order: slower, same mesh.
   */
  vtkSetMacro(SpatialSort, bool);
  vtkGetMacro(SpatialSort, bool);
  vtkBooleanMacro(SpatialSort, bool);
  ///@}

  ///@{
  /**
   * Seed of the randomised insertion order. The mesh does not depend on it (Delaunay is unique under
   * the symbolic tie rule); only the timing does.
   */
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /**
   * Verify the output exactly and report an error if any check fails. Point mode: positive volumes,
   * symmetric adjacency, empty spheres, closed hull. Surface mode: positive volumes, adjacency, boundary
   * equal to the input, volume equal to the enclosed volume. Default off.
   */
  vtkSetMacro(CheckOutput, bool);
  vtkGetMacro(CheckOutput, bool);
  vtkBooleanMacro(CheckOutput, bool);
  ///@}

  ///@{
  /** Density: insert field points (paper 7.2) in surface mode. Default on. */
  vtkSetMacro(FieldPoints, bool);
  vtkGetMacro(FieldPoints, bool);
  vtkBooleanMacro(FieldPoints, bool);
  ///@}

  ///@{
  /**
   * Density: eq. 4's alpha. A tet gets a point at its centroid when the centroid is farther than
   * Alpha * h from the tet's vertices (h: the local target edge length). Smaller = more points.
   * Default: Core's OptionTable.h (mean edge length close to h).
   */
  virtual void SetAlpha(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(Alpha, double);
  ///@}

  ///@{
  /** Density: eq. 5's beta, the minimum spacing of field points in units of h. Default: Core's OptionTable.h. */
  virtual void SetBeta(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(Beta, double);
  ///@}

  ///@{
  /**
   * Density: size growth between neighbours, h(v) <= h(u) + (Gradation - 1) |uv|; away from the
   * boundary the size grows at that rate unless something smaller is asked. Smaller = finer. Default: OptionTable.h.
   */
  virtual void SetGradation(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(Gradation, double);
  ///@}

  ///@{
  /**
   * Density: target edge length at the boundary as a multiple of the boundary's own spacing (its mean
   * edge length per point, paper eq. 3). Default (OptionTable.h) 1: the volume as fine as the surface at the boundary.
   */
  virtual void SetSizeScale(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(SizeScale, double);
  ///@}

  ///@{
  /** Density: cap on the target edge length, graded up to coarser boundary triangles (0 = none). Default: Core's
   * OptionTable.h. */
  virtual void SetMaxEdgeLength(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(MaxEdgeLength, double);
  ///@}

  ///@{
  /** Density: global cap on the tet volume (0 = none). Default: Core's OptionTable.h. */
  virtual void SetMaxVolume(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(MaxVolume, double);
  ///@}

  ///@{
  /** Clustering: insert the points of the second input (Sources) into the volume. Default on. */
  vtkSetMacro(ClusterSourcePoints, bool);
  vtkGetMacro(ClusterSourcePoints, bool);
  vtkBooleanMacro(ClusterSourcePoints, bool);
  ///@}

  ///@{
  /**
   * Clustering and sizing: the point array of Sources holding target edge lengths (empty = none).
   * Non-finite or non-positive values mean "no target here".
   */
  vtkSetStringMacro(SourceSizeArray);
  vtkGetStringMacro(SourceSizeArray);
  ///@}

  ///@{
  /**
   * Boundary patches: names and groups of the input's PatchId values, "NAME=ID,ID,NAME=ID,..." as the
   * CLI's --patch (Core/Mesh/PatchNames.h): group k gets PatchId k + 1 and its name, ids not listed keep their
   * own patch after the groups. Empty (default): the input's PatchId and PatchNames are kept as they are.
   */
  vtkSetStringMacro(PatchAssignment);
  vtkGetStringMacro(PatchAssignment);
  ///@}

  ///@{
  /** Sizing: interpolate SourceSizeArray in space as a sizing field. Default off. */
  vtkSetMacro(SizingFromSources, bool);
  vtkGetMacro(SizingFromSources, bool);
  vtkBooleanMacro(SizingFromSources, bool);
  ///@}

  ///@{
  /** Quality: optimise the mesh (flips, edge removal, smoothing). Default on. */
  vtkSetMacro(Optimize, bool);
  vtkGetMacro(Optimize, bool);
  vtkBooleanMacro(Optimize, bool);
  ///@}

  ///@{
  /**
   * Quality: target for min(smallest dihedral angle, 180 - largest) in degrees. Default: OptionTable.h. Tets whose
   * four vertices lie on the boundary keep the shape the boundary triangles give them.
   */
  virtual void SetTargetMinDihedral(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(TargetMinDihedral, double);
  ///@}

  ///@{
  /** Quality: optimisation pass limit. Default: Core's OptionTable.h. */
  virtual void SetMaxPasses(int value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(MaxPasses, int);
  ///@}

  ///@{
  /** Quality: smoothing (paper 7.6) between the topological passes. Default on. */
  vtkSetMacro(Smoothing, bool);
  vtkGetMacro(Smoothing, bool);
  vtkBooleanMacro(Smoothing, bool);
  ///@}

  ///@{
  /**
   * Quality for finite-volume solvers: the quality stage adds no face that checkMesh finds severely
   * non-orthogonal (> 70 deg) and no tet under the target where it edits, except to fix tets under 2 deg
   * (Core's OrthogonalityFirst.h): a quarter to a half of the severe faces, a smaller worst dihedral
   * angle. Default off.
   */
  vtkSetMacro(OrthogonalityFirst, bool);
  vtkGetMacro(OrthogonalityFirst, bool);
  vtkBooleanMacro(OrthogonalityFirst, bool);
  ///@}

  ///@{
  /**
   * Boundary layers: the number of prism layers grown from the wall patches (0, the default: none).
   * With layers, output 0 holds VTK_WEDGE cells in the layers (VTK_PYRAMID and VTK_TETRA where a column
   * collapsed onto the wall) and VTK_TETRA cells elsewhere (cell arrays LayerIndex, ThinnedReason, Region) and output 1
   * the boundary triangles and the prisms' side quads on symmetry planes. Default and range: Core's OptionTable.h.
   */
  virtual void SetNumberOfLayers(int value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(NumberOfLayers, int);
  ///@}

  ///@{
  /** Boundary layers: height of the layer on the wall (needed with layers). */
  virtual void SetFirstLayerHeight(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(FirstLayerHeight, double);
  ///@}

  ///@{
  /** Boundary layers: ratio between consecutive layer heights. Default: Core's OptionTable.h. */
  virtual void SetLayerGrowthRatio(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(LayerGrowthRatio, double);
  // Total thickness of the layers (0: not given): with FirstLayerHeight the growth ratio is solved for
  // (LayerGrowthRatio is then not used), without it the first height for LayerGrowthRatio.
  virtual void SetTotalLayerThickness(double value); // clamped to the valid range of Core's OptionTable.h
  vtkGetMacro(TotalLayerThickness, double);
  ///@}

  ///@{
  /** Boundary layers: comma-separated patch names or PatchId numbers; empty (default): every wall patch. */
  vtkSetStringMacro(LayerPatches);
  vtkGetStringMacro(LayerPatches);
  ///@}

  ///@{
  /** Boundary layers: every prism as three tets (consistent cuts), for tet-only solvers. Default off. */
  vtkSetMacro(SplitPrisms, bool);
  vtkGetMacro(SplitPrisms, bool);
  vtkBooleanMacro(SplitPrisms, bool);
  ///@}

  ///@{
  /** Boundary layers: keep the wall's triangles even around edges whose prism side faces checkMesh would
   * find highly skewed (by default the triangles there are split at edge midpoints first). Default off. */
  vtkSetMacro(KeepWallTriangles, bool);
  vtkGetMacro(KeepWallTriangles, bool);
  vtkBooleanMacro(KeepWallTriangles, bool);
  ///@}

  /** Convenience: the second input (Sources) connection. */
  void SetSourceConnection(vtkAlgorithmOutput* output);

protected:
  vtkVolGridTetrahedralize();
  ~vtkVolGridTetrahedralize() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // The serial run on a whole input (every rank's part gathered when there are several ranks).
  int Execute(vtkPointSet* input, vtkDataSet* sources, vtkUnstructuredGrid* output, vtkPolyData* boundary);
  int TetrahedralizePoints(vtkPointSet* input, vtkUnstructuredGrid* output);
  int MeshSurface(vtkPointSet* input, vtkDataSet* sources, vtkUnstructuredGrid* output, vtkPolyData* boundary);
  // The steps of MeshSurface (each returns false after its error message).
  volgrid::MesherOptions MakeMesherOptions() const;
  bool ConvertInput(vtkPointSet* input, volgrid::SurfaceMesh& surface, VolGridSurfaceConversionInfo& converted);
  bool TakeSourcePoints(vtkDataSet* sources, volgrid::ImprovementOptions& im);
  bool FitsInMemory(const volgrid::SurfaceMesh& surface, const volgrid::MesherOptions& options);
  bool AssignPatches(vtkPointSet* input, volgrid::MesherResult& result, std::map<int32_t, std::string>& patchNames);
  // MeshSurface with boundary layers (NumberOfLayers > 0): prisms plus tets.
  int MeshWithLayers(const volgrid::SurfaceMesh& surface, const volgrid::MesherOptions& options,
                     vtkUnstructuredGrid* output, vtkPolyData* boundary);

  int InputMode = AUTOMATIC;
  int RegionRule = EVEN_ODD;
  bool AllowSteinerPoints = true;
  bool SpatialSort = true;
  int RandomSeed = 1;
  bool CheckOutput = false;
  bool FieldPoints = true;
  double Alpha = 0;         // the default: the constructor, from Core
  double Beta = 0;          // the default: the constructor, from Core
  double Gradation = 0;     // the default: the constructor, from Core
  double SizeScale = 0;     // the default: the constructor, from Core
  double MaxEdgeLength = 0; // the default: the constructor, from Core
  double MaxVolume = 0;     // the default: the constructor, from Core
  bool ClusterSourcePoints = true;
  char* SourceSizeArray = nullptr;
  char* PatchAssignment = nullptr;
  bool SizingFromSources = false;
  bool Optimize = true;
  double TargetMinDihedral = 0; // the default: the constructor, from Core
  int MaxPasses = 0;            // the default: the constructor, from Core
  bool Smoothing = true;
  bool OrthogonalityFirst = false;
  int NumberOfLayers = 0;         // the default: the constructor, from Core
  double FirstLayerHeight = 0;    // the default: the constructor, from Core
  double LayerGrowthRatio = 0;    // the default: the constructor, from Core
  double TotalLayerThickness = 0; // the default: the constructor, from Core
  char* LayerPatches = nullptr;
  bool SplitPrisms = false;
  bool KeepWallTriangles = false;

private:
  vtkVolGridTetrahedralize(const vtkVolGridTetrahedralize&) = delete;
  void operator=(const vtkVolGridTetrahedralize&) = delete;
};

#endif
