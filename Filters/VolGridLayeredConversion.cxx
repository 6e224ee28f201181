#include "VolGridLayeredConversion.h"

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
// BoundaryFacePatch of the volume (see the header), in its cell order: wedges, pyramids, tets.
vtkSmartPointer<vtkIntArray> layeredBoundaryFacePatch(const volgrid::LayeredMeshResult& r)
{
  if (r.wedges.empty() && r.pyramids.empty()) // split prisms: a tet grid like any other
    return VolGridBoundaryFacePatch(r.tets, r.boundaryTriangles, r.boundaryPatch);
  const volgrid::SolverMesh mesh = volgrid::layeredSolverMesh(r);
  const int64_t tets = mesh.numberOfTets(), wedges = static_cast<int64_t>(r.wedges.size() / 6);
  const int64_t pyramids = static_cast<int64_t>(r.pyramids.size() / 5);
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName("BoundaryFacePatch");
  array->SetNumberOfComponents(5);
  array->SetNumberOfTuples(static_cast<vtkIdType>(tets + wedges + pyramids));
  array->Fill(-1);
  std::vector<volgrid::CellSide> owners;
  volgrid::findBoundaryCellSides(mesh, owners); // a face without a cell has no entry (cell -1)
  const size_t numTriangles = mesh.trianglePatch.size();
  for (size_t f = 0; f < owners.size(); ++f)
  {
    const int64_t c = owners[f].cell; // Core's order: tets, prisms, pyramids
    if (c < 0)
      continue;
    const int64_t cell = c < tets ? wedges + pyramids + c : c - tets; // layer cells keep their order
    const int32_t patch = f < numTriangles ? mesh.trianglePatch[f] : mesh.quadPatch[f - numTriangles];
    array->SetTypedComponent(static_cast<vtkIdType>(cell), owners[f].side, patch);
  }
  return array;
}
} // namespace

void VolGridFillFromLayeredResult(const volgrid::LayeredMeshResult& r, vtkUnstructuredGrid* volume,
                                  vtkPolyData* boundary)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(r.points.size() / 3));
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    points->SetPoint(p, r.points.data() + 3 * p);
  volume->Initialize();
  volume->SetPoints(points);
  const vtkIdType wedges = static_cast<vtkIdType>(r.wedges.size() / 6);
  const vtkIdType tets = static_cast<vtkIdType>(r.tets.size() / 4);
  const vtkIdType pyramids = static_cast<vtkIdType>(r.pyramids.size() / 5);
  volume->Allocate(wedges + pyramids + tets);
  vtkNew<vtkIntArray> layer, region;
  vtkNew<vtkUnsignedCharArray> reason;
  layer->SetName("LayerIndex");
  reason->SetName("ThinnedReason");
  region->SetName("Region");
  for (vtkIdType w = 0; w < wedges; ++w)
  {
    // Core's base triangle has its normal towards the top; VTK's wedge has its first triangle's normal
    // pointing away from the second: both triangles reversed.
    const int32_t* v = r.wedges.data() + 6 * w;
    const vtkIdType ids[6] = { v[0], v[2], v[1], v[3], v[5], v[4] };
    volume->InsertNextCell(VTK_WEDGE, 6, ids);
    layer->InsertNextValue(r.wedgeLayer[w]);
    reason->InsertNextValue(r.wedgeReason[w]);
    region->InsertNextValue(0);
  }
  for (vtkIdType p = 0; p < pyramids; ++p)
  {
    // Core's quad turns like a positive tet's base towards the apex, as VTK's pyramid base does.
    const int32_t* v = r.pyramids.data() + 5 * p;
    const vtkIdType ids[5] = { v[0], v[1], v[2], v[3], v[4] };
    volume->InsertNextCell(VTK_PYRAMID, 5, ids);
    layer->InsertNextValue(r.pyramidLayer[p]);
    reason->InsertNextValue(r.pyramidReason[p]);
    region->InsertNextValue(0);
  }
  for (vtkIdType t = 0; t < tets; ++t)
  {
    const vtkIdType ids[4] = { r.tets[4 * t], r.tets[4 * t + 1], r.tets[4 * t + 2], r.tets[4 * t + 3] };
    volume->InsertNextCell(VTK_TETRA, 4, ids);
    layer->InsertNextValue(r.tetLayer[t]);
    reason->InsertNextValue(r.tetReason[t]);
    region->InsertNextValue(r.tetRegion[t]);
  }
  volume->GetCellData()->AddArray(layer);
  volume->GetCellData()->AddArray(reason);
  volume->GetCellData()->AddArray(region);
  volume->GetCellData()->AddArray(layeredBoundaryFacePatch(r));
  volume->GetCellData()->SetActiveScalars("LayerIndex");

  std::vector<int32_t> patches = r.boundaryPatch;
  if (wedges > 0) // split prisms put their side quads in boundaryTriangles already
    patches.insert(patches.end(), r.sidePatch.begin(), r.sidePatch.end());
  VolGridSetLabelNames(volume, "PatchNames", patches, r.patchNames, "patch");
  if (!boundary)
    return;
  boundary->Initialize();
  boundary->SetPoints(points);
  vtkNew<vtkCellArray> faces;
  for (size_t k = 0; k < r.boundaryTriangles.size(); k += 3)
  {
    const vtkIdType ids[3] = { r.boundaryTriangles[k], r.boundaryTriangles[k + 1], r.boundaryTriangles[k + 2] };
    faces->InsertNextCell(3, ids);
  }
  for (size_t k = 0; wedges > 0 && k < r.sideQuads.size(); k += 4)
  {
    const vtkIdType ids[4] = { r.sideQuads[k], r.sideQuads[k + 1], r.sideQuads[k + 2], r.sideQuads[k + 3] };
    faces->InsertNextCell(4, ids);
  }
  boundary->SetPolys(faces);
  vtkNew<vtkIntArray> patchId;
  patchId->SetName("PatchId");
  patchId->SetNumberOfValues(static_cast<vtkIdType>(patches.size()));
  for (size_t i = 0; i < patches.size(); ++i)
    patchId->SetValue(static_cast<vtkIdType>(i), patches[i]);
  boundary->GetCellData()->AddArray(patchId);
  boundary->GetCellData()->SetActiveScalars("PatchId");
  VolGridSetLabelNames(boundary, "PatchNames", patches, r.patchNames, "patch");
}
