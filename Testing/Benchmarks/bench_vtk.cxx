// vtkDelaunay3D from ParaView's bundled VTK (VTK::FiltersCore). Very slow: the driver runs it at 100k
// points only. Alpha = 0 (the default): the whole Delaunay triangulation of the convex hull.
#include "bench_common.h"

#include <vtkDelaunay3D.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>

namespace volgrid_bench
{

bool runVtkDelaunay3D(const std::vector<double>& xyz, Meter& meter, EngineResult& result)
{
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  std::copy(xyz.begin(), xyz.end(), static_cast<double*>(points->GetVoidPointer(0)));
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);

  vtkNew<vtkDelaunay3D> delaunay;
  delaunay->SetInputData(input);
  meter.start();
  delaunay->Update();
  meter.stop();
  vtkUnstructuredGrid* output = delaunay->GetOutput();
  if (!output)
  {
    result.error = "vtkDelaunay3D produced no output";
    return false;
  }
  result.tets = output->GetNumberOfCells();
  result.points = output->GetNumberOfPoints();
  result.threads = 1;
  result.ok = true;
  return true;
}

} // namespace volgrid_bench
