/**
 * @class   vtkVolGridQuality
 * @brief   Volume and surface grid quality of the VolGrid paper (section 8.2), threaded, with statistics.
 *
 * Input: a vtkUnstructuredGrid (tetrahedra and wedges are measured; pyramids by the CFD metrics only) or a
 * vtkPolyData (triangles are measured). Other cells are skipped: their values are NaN and a warning says
 * how many there were.
 *
 * Output port 0: the input with per-cell arrays added.
 *  - Volume grids: AspectRatio, MinDihedralAngle, MaxDihedralAngle (degrees), MinSolidAngle (steradians),
 *    Volume (signed: inverted tets are negative), VolumeGradient (largest |volume difference| with a
 *    face neighbour), RadiusEdgeRatio, RadiusRatio (vtkMeshQuality's tet radius ratio); for grids of
 *    tets, wedges and pyramids (no other cell), the CFD metrics of OpenFOAM's checkMesh on every cell
 *    (Core/Quality/CfdQuality.h), each the largest over the cell's faces: NonOrthogonality (degrees),
 *    Skewness, VolumeRatio (with the face neighbours).
 *    Wedges (boundary-layer prisms) get their own arrays, NaN on the other cells (the tet arrays are NaN
 *    on wedges): WedgeVolume (signed) and WedgeScaledJacobian (the smallest corner's, 1 for a right prism
 *    on an equilateral triangle at any height, <= 0 at an inverted corner), as Core/Quality/PrismQuality.h
 *    defines them; field data NumberOfWedges and InvertedWedges (wedges with a corner tet that is not
 *    positive, decided exactly); NumberOfPyramids and PyramidVolume (checkMesh's cell volume). TotalVolume
 *    is the tets' and the wedges' volume; on a grid whose CFD metrics are measured, the sum of checkMesh's
 *    cell volumes, pyramids included (the wedges' own volumes overlap where neighbours split a warped side
 *    quad differently; checkMesh's, split about the quad's centre, add up to the domain's).
 *  - Surface grids: AspectRatio, Area, MinAngle, MaxAngle (degrees).
 *  - Quality: a copy of the selected metric (see SetMetric), so that ParaView colours by it at once.
 *  Field data: per metric a 6-component array "<Metric>Statistics" (Count, Min, Max, Mean, StdDev,
 *  WorstCell), and the grid-wide figures (NumberOfTetrahedra, SkippedCells, TotalVolume, and for
 *  tet, wedge and pyramid grids checkMesh's face figures MaxNonOrthogonality, AverageNonOrthogonality,
 *  SevereNonOrthogonalFaces (> 70 deg), MaxSkewness, HighlySkewFaces (> 4), MaxVolumeRatio; or for
 *  surfaces NumberOfElements, SurfaceArea, EnclosedVolume, BoundaryEdges, BoundaryLoops,
 *  NonManifoldEdges, Shells, SkippedCells).
 *
 * Output port 1: a vtkTable with one row per histogram bin, ready for a bar chart: Bin, and per metric
 * "<Metric>_BinStart", "<Metric>_BinEnd", "<Metric>_Count" (the counts of a metric sum to the number of
 * measured cells). Its field data carries the same summary arrays as port 0, including the index of the
 * worst cell per metric.
 *
 * Under MPI, a vtkUnstructuredGrid carrying GlobalPointIds and GlobalCellIds (VolGrid Tetrahedralize's
 * pieces) is put back together on rank 0 and measured there: every per-cell value (VolumeGradient across
 * piece borders too), the statistics and the histogram equal the one-process ones; the table is on rank 0.
 *
 * The metric definitions and their values for degenerate elements are those of Core/Quality/Quality.h; the
 * statistics are those of Core/Quality/QualityStatistics.h. The loops run with vtkSMPTools; all results are
 * bit-identical for any number of threads. If the process uses the Sequential SMP backend (the default
 * of ParaView's VTK), the filter runs its loops with the STDThread backend for its own duration.
 */
#ifndef vtkVolGridQuality_h
#define vtkVolGridQuality_h

#include "vtkPassInputTypeAlgorithm.h"
#include "vtkVolGridFiltersModule.h"

class VTKVOLGRIDFILTERS_EXPORT vtkVolGridQuality : public vtkPassInputTypeAlgorithm
{
public:
  static vtkVolGridQuality* New();
  vtkTypeMacro(vtkVolGridQuality, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Metrics
  {
    ASPECT_RATIO = 0,
    MIN_DIHEDRAL_ANGLE = 1,
    MAX_DIHEDRAL_ANGLE = 2,
    MIN_SOLID_ANGLE = 3,
    VOLUME = 4,
    VOLUME_GRADIENT = 5,
    RADIUS_EDGE_RATIO = 6,
    RADIUS_RATIO = 7,
    AREA = 8,
    MIN_ANGLE = 9,
    MAX_ANGLE = 10,
    NON_ORTHOGONALITY = 11, // CFD metrics of pure tet grids, as OpenFOAM's checkMesh (Core/Quality/CfdQuality.h)
    SKEWNESS = 12,
    VOLUME_RATIO = 13,
    WEDGE_VOLUME = 14, // boundary-layer prisms (VTK_WEDGE), Core/Quality/PrismQuality.h
    WEDGE_SCALED_JACOBIAN = 15
  };

  ///@{
  /**
   * The metric copied into the "Quality" array (default MIN_DIHEDRAL_ANGLE). A volume metric selected
   * for a surface uses its surface counterpart and vice versa: dihedral and solid angles <-> triangle
   * angles (min to MinAngle, max to MaxAngle), Volume and VolumeGradient <-> Area, RadiusEdgeRatio and
   * RadiusRatio -> AspectRatio. The CFD metrics fall back to MaxDihedralAngle on grids that are not
   * pure tets, the wedge metrics on grids without wedges; both to AspectRatio on surfaces.
   */
  vtkSetClampMacro(Metric, int, ASPECT_RATIO, WEDGE_SCALED_JACOBIAN);
  vtkGetMacro(Metric, int);
  ///@}

  ///@{
  /** Number of histogram bins per metric, in [1, 10000] (default 20). */
  vtkSetClampMacro(BinCount, int, 1, 10000);
  vtkGetMacro(BinCount, int);
  ///@}

  /** The name of a metric's array ("AspectRatio", ...), or nullptr for an invalid value. */
  static const char* GetMetricName(int metric);

  /** After an update: the number of cells that were skipped (not tetrahedra / not triangles). */
  vtkGetMacro(NumberOfSkippedCells, vtkIdType);

protected:
  vtkVolGridQuality();
  ~vtkVolGridQuality() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Metric;
  int BinCount;
  vtkIdType NumberOfSkippedCells;

private:
  vtkVolGridQuality(const vtkVolGridQuality&) = delete;
  void operator=(const vtkVolGridQuality&) = delete;

  bool ExecuteThreaded(class vtkDataSet* input, class vtkDataSet* output, class vtkTable* table);
  bool Execute(class vtkDataSet* input, class vtkDataSet* output, class vtkTable* table);
};

#endif
