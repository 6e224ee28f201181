#include "VolGridParallel.h"

#include "SpatialPartition.h"

#include "vtkAppendFilter.h"
#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataSet.h"
#include "vtkExtractCells.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMultiProcessController.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace
{
constexpr int kPieceTag = 418001;

// A shallow copy of `input` without its ghost cells (an empty vtkPolyData for nullptr).
vtkSmartPointer<vtkDataSet> withoutGhostCells(vtkDataSet* input)
{
  if (!input)
    return vtkSmartPointer<vtkPolyData>::New();
  vtkSmartPointer<vtkDataSet> copy;
  copy.TakeReference(input->NewInstance());
  copy->ShallowCopy(input);
  if (copy->HasAnyGhostCells())
  {
    if (auto* poly = vtkPolyData::SafeDownCast(copy))
      poly->RemoveGhostCells();
    else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(copy))
      grid->RemoveGhostCells();
  }
  return copy;
}

bool isEmpty(vtkDataSet* ds)
{
  return !ds || (ds->GetNumberOfPoints() == 0 && ds->GetNumberOfCells() == 0);
}

// Marks the GlobalPointIds / GlobalCellIds arrays as the attributes' global ids (the transfer keeps them as
// plain arrays).
void markGlobalIds(vtkDataSet* ds)
{
  if (vtkDataArray* p = ds->GetPointData()->GetArray("GlobalPointIds"))
    ds->GetPointData()->SetGlobalIds(p);
  if (vtkDataArray* c = ds->GetCellData()->GetArray("GlobalCellIds"))
    ds->GetCellData()->SetGlobalIds(c);
}

vtkSmartPointer<vtkIdTypeArray> iotaArray(const char* name, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkIdTypeArray>::New();
  a->SetName(name);
  a->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
    a->SetValue(i, i);
  return a;
}

std::vector<double> cellCentroids(vtkUnstructuredGrid* grid)
{
  const vtkIdType n = grid->GetNumberOfCells();
  std::vector<double> c(3 * static_cast<size_t>(n), 0.0);
  vtkPoints* points = grid->GetPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    grid->GetCellPoints(i, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      double x[3];
      points->GetPoint(pts[k], x);
      for (int a = 0; a < 3; ++a)
        c[3 * i + a] += x[a] / static_cast<double>(npts);
    }
  }
  return c;
}
} // namespace

vtkMultiProcessController* VolGridParallelController()
{
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  return c && c->GetNumberOfProcesses() > 1 ? c : nullptr;
}

std::vector<std::vector<vtkSmartPointer<vtkDataSet>>> VolGridGatherParts(vtkMultiProcessController* controller,
                                                                         const std::vector<vtkDataSet*>& local)
{
  int mine = static_cast<int>(local.size()), slots = 0;
  controller->AllReduce(&mine, &slots, 1, vtkCommunicator::MAX_OP);
  const bool root = controller->GetLocalProcessId() == 0;
  std::vector<std::vector<vtkSmartPointer<vtkDataSet>>> parts(root ? slots : 0);
  for (int k = 0; k < slots; ++k)
  {
    vtkSmartPointer<vtkDataSet> send = withoutGhostCells(k < mine ? local[k] : nullptr);
    std::vector<vtkSmartPointer<vtkDataObject>> received;
    controller->Gather(send, received, 0);
    for (vtkDataObject* object : received)
    {
      auto* ds = vtkDataSet::SafeDownCast(object);
      if (root && !isEmpty(ds))
        parts[k].emplace_back(ds);
    }
  }
  return parts;
}

vtkSmartPointer<vtkPointSet> VolGridGatherPointSet(vtkMultiProcessController* controller, vtkDataSet* local)
{
  const auto parts = VolGridGatherParts(controller, { local });
  if (controller->GetLocalProcessId() != 0)
    return nullptr;
  const auto& pieces = parts[0];
  if (pieces.size() == 1 && vtkPointSet::SafeDownCast(pieces[0]))
    return vtkPointSet::SafeDownCast(pieces[0]);
  const bool allPoly = std::all_of(pieces.begin(), pieces.end(),
                                   [](const vtkSmartPointer<vtkDataSet>& p) { return vtkPolyData::SafeDownCast(p); });
  if (allPoly)
  {
    if (pieces.empty())
      return vtkSmartPointer<vtkPolyData>::New();
    auto append = vtkSmartPointer<vtkAppendPolyData>::New();
    for (const auto& piece : pieces)
      append->AddInputData(vtkPolyData::SafeDownCast(piece));
    append->Update();
    return append->GetOutput();
  }
  auto append = vtkSmartPointer<vtkAppendFilter>::New();
  append->MergePointsOff();
  for (const auto& piece : pieces)
    append->AddInputData(piece);
  append->Update();
  return append->GetOutput();
}

bool VolGridBroadcastFlag(vtkMultiProcessController* controller, bool flag)
{
  int value = flag ? 1 : 0;
  controller->Broadcast(&value, 1, 0);
  return value != 0;
}

void VolGridDistributeCells(vtkMultiProcessController* controller, vtkUnstructuredGrid* whole,
                            vtkUnstructuredGrid* piece)
{
  const int ranks = controller->GetNumberOfProcesses();
  if (controller->GetLocalProcessId() != 0)
  {
    piece->Initialize();
    controller->Receive(piece, 0, kPieceTag);
    markGlobalIds(piece);
    return;
  }
  auto ided = vtkSmartPointer<vtkUnstructuredGrid>::New();
  ided->ShallowCopy(whole);
  ided->GetPointData()->AddArray(iotaArray("GlobalPointIds", whole->GetNumberOfPoints()));
  ided->GetCellData()->AddArray(iotaArray("GlobalCellIds", whole->GetNumberOfCells()));
  const std::vector<double> centroids = cellCentroids(whole);
  const std::vector<int32_t> part = volgrid::bisectionPartition(centroids.data(), whole->GetNumberOfCells(), ranks);
  std::vector<vtkSmartPointer<vtkIdList>> lists(ranks);
  for (auto& list : lists)
    list = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < static_cast<vtkIdType>(part.size()); ++c)
    lists[part[c]]->InsertNextId(c);
  for (int r = 0; r < ranks; ++r)
  {
    auto extract = vtkSmartPointer<vtkExtractCells>::New();
    extract->SetInputData(ided);
    extract->SetCellList(lists[r]);
    extract->Update();
    if (r == 0)
      piece->ShallowCopy(extract->GetOutput());
    else
      controller->Send(extract->GetOutput(), r, kPieceTag);
  }
  markGlobalIds(piece);
}
