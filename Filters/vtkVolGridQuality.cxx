// vtkVolGridQuality: the filter (metric selection, statistics, histogram table, MPI); the measuring is in
// VolGridQualityVolume.h and VolGridQualitySurface.h, thin adapters to Core/Quality.
#include "vtkVolGridQuality.h"

#include "QualityStatistics.h"

#include "VolGridParallel.h"
#include "VolGridQualityArrays.h"
#include "VolGridQualitySurface.h"
#include "VolGridQualityVolume.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkVolGridQuality);

namespace
{
namespace vq = volgrid::quality;

struct MetricInfo
{
  int id;
  const char* name;
  vq::Worst worst;
};

const MetricInfo kMetrics[] = {
  { vtkVolGridQuality::ASPECT_RATIO, "AspectRatio", vq::Worst::Largest },
  { vtkVolGridQuality::MIN_DIHEDRAL_ANGLE, "MinDihedralAngle", vq::Worst::Smallest },
  { vtkVolGridQuality::MAX_DIHEDRAL_ANGLE, "MaxDihedralAngle", vq::Worst::Largest },
  { vtkVolGridQuality::MIN_SOLID_ANGLE, "MinSolidAngle", vq::Worst::Smallest },
  { vtkVolGridQuality::VOLUME, "Volume", vq::Worst::Smallest },
  { vtkVolGridQuality::VOLUME_GRADIENT, "VolumeGradient", vq::Worst::Largest },
  { vtkVolGridQuality::RADIUS_EDGE_RATIO, "RadiusEdgeRatio", vq::Worst::Largest },
  { vtkVolGridQuality::RADIUS_RATIO, "RadiusRatio", vq::Worst::Largest },
  { vtkVolGridQuality::AREA, "Area", vq::Worst::Smallest },
  { vtkVolGridQuality::MIN_ANGLE, "MinAngle", vq::Worst::Smallest },
  { vtkVolGridQuality::MAX_ANGLE, "MaxAngle", vq::Worst::Largest },
  { vtkVolGridQuality::NON_ORTHOGONALITY, "NonOrthogonality", vq::Worst::Largest },
  { vtkVolGridQuality::SKEWNESS, "Skewness", vq::Worst::Largest },
  { vtkVolGridQuality::VOLUME_RATIO, "VolumeRatio", vq::Worst::Largest },
  { vtkVolGridQuality::WEDGE_VOLUME, "WedgeVolume", vq::Worst::Smallest },
  { vtkVolGridQuality::WEDGE_SCALED_JACOBIAN, "WedgeScaledJacobian", vq::Worst::Smallest },
};

// The selected metric, or its counterpart on the other kind of grid (see the header).
int effectiveMetric(int metric, bool volume)
{
  using Q = vtkVolGridQuality;
  if (volume)
  {
    switch (metric)
    {
      case Q::AREA:
        return Q::VOLUME;
      case Q::MIN_ANGLE:
        return Q::MIN_DIHEDRAL_ANGLE;
      case Q::MAX_ANGLE:
        return Q::MAX_DIHEDRAL_ANGLE;
      default:
        return metric;
    }
  }
  switch (metric)
  {
    case Q::MIN_DIHEDRAL_ANGLE:
    case Q::MIN_SOLID_ANGLE:
      return Q::MIN_ANGLE;
    case Q::MAX_DIHEDRAL_ANGLE:
      return Q::MAX_ANGLE;
    case Q::VOLUME:
    case Q::VOLUME_GRADIENT:
      return Q::AREA;
    case Q::RADIUS_EDGE_RATIO:
    case Q::RADIUS_RATIO:
    case Q::NON_ORTHOGONALITY:
    case Q::SKEWNESS:
    case Q::VOLUME_RATIO:
    case Q::WEDGE_VOLUME:
    case Q::WEDGE_SCALED_JACOBIAN:
      return Q::ASPECT_RATIO;
    default:
      return metric;
  }
}

// Statistics of one array: per-chunk partials in parallel, merged in chunk order (deterministic).
vq::Statistics parallelStatistics(const double* v, vtkIdType n, int bins, vq::Worst worst)
{
  const vtkIdType chunk = vq::kStatisticsChunk;
  const vtkIdType chunks = (n + chunk - 1) / chunk;
  std::vector<vq::Partial> partials(static_cast<size_t>(chunks));
  vtkSMPTools::For(0, chunks, 1,
                   [&](vtkIdType first, vtkIdType last)
                   {
                     for (vtkIdType c = first; c < last; ++c)
                     {
                       partials[c] = vq::accumulate(v, c * chunk, std::min(n, (c + 1) * chunk));
                     }
                   });
  const vq::Partial all = vq::mergeInOrder(partials);
  std::vector<double> edges = all.count ? vq::binEdges(all.min, all.max, bins) : vq::binEdges(1.0, 0.0, bins);
  const size_t nb = edges.size() - 1;
  std::vector<int64_t> chunkCounts(static_cast<size_t>(chunks) * nb, 0);
  vtkSMPTools::For(0, chunks, 1,
                   [&](vtkIdType first, vtkIdType last)
                   {
                     for (vtkIdType c = first; c < last; ++c)
                     {
                       vq::histogram(v, c * chunk, std::min(n, (c + 1) * chunk), edges, chunkCounts.data() + c * nb);
                     }
                   });
  std::vector<int64_t> counts(nb, 0);
  for (vtkIdType c = 0; c < chunks; ++c)
  {
    for (size_t b = 0; b < nb; ++b)
    {
      counts[b] += chunkCounts[c * nb + b];
    }
  }
  return vq::finish(all, n, worst, std::move(edges), std::move(counts));
}
} // namespace

