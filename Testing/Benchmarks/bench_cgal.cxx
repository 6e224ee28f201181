// CGAL 5.5 (header-only, Debian libcgal-dev): Delaunay_triangulation_3 with the
// Exact_predicates_inexact_constructions_kernel, sequential (no TBB, default Sequential_tag).
// Inserting a range makes CGAL spatially sort it (Hilbert/BRIO) before insertion.
// In its own file so that its heavy template compile is isolated.
#include "bench_common.h"

#ifndef VOLGRID_BENCH_HAVE_CGAL
namespace volgrid_bench
{
bool runCGAL(const std::vector<double>&, Meter&, EngineResult& result)
{
  result.error = "CGAL (libcgal-dev) was not found at configure time";
  return false;
}
} // namespace volgrid_bench
#else

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <exception>

namespace volgrid_bench
{

bool runCGAL(const std::vector<double>& xyz, Meter& meter, EngineResult& result)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Triangulation = CGAL::Delaunay_triangulation_3<Kernel>;
  using Point = Kernel::Point_3;

  std::vector<Point> points;
  points.reserve(xyz.size() / 3);
  for (size_t i = 0; i + 2 < xyz.size(); i += 3)
    points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);

  try
  {
    meter.start();
    Triangulation dt;
    dt.insert(points.begin(), points.end());
    meter.stop();
    result.tets = static_cast<int64_t>(dt.number_of_finite_cells());
    result.points = static_cast<int64_t>(dt.number_of_vertices());
  }
  catch (const std::exception& e)
  {
    result.error = std::string("CGAL threw: ") + e.what();
    return false;
  }
  result.threads = 1;
  result.ok = true;
  return true;
}

} // namespace volgrid_bench

#endif // VOLGRID_BENCH_HAVE_CGAL
