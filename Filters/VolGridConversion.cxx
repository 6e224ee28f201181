#include "VolGridConversion.h"

#include "VolGridLayeredConversion.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "BoundaryFaceOwners.h"
#include "Mesher.h"
#include "SolverMesh.h"
#include "TetMesh.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <limits>

void VolGridFillUnstructuredGrid(const volgrid::TetMesh& mesh, const std::vector<int32_t>& keptVertices,
                                 vtkUnstructuredGrid* grid)
{
  const vtkIdType numPoints = static_cast<vtkIdType>(keptVertices.size());
  std::vector<vtkIdType> vertexToOutput(static_cast<size_t>(mesh.numVertices()), -1);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  for (vtkIdType o = 0; o < numPoints; ++o)
  {
    vertexToOutput[keptVertices[o]] = o;
    points->SetPoint(o, mesh.point(keptVertices[o]));
  }

  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  const vtkIdType numTets = mesh.numFiniteTets();
  offsets->SetNumberOfValues(numTets + 1);
  connectivity->SetNumberOfValues(4 * numTets);
  vtkIdType* offset = offsets->GetPointer(0);
  vtkIdType* corner = connectivity->GetPointer(0);
  vtkIdType cell = 0;
  mesh.forEachFiniteTet(
    [&](int32_t t)
    {
      const int32_t* v = mesh.vertices(t);
      offset[cell] = 4 * cell;
      for (int i = 0; i < 4; ++i)
      {
        corner[4 * cell + i] = vertexToOutput[v[i]];
      }
      ++cell;
    });
  offset[numTets] = 4 * numTets;
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  grid->SetPoints(points);
  grid->SetCells(VTK_TETRA, cells);
}

namespace
{
// Cells of perCell corners each. 32-bit connectivity and offsets when they fit (the ids already are
// 32-bit): 20 bytes per tet less than vtkIdType arrays, in memory and in the written file.
template<class Array>
vtkSmartPointer<vtkCellArray> fixedSizeCellsAs(const std::vector<int32_t>& corners, int perCell)
{
  using Value = typename Array::ValueType;
  auto offsets = vtkSmartPointer<Array>::New();
  auto connectivity = vtkSmartPointer<Array>::New();
  const vtkIdType n = static_cast<vtkIdType>(corners.size() / perCell);
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(corners.size()));
  Value* offset = offsets->GetPointer(0);
  Value* corner = connectivity->GetPointer(0);
  for (vtkIdType c = 0; c <= n; ++c)
    offset[c] = static_cast<Value>(perCell * c);
  for (size_t k = 0; k < corners.size(); ++k)
    corner[k] = corners[k];
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

vtkSmartPointer<vtkCellArray> fixedSizeCells(const std::vector<int32_t>& corners, int perCell)
{
  if (corners.size() < static_cast<size_t>(std::numeric_limits<int32_t>::max()))
    return fixedSizeCellsAs<vtkTypeInt32Array>(corners, perCell);
  return fixedSizeCellsAs<vtkTypeInt64Array>(corners, perCell);
}

vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int32_t>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (size_t i = 0; i < values.size(); ++i)
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  return array;
}

// VolGridFillFromMesherResult's volume: the tets on `points`, with their cell arrays.
void fillVolume(const volgrid::MesherResult& result, vtkPoints* points, vtkUnstructuredGrid* volume)
{
  volume->SetPoints(points);
  volume->SetCells(VTK_TETRA, fixedSizeCells(result.tets, 4));
  volume->GetCellData()->RemoveArray("Region");
  volume->GetCellData()->AddArray(intArray("Region", result.tetRegion));
  volume->GetCellData()->RemoveArray("Forced");
  if (result.tetForced.size() == result.tetRegion.size())
  {
    auto forced = vtkSmartPointer<vtkUnsignedCharArray>::New();
    forced->SetName("Forced");
    forced->SetNumberOfValues(static_cast<vtkIdType>(result.tetForced.size()));
    for (size_t i = 0; i < result.tetForced.size(); ++i)
      forced->SetValue(static_cast<vtkIdType>(i), result.tetForced[i]);
    volume->GetCellData()->AddArray(forced);
  }
  volume->GetCellData()->RemoveArray("BoundaryFacePatch");
  volume->GetCellData()->AddArray(
    VolGridBoundaryFacePatch(result.tets, result.boundaryTriangles, result.boundaryPatch));
}
} // namespace