vtkVolGridQuality::vtkVolGridQuality()
  : Metric(MIN_DIHEDRAL_ANGLE)
  , BinCount(20)
  , NumberOfSkippedCells(0)
{
  this->SetNumberOfOutputPorts(2);
}

const char* vtkVolGridQuality::GetMetricName(int metric)
{
  return metric >= ASPECT_RATIO && metric <= WEDGE_SCALED_JACOBIAN ? kMetrics[metric].name : nullptr;
}

int vtkVolGridQuality::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkVolGridQuality::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkTable");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

int vtkVolGridQuality::RequestDataObject(vtkInformation*, vtkInformationVector** inputVector,
                                         vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  if (!input)
  {
    return 0;
  }
  vtkInformation* info0 = outputVector->GetInformationObject(0);
  vtkDataObject* out0 = info0->Get(vtkDataObject::DATA_OBJECT());
  if (!out0 || !out0->IsA(input->GetClassName()))
  {
    vtkDataObject* fresh = input->NewInstance();
    info0->Set(vtkDataObject::DATA_OBJECT(), fresh);
    fresh->Delete();
  }
  vtkInformation* info1 = outputVector->GetInformationObject(1);
  if (!vtkTable::SafeDownCast(info1->Get(vtkDataObject::DATA_OBJECT())))
  {
    vtkTable* table = vtkTable::New();
    info1->Set(vtkDataObject::DATA_OBJECT(), table);
    table->Delete();
  }
  return 1;
}

int vtkVolGridQuality::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  vtkTable* table = vtkTable::GetData(outputVector, 1);
  if (!input || !output || !table)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  // Under MPI, a grid with global ids (VolGrid Tetrahedralize's pieces) is measured whole on rank 0 and the
  // per-cell results go back to the ranks: values, statistics and histogram are the one-process ones.
  vtkMultiProcessController* controller = VolGridParallelController();
  vtkSmartPointer<vtkUnstructuredGrid> whole;
  std::vector<std::vector<vtkIdType>> cellsOfRank;
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (controller && grid && VolGridGatherGrid(controller, grid, whole, cellsOfRank))
  {
    auto wholeResult = vtkSmartPointer<vtkUnstructuredGrid>::New();
    const bool root = controller->GetLocalProcessId() == 0;
    const bool ok = VolGridBroadcastFlag(controller, root ? this->ExecuteThreaded(whole, wholeResult, table) : true);
    if (!root || !ok)
    {
      table->Initialize(); // the statistics live on rank 0 only (ParaView appends the ranks' tables)
    }
    output->ShallowCopy(input);
    if (ok)
    {
      VolGridScatterCellArrays(controller, wholeResult, table->GetFieldData(), cellsOfRank, output);
      output->GetCellData()->SetActiveScalars("Quality");
    }
    return 1;
  }
  if (!this->ExecuteThreaded(input, output, table))
  {
    output->Initialize();
    table->Initialize();
  }
  if (controller && controller->GetLocalProcessId() != 0 && input->GetNumberOfCells() == 0)
  {
    table->Initialize(); // an empty piece adds no histogram rows to the ranks' tables ParaView appends
  }
  return 1;
}

bool vtkVolGridQuality::ExecuteThreaded(vtkDataSet* input, vtkDataSet* output, vtkTable* table)
{
  bool ok = false;
  auto run = [&]() { ok = this->Execute(input, output, table); };
  // ParaView's VTK defaults to the Sequential backend: run threaded unless the user pinned a backend.
  if (std::strcmp(vtkSMPTools::GetBackend(), "Sequential") == 0 && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, run);
  }
  else
  {
    run();
  }
  return ok;
}

