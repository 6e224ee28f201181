// vtkVolGridQuality: a thin adapter from VTK grids to Core/Quality/Quality.h and Core/Quality/QualityStatistics.h.
#include "vtkVolGridQuality.h"

#include "CfdQuality.h"
#include "PrismQuality.h"
#include "Quality.h"
#include "QualityStatistics.h"

#include "VolGridParallel.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <limits>
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

// Passed from the CFD metrics of a mixed grid to the summary's TotalVolume (not a figure of its own).
constexpr const char* kMixedTotalVolume = "MixedTotalVolume";

vtkSmartPointer<vtkDoubleArray> newCellArray(const char* name, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(n);
  return a;
}

// Runs body(begin, end) over [0, n) with vtkSMPTools in a few sequential blocks, reporting progress in
// [p0, p1] between blocks; false if the user aborted.
template<typename Body>
bool parallelBlocks(vtkAlgorithm* self, vtkIdType n, double p0, double p1, const Body& body)
{
  const vtkIdType blocks = n > 100000 ? 10 : 1;
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    const vtkIdType begin = n * b / blocks, end = n * (b + 1) / blocks;
    vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) { body(first, last); });
    self->UpdateProgress(p0 + (p1 - p0) * static_cast<double>(b + 1) / static_cast<double>(blocks));
    if (self->GetAbortExecute())
    {
      return false;
    }
  }
  return true;
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

void addScalar(vtkFieldData* fd, const char* name, double value)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

// Flat xyz doubles of the points: the array itself when it already is one, else a converted copy.
const double* flatPoints(vtkPoints* points, std::vector<double>& storage)
{
  vtkDataArray* data = points->GetData();
  if (auto* d = vtkDoubleArray::FastDownCast(data))
  {
    return d->GetPointer(0);
  }
  const vtkIdType n = points->GetNumberOfPoints();
  storage.resize(static_cast<size_t>(3 * n));
  vtkSMPTools::For(0, n,
                   [&](vtkIdType first, vtkIdType last)
                   {
                     for (vtkIdType i = first; i < last; ++i)
                     {
                       data->GetTuple(i, storage.data() + 3 * i);
                     }
                   });
  return storage.data();
}
} // namespace

struct vtkVolGridQuality::Internals
{
  // Measures the tets of a flat connectivity (4 ids per tet) into the arrays given by out (indexed like
  // the tets), including the volume gradient. False if aborted.
  template<typename Id>
  static bool MeasureTets(vtkVolGridQuality* self, const double* points, vtkIdType numPoints, const Id* tets,
                          vtkIdType numTets, const vq::TetMetricArrays& out, double* gradient)
  {
    if (!parallelBlocks(self, numTets, 0.0, 0.5,
                        [&](vtkIdType b, vtkIdType e) { vq::measureTets(points, tets, b, e, out); }))
    {
      return false;
    }
    self->SetProgressText("Face adjacency");
    vq::PointTets incidence;
    incidence.reset(numPoints, numTets);
    // One point range per thread: each pass reads all tets but writes only its own points' rows.
    const vtkIdType ranges = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
    auto pointRanges = [&](auto pass)
    {
      vtkSMPTools::For(0, ranges, 1,
                       [&](vtkIdType first, vtkIdType last)
                       {
                         for (vtkIdType r = first; r < last; ++r)
                         {
                           pass(numPoints * r / ranges, numPoints * (r + 1) / ranges);
                         }
                       });
    };
    pointRanges([&](vtkIdType b, vtkIdType e) { incidence.count(tets, b, e); });
    incidence.finishCounts();
    pointRanges([&](vtkIdType b, vtkIdType e) { incidence.fill(tets, b, e); });
    self->UpdateProgress(0.6);
    self->SetProgressText("Volume gradient");
    return parallelBlocks(self, numTets, 0.6, 0.85,
                          [&](vtkIdType b, vtkIdType e)
                          { vq::volumeGradient(tets, out.volume, incidence, b, e, gradient); });
  }

  template<typename Id>
  static bool IdsInRange(const Id* ids, vtkIdType n, vtkIdType numPoints)
  {
    std::atomic<bool> bad(false);
    vtkSMPTools::For(0, n,
                     [&](vtkIdType first, vtkIdType last)
                     {
                       for (vtkIdType i = first; i < last; ++i)
                       {
                         if (ids[i] < 0 || ids[i] >= numPoints)
                         {
                           bad = true;
                           return;
                         }
                       }
                     });
    return !bad;
  }

