#include "MeshRegions.h"

#include "ParallelFor.h"

#include <algorithm>

namespace volgrid
{

namespace
{
constexpr size_t kBoxSample = 32768;

} // namespace

int regionCountFor(int64_t tets, int64_t perRegion, int maxRegions)
{
  int regions = 1;
  while (regions < maxRegions && tets / (2 * regions) >= perRegion)
    regions *= 2;
  return regions;
}

void tetCentroid(const TetMesh& mesh, int32_t t, double* c)
{
  const int32_t* v = mesh.vertices(t);
  const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *d = mesh.point(v[2]), *e = mesh.point(v[3]);
  for (int k = 0; k < 3; ++k)
    c[k] = (a[k] + b[k] + d[k] + e[k]) / 4;
}

RegionBoxes boxesOfTets(const TetMesh& mesh, const std::vector<int32_t>& tets, int regions)
{
  const size_t stride = std::max<size_t>(1, tets.size() / kBoxSample);
  std::vector<double> xyz;
  xyz.reserve(3 * (tets.size() / stride + 1));
  for (size_t k = 0; k < tets.size(); k += stride)
  {
    xyz.resize(xyz.size() + 3);
    tetCentroid(mesh, tets[k], xyz.data() + xyz.size() - 3);
  }
  return RegionBoxes(xyz, regions);
}

std::vector<uint8_t> vertexRegions(const TetMesh& mesh, const RegionBoxes& boxes, int threads)
{
  std::vector<uint8_t> region(static_cast<size_t>(mesh.numVertices()), kSpansRegions);
  parallelFor(threads, mesh.numVertices(), 16384,
              [&](int, int64_t from, int64_t to)
              {
                for (int64_t v = from; v < to; ++v)
                  region[static_cast<size_t>(v)] = boxes.regionOf(mesh.point(static_cast<int32_t>(v)));
              });
  return region;
}

void fillSlotPools(TetMesh& mesh, const std::vector<TetSlotPool*>& pools, const std::vector<size_t>& wants)
{
  std::vector<int32_t> free = mesh.takeFreeSlots();
  size_t used = 0;
  for (size_t i = 0; i < pools.size(); ++i)
  {
    const size_t fromList = std::min(free.size() - used, wants[i]);
    std::vector<int32_t> mine(free.begin() + static_cast<ptrdiff_t>(used),
                              free.begin() + static_cast<ptrdiff_t>(used + fromList));
    used += fromList;
    const int32_t appended = static_cast<int32_t>(wants[i] - fromList);
    pools[i]->assign(std::move(mine), mesh.appendTets(appended), appended);
  }
  for (size_t i = free.size(); i > used; --i)
    mesh.returnSlot(free[i - 1]);
}

} // namespace volgrid