bool vtkVolGridQuality::Execute(vtkDataSet* input, vtkDataSet* output, vtkTable* table)
{
  output->ShallowCopy(input);
  this->NumberOfSkippedCells = 0;
  this->SetProgressText("Element quality");
  this->UpdateProgress(0.0);

  auto summary = vtkSmartPointer<vtkFieldData>::New();
  std::vector<vtkSmartPointer<vtkDoubleArray>> arrays; // in kMetrics order of their ids
  bool volume = true;
  bool ok;
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(input))
  {
    ok = VolGridMeasureVolumeGrid(this, grid, arrays, summary, this->NumberOfSkippedCells);
  }
  else if (auto* surface = vtkPolyData::SafeDownCast(input))
  {
    volume = false;
    ok = VolGridMeasureSurface(this, surface, arrays, summary, this->NumberOfSkippedCells);
  }
  else
  {
    vtkErrorMacro("Input must be a vtkUnstructuredGrid or a vtkPolyData, not " << input->GetClassName());
    return false;
  }
  if (!ok)
  {
    return false;
  }

  // Statistics, the Quality copy and the histogram table.
  this->SetProgressText("Statistics");
  const vtkIdType numCells = input->GetNumberOfCells();
  int selected = effectiveMetric(this->Metric, volume);
  const bool measured = std::any_of(arrays.begin(), arrays.end(),
                                    [&](const vtkSmartPointer<vtkDoubleArray>& a)
                                    { return std::strcmp(a->GetName(), kMetrics[selected].name) == 0; });
  if (volume && !measured)
    selected = MAX_DIHEDRAL_ANGLE; // no CFD metrics (not tets only) or no wedge metrics (no wedges)

  vtkCellData* cd = output->GetCellData();
  auto bin = vtkSmartPointer<vtkIntArray>::New();
  bin->SetName("Bin");
  bin->SetNumberOfTuples(this->BinCount);
  for (int b = 0; b < this->BinCount; ++b)
  {
    bin->SetValue(b, b);
  }
  table->AddColumn(bin);
  double totalVolume = 0.0;
  for (size_t k = 0; k < arrays.size(); ++k)
  {
    vtkDoubleArray* a = arrays[k];
    const MetricInfo* info = nullptr;
    for (const MetricInfo& m : kMetrics)
    {
      if (std::strcmp(m.name, a->GetName()) == 0)
        info = &m;
    }
    cd->AddArray(a);
    const vq::Statistics s = parallelStatistics(a->GetPointer(0), numCells, this->BinCount, info->worst);
    if (info->id == VOLUME || info->id == WEDGE_VOLUME)
    {
      totalVolume += s.mean * static_cast<double>(s.count);
    }
    if (info->id == selected)
    {
      auto q = VolGridNewCellArray("Quality", numCells);
      const double* src = a->GetPointer(0);
      double* dst = q->GetPointer(0);
      vtkSMPTools::For(0, numCells, [&](vtkIdType b, vtkIdType e) { std::copy(src + b, src + e, dst + b); });
      cd->AddArray(q);
      cd->SetActiveScalars("Quality");
    }
    auto st = vtkSmartPointer<vtkDoubleArray>::New();
    st->SetName((std::string(info->name) + "Statistics").c_str());
    st->SetNumberOfComponents(6);
    const char* components[6] = { "Count", "Min", "Max", "Mean", "StdDev", "WorstCell" };
    for (int c = 0; c < 6; ++c)
    {
      st->SetComponentName(c, components[c]);
    }
    const double row[6] = { static_cast<double>(s.count),     s.min, s.max, s.mean, s.stddev,
                            static_cast<double>(s.worstIndex) };
    st->InsertNextTuple(row);
    summary->AddArray(st);

    auto lo = VolGridNewCellArray((std::string(info->name) + "_BinStart").c_str(), this->BinCount);
    auto hi = VolGridNewCellArray((std::string(info->name) + "_BinEnd").c_str(), this->BinCount);
    auto count = vtkSmartPointer<vtkIdTypeArray>::New();
    count->SetName((std::string(info->name) + "_Count").c_str());
    count->SetNumberOfTuples(this->BinCount);
    for (int b = 0; b < this->BinCount; ++b)
    {
      lo->SetValue(b, s.binEdges[b]);
      hi->SetValue(b, s.binEdges[b + 1]);
      count->SetValue(b, s.binCounts[b]);
    }
    table->AddColumn(lo);
    table->AddColumn(hi);
    table->AddColumn(count);
    this->UpdateProgress(0.85 + 0.15 * static_cast<double>(k + 1) / static_cast<double>(arrays.size()));
  }
  if (volume)
  {
    if (vtkDataArray* mixed = summary->GetArray(kVolGridMixedTotalVolume))
    {
      totalVolume = mixed->GetTuple1(0);
      summary->RemoveArray(kVolGridMixedTotalVolume);
    }
    VolGridAddScalar(summary, "TotalVolume", totalVolume);
  }
  vtkFieldData* fd = output->GetFieldData();
  vtkFieldData* tfd = table->GetFieldData();
  for (int i = 0; i < summary->GetNumberOfArrays(); ++i)
  {
    fd->AddArray(summary->GetAbstractArray(i));
    tfd->AddArray(summary->GetAbstractArray(i));
  }
  return true;
}

void vtkVolGridQuality::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Metric: " << GetMetricName(this->Metric) << "\n";
  os << indent << "BinCount: " << this->BinCount << "\n";
  os << indent << "NumberOfSkippedCells: " << this->NumberOfSkippedCells << "\n";
}