void VolGridFillFromMesherResult(const volgrid::MesherResult& result, vtkUnstructuredGrid* volume,
                                 vtkPolyData* boundary)
{
  const vtkIdType numPoints = static_cast<vtkIdType>(result.points.size() / 3);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  for (vtkIdType i = 0; i < numPoints; ++i)
    points->SetPoint(i, result.points.data() + 3 * i);
  if (volume)
    fillVolume(result, points, volume);
  if (boundary)
  {
    boundary->SetPoints(points);
    boundary->SetPolys(fixedSizeCells(result.boundaryTriangles, 3));
    boundary->GetCellData()->RemoveArray("PatchId");
    boundary->GetCellData()->AddArray(intArray("PatchId", result.boundaryPatch));
  }
}

vtkSmartPointer<vtkIntArray> VolGridBoundaryFacePatch(const std::vector<int32_t>& tets,
                                                      const std::vector<int32_t>& triangles,
                                                      const std::vector<int32_t>& patches)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName("BoundaryFacePatch");
  array->SetNumberOfComponents(4);
  array->SetNumberOfTuples(static_cast<vtkIdType>(tets.size() / 4));
  array->Fill(-1);
  std::vector<volgrid::FaceOwner> owners;
  volgrid::findBoundaryFaceOwners(tets, triangles, owners); // a triangle without a tet has no entry
  for (size_t t = 0; t < owners.size() && t < patches.size(); ++t)
    if (owners[t].tet >= 0)
      array->SetTypedComponent(static_cast<vtkIdType>(owners[t].tet), owners[t].side, patches[t]);
  return array;
}

void VolGridSetLabelNames(vtkDataObject* data, const char* arrayName, const std::vector<int32_t>& labels,
                          const std::map<int32_t, std::string>& names, const char* prefix)
{
  const std::vector<int32_t> distinct = volgrid::distinctLabels(labels);
  vtkNew<vtkStringArray> array;
  array->SetName(arrayName);
  array->SetNumberOfValues(distinct.empty() || distinct.back() < 0 ? 0 : distinct.back() + 1);
  // Every entry gets a name: VTK's XML reader crashes on empty strings in a string array.
  for (vtkIdType label = 0; label < array->GetNumberOfValues(); ++label)
    array->SetValue(label, volgrid::labelName(names, static_cast<int32_t>(label), prefix));
  data->GetFieldData()->RemoveArray(arrayName);
  data->GetFieldData()->AddArray(array);
}

void VolGridSetPatchAndRegionNames(const volgrid::MesherResult& result,
                                   const std::map<int32_t, std::string>& patchNames,
                                   const std::map<int32_t, std::string>& regionNames, vtkUnstructuredGrid* volume,
                                   vtkPolyData* boundary)
{
  if (volume)
  {
    VolGridSetLabelNames(volume, "PatchNames", result.boundaryPatch, patchNames, "patch");
    VolGridSetLabelNames(volume, "RegionNames", result.tetRegion, regionNames, "region");
  }
  if (boundary)
    VolGridSetLabelNames(boundary, "PatchNames", result.boundaryPatch, patchNames, "patch");
}

std::map<int32_t, std::string> VolGridReadLabelNames(vtkDataObject* data, const char* arrayName)
{
  std::map<int32_t, std::string> names;
  vtkStringArray* array =
    data ? vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(arrayName)) : nullptr;
  for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
    if (!array->GetValue(i).empty())
      names[static_cast<int32_t>(i)] = array->GetValue(i);
  return names;
}

void VolGridFillFromSolverMesh(const volgrid::SolverMesh& mesh, vtkUnstructuredGrid* volume, vtkPolyData* boundary)
{
  if (volgrid::hasLayerCells(mesh))
    VolGridFillFromMixedSolverMesh(mesh, volume, boundary);
  else
  {
    volgrid::MesherResult result; // the same arrays under the mesher's names
    result.points = mesh.points;
    result.tets = mesh.tets;
    result.tetRegion = mesh.tetRegion;
    result.tetRegion.resize(mesh.tets.size() / 4, 0);
    result.boundaryTriangles = mesh.triangles;
    result.boundaryPatch = mesh.trianglePatch;
    result.boundaryPatch.resize(mesh.triangles.size() / 3, 0);
    VolGridFillFromMesherResult(result, volume, boundary);
    VolGridSetPatchAndRegionNames(result, mesh.patchNames, mesh.regionNames, volume, boundary);
  }
  for (const auto& field : mesh.pointData)
  {
    if (field.second.size() != mesh.points.size() / 3)
      continue;
    vtkNew<vtkDoubleArray> array;
    array->SetName(field.first.c_str());
    array->SetNumberOfValues(static_cast<vtkIdType>(field.second.size()));
    for (size_t i = 0; i < field.second.size(); ++i)
      array->SetValue(static_cast<vtkIdType>(i), field.second[i]);
    volume->GetPointData()->AddArray(array);
  }
}