  static bool Volume(vtkVolGridQuality* self, vtkUnstructuredGrid* input,
                     std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary);
  // The wedges (boundary-layer prisms, Core/Quality/PrismQuality.h): two cell arrays and two figures.
  static bool Wedges(vtkVolGridQuality* self, vtkUnstructuredGrid* input, const double* points,
                     std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary);
  // The CFD face metrics of a pure tet grid (Core/Quality/CfdQuality.h): three cell arrays and six figures.
  static void Cfd(vtkVolGridQuality* self, vtkUnstructuredGrid* input, const double* points,
                  std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary);
  // The same on a grid of tets, wedges and pyramids; field data PyramidVolume too (TotalVolume counts it).
  static bool CfdMixed(vtkVolGridQuality* self, vtkUnstructuredGrid* input, const double* points,
                       std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary);
  static void AddCfdFigures(const vq::CfdSummary& s, vtkFieldData* summary);
  static bool Surface(vtkVolGridQuality* self, vtkPolyData* input, std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays,
                      vtkFieldData* summary);
};

bool vtkVolGridQuality::Internals::Volume(vtkVolGridQuality* self, vtkUnstructuredGrid* input,
                                          std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<double> pointStorage;
  const double* points = numPoints ? flatPoints(input->GetPoints(), pointStorage) : nullptr;

  vtkUnsignedCharArray* types = input->GetCellTypesArray();
  vtkIdType numTets = 0, numWedges = 0, numPyramids = 0;
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    numTets += types->GetValue(c) == VTK_TETRA;
    numWedges += types->GetValue(c) == VTK_WEDGE;
    numPyramids += types->GetValue(c) == VTK_PYRAMID;
  }
  self->NumberOfSkippedCells = numCells - numTets - numWedges - numPyramids;

  for (int m = ASPECT_RATIO; m <= RADIUS_RATIO; ++m)
  {
    arrays.push_back(newCellArray(kMetrics[m].name, numCells));
  }
  auto ptr = [&](int m) { return arrays[m]->GetPointer(0); };

  bool ok = true;
  vtkCellArray* cells = input->GetCells();
  if (numTets == numCells && numCells > 0)
  {
    // Pure tet grid: measure straight from the connectivity array, write straight into the outputs.
    vq::TetMetricArrays out;
    out.aspectRatio = ptr(ASPECT_RATIO);
    out.minDihedralAngle = ptr(MIN_DIHEDRAL_ANGLE);
    out.maxDihedralAngle = ptr(MAX_DIHEDRAL_ANGLE);
    out.minSolidAngle = ptr(MIN_SOLID_ANGLE);
    out.volume = ptr(VOLUME);
    out.radiusEdgeRatio = ptr(RADIUS_EDGE_RATIO);
    out.radiusRatio = ptr(RADIUS_RATIO);
    if (cells->IsStorage64Bit())
    {
      const vtkTypeInt64* conn = cells->GetConnectivityArray64()->GetPointer(0);
      if (!IdsInRange(conn, 4 * numTets, numPoints))
      {
        vtkErrorWithObjectMacro(self, "The grid has point ids outside [0, " << numPoints << ").");
        return false;
      }
      ok = MeasureTets(self, points, numPoints, conn, numTets, out, ptr(VOLUME_GRADIENT));
    }
    else
    {
      const vtkTypeInt32* conn = cells->GetConnectivityArray32()->GetPointer(0);
      if (!IdsInRange(conn, 4 * numTets, numPoints))
      {
        vtkErrorWithObjectMacro(self, "The grid has point ids outside [0, " << numPoints << ").");
        return false;
      }
      ok = MeasureTets(self, points, numPoints, conn, numTets, out, ptr(VOLUME_GRADIENT));
    }
  }
  else
  {
    // Mixed grid: gather the tets, measure them compactly, scatter; the other cells get NaN.
    std::vector<vtkIdType> tets(static_cast<size_t>(4 * numTets));
    std::vector<vtkIdType> tetCells(static_cast<size_t>(numTets));
    vtkIdType t = 0;
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      if (types->GetValue(c) != VTK_TETRA)
        continue;
      vtkIdType npts;
      const vtkIdType* pts;
      input->GetCellPoints(c, npts, pts);
      std::copy(pts, pts + 4, tets.begin() + 4 * t);
      tetCells[t++] = c;
    }
    if (!IdsInRange(tets.data(), 4 * numTets, numPoints))
    {
      vtkErrorWithObjectMacro(self, "The grid has point ids outside [0, " << numPoints << ").");
      return false;
    }
    std::vector<double> compact(static_cast<size_t>(8 * numTets));
    auto slot = [&](int m) { return compact.data() + m * numTets; };
    vq::TetMetricArrays out;
    out.aspectRatio = slot(ASPECT_RATIO);
    out.minDihedralAngle = slot(MIN_DIHEDRAL_ANGLE);
    out.maxDihedralAngle = slot(MAX_DIHEDRAL_ANGLE);
    out.minSolidAngle = slot(MIN_SOLID_ANGLE);
    out.volume = slot(VOLUME);
    out.radiusEdgeRatio = slot(RADIUS_EDGE_RATIO);
    out.radiusRatio = slot(RADIUS_RATIO);
    ok = MeasureTets(self, points, numPoints, tets.data(), numTets, out, slot(VOLUME_GRADIENT));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int m = ASPECT_RATIO; m <= RADIUS_RATIO && ok; ++m)
    {
      double* dst = ptr(m);
      std::fill(dst, dst + numCells, nan);
      const double* src = slot(m);
      for (vtkIdType i = 0; i < numTets; ++i)
      {
        dst[tetCells[i]] = src[i];
      }
    }
  }
  if (!ok)
  {
    return false;
  }
  if (self->NumberOfSkippedCells > 0)
  {
    vtkWarningWithObjectMacro(self, << self->NumberOfSkippedCells << " of " << numCells
                                    << " cells are neither tetrahedra, wedges nor pyramids: they were skipped (their "
                                       "values are NaN).");
  }
  addScalar(summary, "NumberOfTetrahedra", static_cast<double>(numTets));
  addScalar(summary, "SkippedCells", static_cast<double>(self->NumberOfSkippedCells));
  addScalar(summary, "NumberOfPyramids", static_cast<double>(numPyramids));
  if (numPyramids == 0)
    addScalar(summary, "PyramidVolume", 0.0); // with pyramids: measured with the CFD metrics (CfdMixed)
  if (!Wedges(self, input, points, arrays, summary))
    return false;
  if (numTets == numCells && numCells > 0)
    Cfd(self, input, points, arrays, summary);
  else if (self->NumberOfSkippedCells == 0 && numCells > 0)
    return CfdMixed(self, input, points, arrays, summary);
  return true;
}

