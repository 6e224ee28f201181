// VolGrid's own Delaunay kernel (Core/Delaunay/Delaunay.h), compiled in when that header exists.
#include "bench_common.h"

#ifndef VOLGRID_BENCH_HAVE_VOLGRID
namespace volgrid_bench
{
bool runVolGrid(const std::vector<double>&, const VolGridSettings&, Meter&, EngineResult& result)
{
  result.error =
    "the volgrid engine is not built (no Core/Delaunay/Delaunay.h at configure time, or -DVOLGRID_BENCH_VOLGRID=OFF)";
  return false;
}
} // namespace volgrid_bench
#else

#include "Delaunay.h"
#include "ParallelFor.h"
#include "TetMesh.h"

#include <algorithm>
#include <cstdlib>

namespace volgrid_bench
{

bool runVolGrid(const std::vector<double>& xyz, const VolGridSettings& settings, Meter& meter, EngineResult& result)
{
  volgrid::DelaunayOptions options; // defaults (ghost tets kept, as CGAL keeps its infinite cells)
  options.spatialSort = settings.spatialSort;
  // Threads: the default (all cores), or VOLGRID_THREADS=N (0 = all cores); VOLGRID_CANONICAL=1
  // turns on canonical tet numbering for every input (large ones always have it).
  if (const char* env = std::getenv("VOLGRID_THREADS"))
    options.threads = std::atoi(env);
  if (const char* env = std::getenv("VOLGRID_CANONICAL"))
    options.canonicalNumbering = std::atoi(env) != 0;
  if (settings.location == "walk")
    options.location = volgrid::PointLocation::Walk;
  else if (settings.location == "bucket-grid")
    options.location = volgrid::PointLocation::BucketGrid;
  else
  {
    result.error = "unknown --location '" + settings.location + "' (walk, bucket-grid)";
    return false;
  }

  volgrid::TetMesh mesh;
  std::vector<int32_t> inputToVertex;
  volgrid::DelaunayReport report;
  meter.start();
  const volgrid::Status status =
    volgrid::buildDelaunay(xyz.data(), xyz.size() / 3, options, mesh, inputToVertex, nullptr, &report);
  meter.stop();
  if (!status.ok())
  {
    result.error = "buildDelaunay failed: " + status.message;
    return false;
  }
  result.tets = mesh.numFiniteTets();
  result.points = static_cast<int64_t>(report.numVertices);
  result.threads = std::min(volgrid::resolveThreads(options.threads), 255); // Delaunay.h: at most 255
  result.note = "location=" + settings.location + (settings.spatialSort ? " sort=brio-hilbert" : " sort=none") +
    " walk_steps=" + std::to_string(report.walkSteps) + " cavity_tets=" + std::to_string(report.cavityTets) +
    " deferred=" + std::to_string(report.deferred) + " duplicates=" + std::to_string(report.numDuplicates);
  result.ok = true;
  return true;
}

} // namespace volgrid_bench

#endif // VOLGRID_BENCH_HAVE_VOLGRID
