/**
 * @class   vtkVolGridTetrahedralize
 * @brief   Exact Delaunay tetrahedralization of a point set (VolGrid Core), as a vtkUnstructuredGrid.
 *
 * The input is any vtkPointSet. Its points are tetrahedralized with VolGrid's exact Delaunay kernel
 * (adaptive exact predicates with Simulation of Simplicity, so cospherical and coplanar inputs give a valid,
 * unique triangulation). Exactly coincident points are merged: the output keeps one point per distinct
 * location, in input order, and the point-data array `InputPointId` maps each output point to the first
 * input point at that location. Input point data is passed through for the kept points.
 *
 * On bad input (no points, NaN/Inf coordinates, all points coplanar) the filter reports an error that
 * says what and where, and produces an empty output.
 */
#ifndef vtkVolGridTetrahedralize_h
#define vtkVolGridTetrahedralize_h

#include "vtkUnstructuredGridAlgorithm.h"
#include "vtkVolGridFiltersModule.h" // for export macro

class VTKVOLGRIDFILTERS_EXPORT vtkVolGridTetrahedralize : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkVolGridTetrahedralize* New();
  vtkTypeMacro(vtkVolGridTetrahedralize, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
   * Verify the output (positive volumes, symmetric adjacency, exact empty-sphere property, closed hull)
   * and report an error if any check fails. Costs about as much as the tetrahedralization. Default off.
   */
  vtkSetMacro(CheckOutput, bool);
  vtkGetMacro(CheckOutput, bool);
  vtkBooleanMacro(CheckOutput, bool);
  ///@}

protected:
  vtkVolGridTetrahedralize();
  ~vtkVolGridTetrahedralize() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool SpatialSort = true;
  int RandomSeed = 1;
  bool CheckOutput = false;

private:
  vtkVolGridTetrahedralize(const vtkVolGridTetrahedralize&) = delete;
  void operator=(const vtkVolGridTetrahedralize&) = delete;
};

#endif