bool vtkVolGridQuality::Internals::Wedges(vtkVolGridQuality* self, vtkUnstructuredGrid* input, const double* points,
                                          std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkUnsignedCharArray* types = input->GetCellTypesArray();
  std::vector<vtkIdType> wedges, wedgeCells; // SolverMesh's order: VTK's triangles reversed
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    if (types->GetValue(c) != VTK_WEDGE)
      continue;
    vtkIdType npts;
    const vtkIdType* v;
    input->GetCellPoints(c, npts, v);
    if (npts != 6)
    {
      vtkErrorWithObjectMacro(self, "Wedge cell " << c << " has " << npts << " points instead of 6.");
      return false;
    }
    wedges.insert(wedges.end(), { v[0], v[2], v[1], v[3], v[5], v[4] });
    wedgeCells.push_back(c);
  }
  addScalar(summary, "NumberOfWedges", static_cast<double>(wedgeCells.size()));
  if (!IdsInRange(wedges.data(), static_cast<vtkIdType>(wedges.size()), numPoints))
  {
    vtkErrorWithObjectMacro(self, "The grid has point ids outside [0, " << numPoints << ").");
    return false;
  }
  if (wedgeCells.empty())
  {
    addScalar(summary, "InvertedWedges", 0.0);
    return true;
  }
  auto volume = newCellArray("WedgeVolume", numCells), jacobian = newCellArray("WedgeScaledJacobian", numCells);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::fill(volume->GetPointer(0), volume->GetPointer(0) + numCells, nan);
  std::fill(jacobian->GetPointer(0), jacobian->GetPointer(0) + numCells, nan);
  std::vector<unsigned char> inverted(wedgeCells.size(), 0);
  const bool ok = parallelBlocks(self, static_cast<vtkIdType>(wedgeCells.size()), 0.6, 0.7,
                                 [&](vtkIdType begin, vtkIdType end)
                                 {
                                   for (vtkIdType w = begin; w < end; ++w)
                                   {
                                     const double* p[6];
                                     for (int k = 0; k < 6; ++k)
                                       p[k] = points + 3 * wedges[6 * w + k];
                                     const vq::PrismMetrics m = vq::prismMetrics(p);
                                     volume->SetValue(wedgeCells[w], m.volume);
                                     jacobian->SetValue(wedgeCells[w], m.minScaledJacobian);
                                     inverted[w] = m.nonPositiveCorners > 0;
                                   }
                                 });
  addScalar(summary, "InvertedWedges",
            static_cast<double>(std::count(inverted.begin(), inverted.end(), static_cast<unsigned char>(1))));
  arrays.push_back(volume);
  arrays.push_back(jacobian);
  return ok;
}

