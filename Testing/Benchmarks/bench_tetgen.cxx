// TetGen 1.5 (Debian libtet, AGPL-3): benchmark only. Core, Filters and Plugin never link it.
// tetgen.h defines REAL and many other names: it is included here and nowhere else.
#include "bench_common.h"

#ifndef VOLGRID_BENCH_HAVE_TETGEN
namespace volgrid_bench
{
bool runTetGen(const std::vector<double>&, Meter&, EngineResult& result)
{
  result.error = "TetGen (libtet1.5-dev) was not found at configure time";
  return false;
}
} // namespace volgrid_bench
#else

#define TETLIBRARY
#include <tetgen.h>

#include <cstring>
#include <string>

namespace volgrid_bench
{

bool runTetGen(const std::vector<double>& xyz, Meter& meter, EngineResult& result)
{
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(xyz.size() / 3);
  in.pointlist = new REAL[xyz.size()]; // tetgenio::deinitialize() frees it with delete[]
  std::memcpy(in.pointlist, xyz.data(), xyz.size() * sizeof(double));

  char switches[] = "Q"; // quiet; no -p: the plain Delaunay tetrahedralization of the points
  meter.start();
  try
  {
    tetrahedralize(switches, &in, &out);
  }
  catch (int code)
  {
    meter.stop();
    result.error = "TetGen threw error code " + std::to_string(code);
    return false;
  }
  meter.stop();
  result.tets = out.numberoftetrahedra; // TetGen outputs finite tets only
  result.points = out.numberofpoints;
  result.threads = 1;
  result.ok = true;
  return true;
}

} // namespace volgrid_bench

#endif // VOLGRID_BENCH_HAVE_TETGEN
