#include "VolGridSurfaceConversion.h"
#include "VolGridConversion.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "PolygonTriangulation.h"
#include "SurfaceMesh.h"
#include "SurfaceReader.h"

#include <algorithm>
#include <cmath>
#include <vector>

bool VolGridAppendSurface(vtkDataSet* input, volgrid::SurfaceMesh& mesh, const char* patchArrayName,
                          int32_t patchOffset, int32_t defaultPatch, VolGridSurfaceConversionInfo* info)
{
  VolGridSurfaceConversionInfo local;
  VolGridSurfaceConversionInfo& out = info ? *info : local;
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    return false;
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const int32_t base = mesh.numberOfPoints();
  mesh.points.reserve(mesh.points.size() + 3 * static_cast<size_t>(numPoints));
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    mesh.points.insert(mesh.points.end(), p, p + 3);
  }

  vtkDataArray* patchArray = patchArrayName ? input->GetCellData()->GetArray(patchArrayName) : nullptr;
  // A patch id per new triangle; the mesh gets patch ids when it has some already or any are >= 0.
  const size_t firstTriangle = static_cast<size_t>(mesh.numberOfTriangles());
  std::vector<int32_t> newPatches;

  const vtkIdType numCells = input->GetNumberOfCells();
  vtkNew<vtkIdList> ids;
  std::vector<int32_t> loop;
  std::vector<int32_t> clipped;
  std::vector<double> polygonPoints;
  std::vector<vtkIdType> corners;
  const vtkIdType trianglesBefore = static_cast<vtkIdType>(firstTriangle);
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    const int type = input->GetCellType(c);
    if (type != VTK_TRIANGLE && type != VTK_QUAD && type != VTK_POLYGON && type != VTK_PIXEL &&
        type != VTK_TRIANGLE_STRIP)
    {
      ++out.skippedCells;
      continue;
    }
    input->GetCellPoints(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    bool valid = n >= 3;
    for (vtkIdType k = 0; k < n && valid; ++k)
    {
      valid = ids->GetId(k) >= 0 && ids->GetId(k) < numPoints;
    }
    if (!valid)
    {
      ++(n < 3 ? out.skippedCells : out.invalidCells);
      continue;
    }
    int32_t patch = defaultPatch;
    if (patchArray)
    {
      const double v = patchArray->GetComponent(c, 0);
      patch = std::isfinite(v) ? static_cast<int32_t>(std::lround(v)) + patchOffset : defaultPatch;
    }
    auto add = [&](vtkIdType a, vtkIdType b, vtkIdType d)
    {
      mesh.triangles.push_back(base + static_cast<int32_t>(a));
      mesh.triangles.push_back(base + static_cast<int32_t>(b));
      mesh.triangles.push_back(base + static_cast<int32_t>(d));
      newPatches.push_back(patch);
    };
    if (type == VTK_TRIANGLE_STRIP)
    {
      for (vtkIdType k = 0; k + 2 < n; ++k)
      {
        if (k % 2 == 0)
          add(ids->GetId(k), ids->GetId(k + 1), ids->GetId(k + 2));
        else
          add(ids->GetId(k + 1), ids->GetId(k), ids->GetId(k + 2));
      }
      ++out.strips;
    }
    else if (n == 3)
    {
      add(ids->GetId(0), ids->GetId(1), ids->GetId(2));
      ++out.triangles;
    }
    else
    {
      // Quads, pixels and polygons: ear clipping in the polygon's plane (pixels are stored in raster order).
      loop.clear();
      polygonPoints.clear();
      corners.clear();
      for (vtkIdType k = 0; k < n; ++k)
      {
        const vtkIdType id = (type == VTK_PIXEL && n == 4) ? ids->GetId(k == 2 ? 3 : (k == 3 ? 2 : k)) : ids->GetId(k);
        corners.push_back(id);
        loop.push_back(static_cast<int32_t>(k));
        double p[3];
        input->GetPoint(id, p);
        polygonPoints.insert(polygonPoints.end(), p, p + 3);
      }
      clipped.clear();
      if (!volgrid::triangulatePolygon(polygonPoints, loop, clipped))
      {
        ++out.fanFallbacks;
      }
      for (size_t t = 0; t + 2 < clipped.size(); t += 3)
      {
        add(corners[clipped[t]], corners[clipped[t + 1]], corners[clipped[t + 2]]);
      }
      ++out.polygons;
    }
  }

  const bool anyPatch =
    mesh.hasPatchIds() || std::any_of(newPatches.begin(), newPatches.end(), [](int32_t p) { return p >= 0; });
  if (anyPatch)
  {
    mesh.patchIds.resize(firstTriangle, -1);
    mesh.patchIds.insert(mesh.patchIds.end(), newPatches.begin(), newPatches.end());
  }
  return static_cast<vtkIdType>(mesh.numberOfTriangles()) > trianglesBefore;
}

bool VolGridPolyDataToSurfaceMesh(vtkDataSet* input, volgrid::SurfaceMesh& mesh, VolGridSurfaceConversionInfo* info)
{
  mesh.clear();
  mesh.patchNames = VolGridReadLabelNames(input, "PatchNames");
  return VolGridAppendSurface(input, mesh, "PatchId", 0, -1, info);
}

void VolGridSurfaceMeshToPolyData(const volgrid::SurfaceMesh& mesh, vtkPolyData* output, const char* patchArrayName)
{
  output->Initialize();
  const vtkIdType numPoints = mesh.numberOfPoints();
  const vtkIdType numTriangles = mesh.numberOfTriangles();
  auto coords = vtkSmartPointer<vtkDoubleArray>::New();
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(numPoints);
  std::copy(mesh.points.begin(), mesh.points.end(), coords->GetPointer(0));
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coords);

  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(numTriangles + 1);
  connectivity->SetNumberOfValues(3 * numTriangles);
  for (vtkIdType t = 0; t <= numTriangles; ++t)
  {
    offsets->SetValue(t, 3 * t);
  }
  for (vtkIdType i = 0; i < 3 * numTriangles; ++i)
  {
    connectivity->SetValue(i, mesh.triangles[static_cast<size_t>(i)]);
  }
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);

  if (patchArrayName && mesh.hasPatchIds())
  {
    auto patches = vtkSmartPointer<vtkIntArray>::New();
    patches->SetName(patchArrayName);
    patches->SetNumberOfValues(numTriangles);
    for (vtkIdType t = 0; t < numTriangles; ++t)
    {
      patches->SetValue(t, mesh.patchIds[static_cast<size_t>(t)]);
    }
    output->GetCellData()->AddArray(patches);
    VolGridSetLabelNames(output, "PatchNames", mesh.patchIds, mesh.patchNames, "patch");
  }
}
