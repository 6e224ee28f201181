// The surface path of vtkVolGridQuality: a thin adapter from a vtkPolyData's triangles to Core/Quality's
// triangle metrics and surface figures (Quality.h).
#include "VolGridQualitySurface.h"

#include "VolGridQualityArrays.h"
#include "vtkVolGridQuality.h"

#include "Quality.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace
{
namespace vq = volgrid::quality;
using Q = vtkVolGridQuality;
} // namespace

bool VolGridMeasureSurface(vtkAlgorithm* self, vtkPolyData* input, std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays,
                           vtkFieldData* summary, vtkIdType& skippedCells)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<double> pointStorage;
  const double* points = numPoints ? VolGridFlatPoints(input->GetPoints(), pointStorage) : nullptr;

  // Triangles of the polys; polys come after the verts and lines in the cell numbering.
  std::vector<int64_t> tris;
  std::vector<vtkIdType> triCells;
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  auto it = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  vtkIdType cell = firstPoly;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    if (npts != 3)
      continue;
    for (int k = 0; k < 3; ++k)
    {
      if (pts[k] < 0 || pts[k] >= numPoints)
      {
        vtkErrorWithObjectMacro(self, "Cell " << cell << " has a point id outside [0, " << numPoints << ").");
        return false;
      }
      tris.push_back(pts[k]);
    }
    triCells.push_back(cell);
  }
  const vtkIdType numTris = static_cast<vtkIdType>(triCells.size());
  skippedCells = numCells - numTris;

  const int surfaceMetrics[4] = { Q::ASPECT_RATIO, Q::AREA, Q::MIN_ANGLE, Q::MAX_ANGLE };
  for (int m : surfaceMetrics)
  {
    arrays.push_back(VolGridNewCellArray(vtkVolGridQuality::GetMetricName(m), numCells));
    arrays.back()->Fill(std::numeric_limits<double>::quiet_NaN());
  }
  double* aspect = arrays[0]->GetPointer(0);
  double* area = arrays[1]->GetPointer(0);
  double* minAngle = arrays[2]->GetPointer(0);
  double* maxAngle = arrays[3]->GetPointer(0);
  if (!VolGridParallelBlocks(self, numTris, 0.0, 0.6,
                             [&](vtkIdType b, vtkIdType e)
                             {
                               for (vtkIdType t = b; t < e; ++t)
                               {
                                 const int64_t* v = tris.data() + 3 * t;
                                 const vq::TriangleMetrics m =
                                   vq::triangleMetrics(points + 3 * v[0], points + 3 * v[1], points + 3 * v[2]);
                                 const vtkIdType c = triCells[t];
                                 aspect[c] = m.aspectRatio;
                                 area[c] = m.area;
                                 minAngle[c] = m.minAngle;
                                 maxAngle[c] = m.maxAngle;
                               }
                             }))
  {
    return false;
  }
  self->SetProgressText("Surface topology");
  const vq::SurfaceSummary s = vq::surfaceSummary(points, numPoints, tris.data(), numTris);
  self->UpdateProgress(0.85);
  if (skippedCells > 0)
  {
    vtkWarningWithObjectMacro(self, << skippedCells << " of " << numCells
                                    << " cells are not triangles: they were skipped (their values are NaN).");
  }
  VolGridAddScalar(summary, "NumberOfElements", static_cast<double>(s.elements));
  VolGridAddScalar(summary, "SurfaceArea", s.area);
  VolGridAddScalar(summary, "EnclosedVolume", s.enclosedVolume);
  VolGridAddScalar(summary, "BoundaryEdges", static_cast<double>(s.boundaryEdges));
  VolGridAddScalar(summary, "BoundaryLoops", static_cast<double>(s.boundaryLoops));
  VolGridAddScalar(summary, "NonManifoldEdges", static_cast<double>(s.nonManifoldEdges));
  VolGridAddScalar(summary, "Shells", static_cast<double>(s.shells));
  VolGridAddScalar(summary, "SkippedCells", static_cast<double>(skippedCells));
  return true;
}