void vtkVolGridQuality::Internals::Cfd(vtkVolGridQuality* self, vtkUnstructuredGrid* input, const double* points,
                                       std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary)
{
  self->SetProgressText("CFD face metrics");
  const vtkIdType numCells = input->GetNumberOfCells();
  std::vector<double> xyz(points, points + 3 * input->GetNumberOfPoints());
  std::vector<int32_t> tets(static_cast<size_t>(4 * numCells));
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    input->GetCellPoints(c, npts, pts);
    std::copy(pts, pts + 4, tets.begin() + 4 * c);
  }
  vq::CfdCellMetrics cells;
  const vq::CfdSummary s = vq::cfdMetrics(xyz, tets, &cells);
  const std::pair<const char*, std::vector<double>*> columns[] = { { "NonOrthogonality", &cells.nonOrthogonality },
                                                                   { "Skewness", &cells.skewness },
                                                                   { "VolumeRatio", &cells.volumeRatio } };
  for (const auto& column : columns)
  {
    arrays.push_back(newCellArray(column.first, numCells));
    std::copy(column.second->begin(), column.second->end(), arrays.back()->GetPointer(0));
  }
  AddCfdFigures(s, summary);
}

void vtkVolGridQuality::Internals::AddCfdFigures(const vq::CfdSummary& s, vtkFieldData* summary)
{
  addScalar(summary, "MaxNonOrthogonality", s.maxNonOrthogonality);
  addScalar(summary, "AverageNonOrthogonality", s.averageNonOrthogonality);
  addScalar(summary, "SevereNonOrthogonalFaces", static_cast<double>(s.severelyNonOrthogonalFaces));
  addScalar(summary, "MaxSkewness", s.maxSkewness);
  addScalar(summary, "HighlySkewFaces", static_cast<double>(s.highlySkewFaces));
  addScalar(summary, "MaxVolumeRatio", s.maxVolumeRatio);
}

bool vtkVolGridQuality::Internals::CfdMixed(vtkVolGridQuality* self, vtkUnstructuredGrid* input, const double* points,
                                            std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary)
{
  self->SetProgressText("CFD face metrics");
  const vtkIdType numCells = input->GetNumberOfCells();
  std::vector<double> xyz(points, points + 3 * input->GetNumberOfPoints());
  // Each shape in Core's order (VTK's wedge lists its triangles the other way round), and where it came from.
  std::vector<int32_t> tets, prisms, pyramids;
  std::vector<vtkIdType> tetCells, prismCells, pyramidCells;
  vtkUnsignedCharArray* types = input->GetCellTypesArray();
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    vtkIdType npts;
    const vtkIdType* v;
    input->GetCellPoints(c, npts, v);
    const int type = types->GetValue(c);
    const int expected = type == VTK_TETRA ? 4 : type == VTK_WEDGE ? 6 : 5;
    if (npts != expected)
    {
      vtkErrorWithObjectMacro(self, "Cell " << c << " has " << npts << " points instead of " << expected << ".");
      return false;
    }
    if (std::any_of(v, v + npts, [&](vtkIdType id) { return id < 0 || id >= input->GetNumberOfPoints(); }))
    {
      vtkErrorWithObjectMacro(self,
                              "Cell " << c << " has a point id outside [0, " << input->GetNumberOfPoints() << ").");
      return false;
    }
    if (type == VTK_TETRA)
      tets.insert(tets.end(), v, v + 4), tetCells.push_back(c);
    else if (type == VTK_WEDGE)
      prisms.insert(prisms.end(),
                    { static_cast<int32_t>(v[0]), static_cast<int32_t>(v[2]), static_cast<int32_t>(v[1]),
                      static_cast<int32_t>(v[3]), static_cast<int32_t>(v[5]), static_cast<int32_t>(v[4]) }),
        prismCells.push_back(c);
    else
      pyramids.insert(pyramids.end(), v, v + 5), pyramidCells.push_back(c);
  }
  vq::MixedCells mixed;
  mixed.tets = &tets;
  mixed.prisms = &prisms;
  mixed.pyramids = &pyramids;
  vq::CfdCellMetrics cells;
  const vq::CfdSummary s = vq::cfdMetricsMixed(xyz, mixed, &cells);
  std::vector<vtkIdType> order(tetCells); // Core's cell order -> the grid's
  order.insert(order.end(), prismCells.begin(), prismCells.end());
  order.insert(order.end(), pyramidCells.begin(), pyramidCells.end());
  const std::pair<const char*, std::vector<double>*> columns[] = { { "NonOrthogonality", &cells.nonOrthogonality },
                                                                   { "Skewness", &cells.skewness },
                                                                   { "VolumeRatio", &cells.volumeRatio } };
  for (const auto& column : columns)
  {
    arrays.push_back(newCellArray(column.first, numCells));
    double* dst = arrays.back()->GetPointer(0);
    for (size_t i = 0; i < order.size(); ++i)
      dst[order[i]] = (*column.second)[i];
  }
  double pyramidVolume = 0, cellVolume = 0;
  for (size_t i = 0; i < order.size(); ++i)
    (i >= tetCells.size() + prismCells.size() ? pyramidVolume : cellVolume) += cells.volume[i];
  if (!pyramidCells.empty())
    addScalar(summary, "PyramidVolume", pyramidVolume);
  // The total as checkMesh splits the cells: the wedges' own volumes (three tets each) overlap or leave
  // gaps where neighbouring wedges split a warped side quad differently.
  addScalar(summary, kMixedTotalVolume, cellVolume + pyramidVolume);
  AddCfdFigures(s, summary);
  return true;
}

