#include "VolGridConversion.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkIdTypeArray.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include "TetMesh.h"

void VolGridFillUnstructuredGrid(
  const volgrid::TetMesh& mesh, const std::vector<int32_t>& keptVertices, vtkUnstructuredGrid* grid)
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
  mesh.forEachFiniteTet([&](int32_t t) {
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
