// The volume-grid paths of vtkVolGridQuality: a thin adapter from a vtkUnstructuredGrid to Core/Quality's
// tet metrics (Quality.h), wedge metrics (PrismQuality.h) and checkMesh's CFD metrics (CfdQuality.h).
#include "VolGridQualityVolume.h"

#include "VolGridCellOrder.h"
#include "VolGridQualityArrays.h"
#include "vtkVolGridQuality.h"

#include "CfdQuality.h"
#include "PrismQuality.h"
#include "Quality.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace
{
namespace vq = volgrid::quality;
using Q = vtkVolGridQuality;

// Measures the tets of a flat connectivity (4 ids per tet) into the arrays given by out (indexed like
// the tets), including the volume gradient. False if aborted.
template<typename Id>
bool measureTetsAndGradient(vtkAlgorithm* self, const double* points, vtkIdType numPoints, const Id* tets,
                            vtkIdType numTets, const vq::TetMetricArrays& out, double* gradient)
{
  if (!VolGridParallelBlocks(self, numTets, 0.0, 0.5,
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
  return VolGridParallelBlocks(self, numTets, 0.6, 0.85,
                               [&](vtkIdType b, vtkIdType e)
                               { vq::volumeGradient(tets, out.volume, incidence, b, e, gradient); });
}

// True if every id of ids[0, n) is a point of the grid.
template<typename Id>
bool idsInRange(const Id* ids, vtkIdType n, vtkIdType numPoints)
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

// checkMesh's six face figures as field data.
void addCfdFigures(const vq::CfdSummary& s, vtkFieldData* summary)
{
  VolGridAddScalar(summary, "MaxNonOrthogonality", s.maxNonOrthogonality);
  VolGridAddScalar(summary, "AverageNonOrthogonality", s.averageNonOrthogonality);
  VolGridAddScalar(summary, "SevereNonOrthogonalFaces", static_cast<double>(s.severelyNonOrthogonalFaces));
  VolGridAddScalar(summary, "MaxSkewness", s.maxSkewness);
  VolGridAddScalar(summary, "HighlySkewFaces", static_cast<double>(s.highlySkewFaces));
  VolGridAddScalar(summary, "MaxVolumeRatio", s.maxVolumeRatio);
}

// The wedges (boundary-layer prisms, Core/Quality/PrismQuality.h): two cell arrays and two figures.
bool measureWedges(vtkAlgorithm* self, vtkUnstructuredGrid* input, const double* points,
                   std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkUnsignedCharArray* types = input->GetCellTypesArray();
  std::vector<vtkIdType> wedges, wedgeCells; // in Core's prism order (VolGridCellOrder.h)
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
    const auto prism = VolGridPrismFromWedge<vtkIdType>(v);
    wedges.insert(wedges.end(), prism.begin(), prism.end());
    wedgeCells.push_back(c);
  }
  VolGridAddScalar(summary, "NumberOfWedges", static_cast<double>(wedgeCells.size()));
  if (!idsInRange(wedges.data(), static_cast<vtkIdType>(wedges.size()), numPoints))
  {
    vtkErrorWithObjectMacro(self, "The grid has point ids outside [0, " << numPoints << ").");
    return false;
  }
  if (wedgeCells.empty())
  {
    VolGridAddScalar(summary, "InvertedWedges", 0.0);
    return true;
  }
  auto volume = VolGridNewCellArray("WedgeVolume", numCells),
       jacobian = VolGridNewCellArray("WedgeScaledJacobian", numCells);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::fill(volume->GetPointer(0), volume->GetPointer(0) + numCells, nan);
  std::fill(jacobian->GetPointer(0), jacobian->GetPointer(0) + numCells, nan);
  std::vector<unsigned char> inverted(wedgeCells.size(), 0);
  const bool ok = VolGridParallelBlocks(self, static_cast<vtkIdType>(wedgeCells.size()), 0.6, 0.7,
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
  VolGridAddScalar(summary, "InvertedWedges",
                   static_cast<double>(std::count(inverted.begin(), inverted.end(), static_cast<unsigned char>(1))));
  arrays.push_back(volume);
  arrays.push_back(jacobian);
  return ok;
}

// The CFD face metrics of a pure tet grid (Core/Quality/CfdQuality.h): three cell arrays and six figures.
void measureTetCfd(vtkAlgorithm* self, vtkUnstructuredGrid* input, const double* points,
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
    arrays.push_back(VolGridNewCellArray(column.first, numCells));
    std::copy(column.second->begin(), column.second->end(), arrays.back()->GetPointer(0));
  }
  addCfdFigures(s, summary);
}

// The same on a grid of tets, wedges and pyramids; field data PyramidVolume too (TotalVolume counts it).
bool measureMixedCfd(vtkAlgorithm* self, vtkUnstructuredGrid* input, const double* points,
                     std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary)
{
  self->SetProgressText("CFD face metrics");
  const vtkIdType numCells = input->GetNumberOfCells();
  std::vector<double> xyz(points, points + 3 * input->GetNumberOfPoints());
  // Each shape in Core's order (VolGridCellOrder.h: VTK's wedge lists its triangles the other way round), and
  // where it came from.
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
    {
      const auto prism = VolGridPrismFromWedge<int32_t>(v);
      prisms.insert(prisms.end(), prism.begin(), prism.end());
      prismCells.push_back(c);
    }
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
    arrays.push_back(VolGridNewCellArray(column.first, numCells));
    double* dst = arrays.back()->GetPointer(0);
    for (size_t i = 0; i < order.size(); ++i)
      dst[order[i]] = (*column.second)[i];
  }
  double pyramidVolume = 0, cellVolume = 0;
  for (size_t i = 0; i < order.size(); ++i)
    (i >= tetCells.size() + prismCells.size() ? pyramidVolume : cellVolume) += cells.volume[i];
  if (!pyramidCells.empty())
    VolGridAddScalar(summary, "PyramidVolume", pyramidVolume);
  // The total as checkMesh splits the cells: the wedges' own volumes (three tets each) overlap or leave
  // gaps where neighbouring wedges split a warped side quad differently.
  VolGridAddScalar(summary, kVolGridMixedTotalVolume, cellVolume + pyramidVolume);
  addCfdFigures(s, summary);
  return true;
}
} // namespace

