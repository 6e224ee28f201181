/**
 * @class   vtkVolGridTetrahedralize
 * @brief   VolGrid's tetrahedral mesher: closed surfaces -> boundary-conforming tets; points -> Delaunay.
 *
 * Surface mode (the input has triangles or polygons; polygons are triangulated with a warning): the
 * volume enclosed by one or more closed shells, nested to any depth (e.g. an aircraft inside a far-field
 * sphere), is tetrahedralized so that the boundary of the mesh is exactly the input: same points, same
 * triangles, no point added on the boundary (interior Steiner points may be added and are counted).
 * Output port 0: the tets with the cell array `Region`; input point i (after exact merging) is output
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
 * Bad input (no points, NaN/Inf, all points coplanar; open or self-intersecting surfaces, non-manifold
 * edges, degenerate or duplicate triangles, intersecting shells) gives an error that names the defect,
 * its count and the first ids, and an empty output.
 */
#ifndef vtkVolGridTetrahedralize_h
#define vtkVolGridTetrahedralize_h

#include "vtkUnstructuredGridAlgorithm.h"
#include "vtkVolGridFiltersModule.h" // for export macro

class vtkPointSet;
class vtkPolyData;

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

protected:
  vtkVolGridTetrahedralize();
  ~vtkVolGridTetrahedralize() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int TetrahedralizePoints(vtkPointSet* input, vtkUnstructuredGrid* output);
  int MeshSurface(vtkPointSet* input, vtkUnstructuredGrid* output, vtkPolyData* boundary);

  int InputMode = AUTOMATIC;
  int RegionRule = EVEN_ODD;
  bool AllowSteinerPoints = true;
  bool SpatialSort = true;
  int RandomSeed = 1;
  bool CheckOutput = false;

private:
  vtkVolGridTetrahedralize(const vtkVolGridTetrahedralize&) = delete;
  void operator=(const vtkVolGridTetrahedralize&) = delete;
};

#endif
