#include "VolGridLayeredConversion.h"

#include "VolGridCellOrder.h"
#include "VolGridConversion.h"

#include "BoundaryFaceOwners.h"
#include "LayeredMesher.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cstdint>
#include <vector>

namespace
{
// BoundaryFacePatch of the volume (see the header), in its cell order: prisms, pyramids, tets.
vtkSmartPointer<vtkIntArray> mixedBoundaryFacePatch(const volgrid::SolverMesh& mesh)
{
  if (!volgrid::hasLayerCells(mesh)) // split prisms: a tet grid like any other
    return VolGridBoundaryFacePatch(mesh.tets, mesh.triangles, mesh.trianglePatch);
  const int64_t tets = mesh.numberOfTets(), prisms = static_cast<int64_t>(mesh.prisms.size() / 6);
  const int64_t pyramids = static_cast<int64_t>(mesh.pyramids.size() / 5);
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName("BoundaryFacePatch");
  array->SetNumberOfComponents(5);
  array->SetNumberOfTuples(static_cast<vtkIdType>(tets + prisms + pyramids));
  array->Fill(-1);
  std::vector<volgrid::CellSide> owners;
  volgrid::findBoundaryCellSides(mesh, owners); // a face without a cell has no entry (cell -1)
  const size_t numTriangles = mesh.trianglePatch.size();
  for (size_t f = 0; f < owners.size(); ++f)
  {
    const int64_t c = owners[f].cell; // Core's order: tets, prisms, pyramids
    if (c < 0)
      continue;
    const int64_t cell = c < tets ? prisms + pyramids + c : c - tets; // layer cells keep their order
    const int32_t patch = f < numTriangles ? mesh.trianglePatch[f] : mesh.quadPatch[f - numTriangles];
    array->SetTypedComponent(static_cast<vtkIdType>(cell), owners[f].side, patch);
  }
  return array;
}

template<typename T>
void appendTo(vtkAOSDataArrayTemplate<T>* array, const std::vector<T>& values, size_t count, T missing)
{
  for (size_t i = 0; i < count; ++i)
    array->InsertNextValue(i < values.size() ? values[i] : missing);
}
} // namespace

void VolGridFillFromMixedSolverMesh(const volgrid::SolverMesh& mesh, vtkUnstructuredGrid* volume, vtkPolyData* boundary)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.numberOfPoints()));
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    points->SetPoint(p, mesh.points.data() + 3 * p);
  volume->Initialize();
  volume->SetPoints(points);
  const size_t prisms = mesh.prisms.size() / 6, pyramids = mesh.pyramids.size() / 5, tets = mesh.tets.size() / 4;
  volume->Allocate(static_cast<vtkIdType>(prisms + pyramids + tets));
  for (size_t w = 0; w < prisms; ++w)
  {
    const auto ids = VolGridWedgeFromPrism<vtkIdType>(mesh.prisms.data() + 6 * w); // both triangles reversed
    volume->InsertNextCell(VTK_WEDGE, 6, ids.data());
  }
  for (size_t p = 0; p < pyramids; ++p)
  {
    // Core's quad turns like a positive tet's base towards the apex, as VTK's pyramid base does (same order).
    const int32_t* v = mesh.pyramids.data() + 5 * p;
    const vtkIdType ids[5] = { v[0], v[1], v[2], v[3], v[4] };
    volume->InsertNextCell(VTK_PYRAMID, 5, ids);
  }
  for (size_t t = 0; t < tets; ++t)
  {
    const int32_t* v = mesh.tets.data() + 4 * t;
    const vtkIdType ids[4] = { v[0], v[1], v[2], v[3] };
    volume->InsertNextCell(VTK_TETRA, 4, ids);
  }
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  appendTo<int>(region, mesh.prismRegion, prisms, 0);
  appendTo<int>(region, mesh.pyramidRegion, pyramids, 0);
  appendTo<int>(region, mesh.tetRegion, tets, 0);
  volume->GetCellData()->AddArray(region);
  volume->GetCellData()->AddArray(mixedBoundaryFacePatch(mesh));
  std::vector<int32_t> patches = mesh.trianglePatch;
  patches.insert(patches.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  std::vector<int32_t> regions(region->GetPointer(0), region->GetPointer(0) + region->GetNumberOfValues());
  VolGridSetLabelNames(volume, "PatchNames", patches, mesh.patchNames, "patch");
  VolGridSetLabelNames(volume, "RegionNames", regions, mesh.regionNames, "region");
  if (!boundary)
    return;
  boundary->Initialize();
  boundary->SetPoints(points);
  vtkNew<vtkCellArray> faces;
  for (size_t k = 0; k + 3 <= mesh.triangles.size(); k += 3)
  {
    const vtkIdType ids[3] = { mesh.triangles[k], mesh.triangles[k + 1], mesh.triangles[k + 2] };
    faces->InsertNextCell(3, ids);
  }
  for (size_t k = 0; k + 4 <= mesh.quads.size(); k += 4)
  {
    const vtkIdType ids[4] = { mesh.quads[k], mesh.quads[k + 1], mesh.quads[k + 2], mesh.quads[k + 3] };
    faces->InsertNextCell(4, ids);
  }
  boundary->SetPolys(faces);
  vtkNew<vtkIntArray> patchId;
  patchId->SetName("PatchId");
  appendTo<int>(patchId, patches, patches.size(), 0);
  boundary->GetCellData()->AddArray(patchId);
  boundary->GetCellData()->SetActiveScalars("PatchId");
  VolGridSetLabelNames(boundary, "PatchNames", patches, mesh.patchNames, "patch");
}

void VolGridFillFromLayeredResult(const volgrid::LayeredMeshResult& r, vtkUnstructuredGrid* volume,
                                  vtkPolyData* boundary)
{
  VolGridFillFromMixedSolverMesh(volgrid::layeredSolverMesh(r), volume, boundary);
  vtkNew<vtkIntArray> layer;
  vtkNew<vtkUnsignedCharArray> reason;
  layer->SetName("LayerIndex");
  reason->SetName("ThinnedReason");
  appendTo<int>(layer, r.wedgeLayer, r.wedges.size() / 6, 0); // the volume's order: wedges, pyramids, tets
  appendTo<int>(layer, r.pyramidLayer, r.pyramids.size() / 5, 0);
  appendTo<int>(layer, r.tetLayer, r.tets.size() / 4, -1);
  appendTo<unsigned char>(reason, r.wedgeReason, r.wedges.size() / 6, 0);
  appendTo<unsigned char>(reason, r.pyramidReason, r.pyramids.size() / 5, 0);
  appendTo<unsigned char>(reason, r.tetReason, r.tets.size() / 4, 0);
  // The layer arrays first (as VolGrid has written them since layers came), then Region and the patches.
  vtkCellData* cd = volume->GetCellData();
  vtkSmartPointer<vtkDataArray> region = cd->GetArray("Region"), patches = cd->GetArray("BoundaryFacePatch");
  cd->RemoveArray("Region");
  cd->RemoveArray("BoundaryFacePatch");
  for (vtkDataArray* array :
       { static_cast<vtkDataArray*>(layer), static_cast<vtkDataArray*>(reason), region.Get(), patches.Get() })
    cd->AddArray(array);
  cd->SetActiveScalars("LayerIndex");
}