bool vtkVolGridQuality::Internals::Surface(vtkVolGridQuality* self, vtkPolyData* input,
                                           std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<double> pointStorage;
  const double* points = numPoints ? flatPoints(input->GetPoints(), pointStorage) : nullptr;

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
  self->NumberOfSkippedCells = numCells - numTris;

  const int surfaceMetrics[4] = { ASPECT_RATIO, AREA, MIN_ANGLE, MAX_ANGLE };
  for (int m : surfaceMetrics)
  {
    arrays.push_back(newCellArray(kMetrics[m].name, numCells));
    arrays.back()->Fill(std::numeric_limits<double>::quiet_NaN());
  }
  double* aspect = arrays[0]->GetPointer(0);
  double* area = arrays[1]->GetPointer(0);
  double* minAngle = arrays[2]->GetPointer(0);
  double* maxAngle = arrays[3]->GetPointer(0);
  if (!parallelBlocks(self, numTris, 0.0, 0.6,
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
  if (self->NumberOfSkippedCells > 0)
  {
    vtkWarningWithObjectMacro(self, << self->NumberOfSkippedCells << " of " << numCells
                                    << " cells are not triangles: they were skipped (their values are NaN).");
  }
  addScalar(summary, "NumberOfElements", static_cast<double>(s.elements));
  addScalar(summary, "SurfaceArea", s.area);
  addScalar(summary, "EnclosedVolume", s.enclosedVolume);
  addScalar(summary, "BoundaryEdges", static_cast<double>(s.boundaryEdges));
  addScalar(summary, "BoundaryLoops", static_cast<double>(s.boundaryLoops));
  addScalar(summary, "NonManifoldEdges", static_cast<double>(s.nonManifoldEdges));
  addScalar(summary, "Shells", static_cast<double>(s.shells));
  addScalar(summary, "SkippedCells", static_cast<double>(self->NumberOfSkippedCells));
  return true;
}

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
    ok = Internals::Volume(this, grid, arrays, summary);
  }
  else if (auto* surface = vtkPolyData::SafeDownCast(input))
  {
    volume = false;
    ok = Internals::Surface(this, surface, arrays, summary);
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
      auto q = newCellArray("Quality", numCells);
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

    auto lo = newCellArray((std::string(info->name) + "_BinStart").c_str(), this->BinCount);
    auto hi = newCellArray((std::string(info->name) + "_BinEnd").c_str(), this->BinCount);
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
    if (vtkDataArray* mixed = summary->GetArray(kMixedTotalVolume))
    {
      totalVolume = mixed->GetTuple1(0);
      summary->RemoveArray(kMixedTotalVolume);
    }
    addScalar(summary, "TotalVolume", totalVolume);
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
