#include "VolGridSolverMeshFromGrid.h"

#include "VolGridCellOrder.h"
#include "VolGridConversion.h"

#include "vtkCellData.h"
#include "vtkCellIterator.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include "BoundaryFaceOwners.h"
#include "SolverMesh.h"

namespace
{
// A cell kind's Exodus sides: per side its corners in Core's vertex order (-1 after a triangle's three).
struct Kind
{
  int sides;
  int side[5][4];
};
Kind tetSides()
{
  Kind k{ 4, {} };
  for (int s = 0; s < 4; ++s)
  {
    for (int i = 0; i < 3; ++i)
      k.side[s][i] = volgrid::kExodusTetSide[s][i];
    k.side[s][3] = -1;
  }
  return k;
}
Kind layerSides(const int (&table)[5][4])
{
  Kind k{ 5, {} };
  for (int s = 0; s < 5; ++s)
    for (int i = 0; i < 4; ++i)
      k.side[s][i] = table[s][i];
  return k;
}
const Kind kTet = tetSides();
const Kind kWedge = layerSides(volgrid::kExodusWedgeSide);
const Kind kPyramid = layerSides(volgrid::kExodusPyramidSide);

// Appends cell c (ids in Core's order, n of them) with its region, and its boundary faces with their
// patches (BoundaryFacePatch: component k for Exodus side k + 1).
void addCell(const vtkIdType* ids, int n, const Kind& kind, vtkIdType c, vtkDataArray* facePatch, vtkDataArray* region,
             std::vector<int32_t>& cells, std::vector<int32_t>& cellRegion, volgrid::SolverMesh& mesh)
{
  for (int k = 0; k < n; ++k)
    cells.push_back(static_cast<int32_t>(ids[k]));
  cellRegion.push_back(region ? static_cast<int32_t>(region->GetComponent(c, 0)) : 1);
  for (int side = 0; side < kind.sides; ++side)
  {
    const double patch = facePatch->GetComponent(c, side);
    if (patch < 0)
      continue;
    const int* f = kind.side[side];
    const bool quad = f[3] >= 0;
    for (int k = 0; k < (quad ? 4 : 3); ++k)
      (quad ? mesh.quads : mesh.triangles).push_back(static_cast<int32_t>(ids[f[k]]));
    (quad ? mesh.quadPatch : mesh.trianglePatch).push_back(static_cast<int32_t>(patch));
  }
}
} // namespace

bool VolGridSolverMeshFromGrid(vtkUnstructuredGrid* grid, volgrid::SolverMesh& mesh, std::string& error)
{
  mesh = volgrid::SolverMesh();
  const vtkIdType numCells = grid ? grid->GetNumberOfCells() : 0;
  if (numCells == 0)
  {
    error = "the input has no cells";
    return false;
  }
  vtkDataArray* facePatch = grid->GetCellData()->GetArray("BoundaryFacePatch");
  if (!facePatch || (facePatch->GetNumberOfComponents() != 4 && facePatch->GetNumberOfComponents() != 5))
  {
    error = "the input has no BoundaryFacePatch cell array (4 or 5 components), so its boundary patches are "
            "unknown; write the volume output of VolGrid Tetrahedralize or a mesh read by VolGrid";
    return false;
  }
  vtkDataArray* region = grid->GetCellData()->GetArray("Region");
  const bool mixed = facePatch->GetNumberOfComponents() == 5; // VolGridLayeredConversion.h
  vtkIdType others = 0;
  auto cells = vtkSmartPointer<vtkCellIterator>::Take(grid->NewCellIterator());
  for (cells->InitTraversal(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    const int type = cells->GetCellType();
    const vtkIdType* ids = cells->GetPointIds()->GetPointer(0);
    if (type == VTK_TETRA)
      addCell(ids, 4, kTet, cells->GetCellId(), facePatch, region, mesh.tets, mesh.tetRegion, mesh);
    else if (mixed && type == VTK_WEDGE)
    {
      const auto core = VolGridPrismFromWedge<vtkIdType>(ids);
      addCell(core.data(), 6, kWedge, cells->GetCellId(), facePatch, region, mesh.prisms, mesh.prismRegion, mesh);
    }
    else if (mixed && type == VTK_PYRAMID)
      addCell(ids, 5, kPyramid, cells->GetCellId(), facePatch, region, mesh.pyramids, mesh.pyramidRegion, mesh);
    else
      ++others;
  }
  if (others > 0)
  {
    error = std::to_string(others) + " of the input's " + std::to_string(numCells) + " cells are not " +
      (mixed ? "tetrahedra, wedges or pyramids" : "tetrahedra") + " (the solver formats take those cells)";
    return false;
  }
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  mesh.points.resize(static_cast<size_t>(3 * numPoints));
  for (vtkIdType i = 0; i < numPoints; ++i)
    grid->GetPoint(i, mesh.points.data() + 3 * i);
  vtkPointData* pointData = grid->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pointData->GetArray(a);
    if (!array || !array->GetName() || array->GetNumberOfComponents() != 1)
      continue; // the solver formats' point fields are scalars
    std::vector<double>& values = mesh.pointData[array->GetName()];
    values.resize(static_cast<size_t>(numPoints));
    for (vtkIdType i = 0; i < numPoints; ++i)
      values[i] = array->GetComponent(i, 0);
  }
  mesh.patchNames = VolGridReadLabelNames(grid, "PatchNames");
  mesh.regionNames = VolGridReadLabelNames(grid, "RegionNames");
  return true;
}