bool VolGridMeasureVolumeGrid(vtkAlgorithm* self, vtkUnstructuredGrid* input,
                              std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary,
                              vtkIdType& skippedCells)
{
  const vtkIdType numCells = input->GetNumberOfCells();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<double> pointStorage;
  const double* points = numPoints ? VolGridFlatPoints(input->GetPoints(), pointStorage) : nullptr;

  vtkUnsignedCharArray* types = input->GetCellTypesArray();
  vtkIdType numTets = 0, numWedges = 0, numPyramids = 0;
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    numTets += types->GetValue(c) == VTK_TETRA;
    numWedges += types->GetValue(c) == VTK_WEDGE;
    numPyramids += types->GetValue(c) == VTK_PYRAMID;
  }
  skippedCells = numCells - numTets - numWedges - numPyramids;

  for (int m = Q::ASPECT_RATIO; m <= Q::RADIUS_RATIO; ++m)
  {
    arrays.push_back(VolGridNewCellArray(vtkVolGridQuality::GetMetricName(m), numCells));
  }
  auto ptr = [&](int m) { return arrays[m]->GetPointer(0); };

  bool ok = true;
  vtkCellArray* cells = input->GetCells();
  if (numTets == numCells && numCells > 0)
  {
    // Pure tet grid: measure straight from the connectivity array, write straight into the outputs.
    vq::TetMetricArrays out;
    out.aspectRatio = ptr(Q::ASPECT_RATIO);
    out.minDihedralAngle = ptr(Q::MIN_DIHEDRAL_ANGLE);
    out.maxDihedralAngle = ptr(Q::MAX_DIHEDRAL_ANGLE);
    out.minSolidAngle = ptr(Q::MIN_SOLID_ANGLE);
    out.volume = ptr(Q::VOLUME);
    out.radiusEdgeRatio = ptr(Q::RADIUS_EDGE_RATIO);
    out.radiusRatio = ptr(Q::RADIUS_RATIO);
    // The connectivity is 64- or 32-bit: one check and one measurement for either.
    auto measure = [&](const auto* conn)
    {
      if (!idsInRange(conn, 4 * numTets, numPoints))
      {
        vtkErrorWithObjectMacro(self, "The grid has point ids outside [0, " << numPoints << ").");
        return false;
      }
      return measureTetsAndGradient(self, points, numPoints, conn, numTets, out, ptr(Q::VOLUME_GRADIENT));
    };
    ok = cells->IsStorage64Bit() ? measure(cells->GetConnectivityArray64()->GetPointer(0))
                                 : measure(cells->GetConnectivityArray32()->GetPointer(0));
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
    if (!idsInRange(tets.data(), 4 * numTets, numPoints))
    {
      vtkErrorWithObjectMacro(self, "The grid has point ids outside [0, " << numPoints << ").");
      return false;
    }
    std::vector<double> compact(static_cast<size_t>(8 * numTets));
    auto slot = [&](int m) { return compact.data() + m * numTets; };
    vq::TetMetricArrays out;
    out.aspectRatio = slot(Q::ASPECT_RATIO);
    out.minDihedralAngle = slot(Q::MIN_DIHEDRAL_ANGLE);
    out.maxDihedralAngle = slot(Q::MAX_DIHEDRAL_ANGLE);
    out.minSolidAngle = slot(Q::MIN_SOLID_ANGLE);
    out.volume = slot(Q::VOLUME);
    out.radiusEdgeRatio = slot(Q::RADIUS_EDGE_RATIO);
    out.radiusRatio = slot(Q::RADIUS_RATIO);
    ok = measureTetsAndGradient(self, points, numPoints, tets.data(), numTets, out, slot(Q::VOLUME_GRADIENT));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int m = Q::ASPECT_RATIO; m <= Q::RADIUS_RATIO && ok; ++m)
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
  if (skippedCells > 0)
  {
    vtkWarningWithObjectMacro(self, << skippedCells << " of " << numCells
                                    << " cells are neither tetrahedra, wedges nor pyramids: they were skipped (their "
                                       "values are NaN).");
  }
  VolGridAddScalar(summary, "NumberOfTetrahedra", static_cast<double>(numTets));
  VolGridAddScalar(summary, "SkippedCells", static_cast<double>(skippedCells));
  VolGridAddScalar(summary, "NumberOfPyramids", static_cast<double>(numPyramids));
  if (numPyramids == 0)
    VolGridAddScalar(summary, "PyramidVolume", 0.0); // with pyramids: measured with the CFD metrics (measureMixedCfd)
  if (!measureWedges(self, input, points, arrays, summary))
    return false;
  if (numTets == numCells && numCells > 0)
    measureTetCfd(self, input, points, arrays, summary);
  else if (skippedCells == 0 && numCells > 0)
    return measureMixedCfd(self, input, points, arrays, summary);
  return true;
}
