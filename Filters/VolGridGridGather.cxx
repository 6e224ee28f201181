// VolGridGatherGrid / VolGridScatterCellArrays (declared in VolGridParallel.h): a grid handed out by
// VolGridDistributeCells, put back together on rank 0 by its global ids, and per-cell results sent back.
#include "VolGridParallel.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMultiProcessController.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <tuple>

namespace
{
constexpr int kResultTag = 418002;

// Points, cells and the two id arrays only: what the whole grid is rebuilt from.
vtkSmartPointer<vtkUnstructuredGrid> geometryWithIds(vtkUnstructuredGrid* local)
{
  auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
  g->SetPoints(local->GetPoints());
  g->SetCells(local->GetCellTypesArray(), local->GetCells());
  g->GetPointData()->AddArray(local->GetPointData()->GetArray("GlobalPointIds"));
  g->GetCellData()->AddArray(local->GetCellData()->GetArray("GlobalCellIds"));
  return g;
}

struct CellRef
{
  vtkIdType global, rank, local;
};

void assemble(const std::vector<vtkSmartPointer<vtkDataObject>>& pieces, vtkUnstructuredGrid* whole,
              std::vector<std::vector<vtkIdType>>& cellsOfRank)
{
  std::vector<vtkIdType> pointIds;
  std::vector<CellRef> cells;
  cellsOfRank.assign(pieces.size(), {});
  for (size_t r = 0; r < pieces.size(); ++r)
  {
    auto* g = vtkUnstructuredGrid::SafeDownCast(pieces[r]);
    if (!g || g->GetNumberOfCells() == 0)
      continue;
    vtkDataArray* pid = g->GetPointData()->GetArray("GlobalPointIds");
    vtkDataArray* cid = g->GetCellData()->GetArray("GlobalCellIds");
    for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p)
      pointIds.push_back(static_cast<vtkIdType>(pid->GetComponent(p, 0)));
    for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
      cells.push_back({ static_cast<vtkIdType>(cid->GetComponent(c, 0)), static_cast<vtkIdType>(r), c });
    cellsOfRank[r].resize(g->GetNumberOfCells());
  }
  std::sort(pointIds.begin(), pointIds.end());
  pointIds.erase(std::unique(pointIds.begin(), pointIds.end()), pointIds.end());
  std::sort(cells.begin(), cells.end(),
            [](const CellRef& a, const CellRef& b)
            { return std::tie(a.global, a.rank, a.local) < std::tie(b.global, b.rank, b.local); });
  auto index = [&](vtkIdType gid)
  { return static_cast<vtkIdType>(std::lower_bound(pointIds.begin(), pointIds.end(), gid) - pointIds.begin()); };
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(pointIds.size()));
  for (const auto& object : pieces)
  {
    auto* g = vtkUnstructuredGrid::SafeDownCast(object);
    if (!g || g->GetNumberOfCells() == 0)
      continue;
    vtkDataArray* pid = g->GetPointData()->GetArray("GlobalPointIds");
    for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p)
      points->SetPoint(index(static_cast<vtkIdType>(pid->GetComponent(p, 0))), g->GetPoint(p));
  }
  whole->SetPoints(points);
  whole->Allocate(static_cast<vtkIdType>(cells.size()));
  std::vector<vtkIdType> ids;
  for (size_t k = 0; k < cells.size(); ++k)
  {
    auto* g = vtkUnstructuredGrid::SafeDownCast(pieces[cells[k].rank]);
    vtkDataArray* pid = g->GetPointData()->GetArray("GlobalPointIds");
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    g->GetCellPoints(cells[k].local, npts, pts);
    ids.resize(static_cast<size_t>(npts));
    for (vtkIdType i = 0; i < npts; ++i)
      ids[i] = index(static_cast<vtkIdType>(pid->GetComponent(pts[i], 0)));
    whole->InsertNextCell(g->GetCellType(cells[k].local), npts, ids.data());
    cellsOfRank[cells[k].rank][cells[k].local] = static_cast<vtkIdType>(k);
  }
}
} // namespace

bool VolGridGatherGrid(vtkMultiProcessController* controller, vtkUnstructuredGrid* local,
                       vtkSmartPointer<vtkUnstructuredGrid>& whole, std::vector<std::vector<vtkIdType>>& cellsOfRank)
{
  const bool empty = !local || local->GetNumberOfCells() == 0;
  int mine =
    empty || (local->GetPointData()->GetArray("GlobalPointIds") && local->GetCellData()->GetArray("GlobalCellIds")) ? 1
                                                                                                                    : 0;
  int all = 0;
  controller->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
  if (!all)
    return false;
  vtkSmartPointer<vtkUnstructuredGrid> send =
    empty ? vtkSmartPointer<vtkUnstructuredGrid>::New() : geometryWithIds(local);
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(send, pieces, 0);
  if (controller->GetLocalProcessId() == 0)
  {
    whole = vtkSmartPointer<vtkUnstructuredGrid>::New();
    assemble(pieces, whole, cellsOfRank);
  }
  return true;
}

void VolGridScatterCellArrays(vtkMultiProcessController* controller, vtkDataSet* wholeResult, vtkFieldData* fieldData,
                              const std::vector<std::vector<vtkIdType>>& cellsOfRank, vtkDataSet* output)
{
  auto received = vtkSmartPointer<vtkTable>::New();
  if (controller->GetLocalProcessId() == 0)
  {
    vtkCellData* cd = wholeResult->GetCellData();
    for (int r = controller->GetNumberOfProcesses() - 1; r >= 0; --r)
    {
      auto table = vtkSmartPointer<vtkTable>::New();
      const std::vector<vtkIdType>& cells =
        r < static_cast<int>(cellsOfRank.size()) ? cellsOfRank[r] : std::vector<vtkIdType>();
      for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
      {
        vtkDataArray* source = cd->GetArray(a);
        if (!source)
          continue;
        vtkSmartPointer<vtkDataArray> part;
        part.TakeReference(source->NewInstance());
        part->SetName(source->GetName());
        part->SetNumberOfComponents(source->GetNumberOfComponents());
        part->SetNumberOfTuples(static_cast<vtkIdType>(cells.size()));
        for (size_t c = 0; c < cells.size(); ++c)
          part->SetTuple(static_cast<vtkIdType>(c), cells[c], source);
        table->AddColumn(part);
      }
      table->GetFieldData()->ShallowCopy(fieldData);
      if (r == 0)
        received = table;
      else
        controller->Send(table, r, kResultTag);
    }
  }
  else
  {
    controller->Receive(received, 0, kResultTag);
  }
  vtkCellData* out = output->GetCellData();
  for (vtkIdType a = 0; a < received->GetNumberOfColumns(); ++a)
  {
    if (auto* array = vtkDataArray::SafeDownCast(received->GetColumn(a)))
      out->AddArray(array);
  }
  vtkFieldData* fd = output->GetFieldData();
  for (int a = 0; a < received->GetFieldData()->GetNumberOfArrays(); ++a)
    fd->AddArray(received->GetFieldData()->GetAbstractArray(a));
}
