// volgrid_bench_delaunay: one Delaunay tetrahedralization by one engine on one generated input, reported
// as one JSON line on stdout. scripts/bench.sh runs one process per case so that peak memory is per run.
//
//   volgrid_bench_delaunay --engine volgrid|tetgen|cgal|vtk --input random|grid|jittered-grid|spheres
//                          --n N [--seed S] [--force]
//                          [--location walk|bucket-grid] [--no-sort]      (volgrid engine only)
//
// Only the triangulation call is timed. The memory baseline (VmRSS) is taken after the points were
// generated and copied into the engine's own input structure; the peak (VmHWM, reset at the start of the
// timed call when the kernel allows it) is read right after the call.
// bytes_per_tet_beyond_input = (peak RSS - baseline RSS) / finite tets.
#include "bench_common.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{

void usage(FILE* out)
{
  std::fprintf(out,
               "usage: volgrid_bench_delaunay --engine volgrid|tetgen|cgal|vtk\n"
               "         --input random|grid|jittered-grid|spheres --n N [--seed S] [--force]\n"
               "         [--location walk|bucket-grid] [--no-sort]\n"
               "  --force      run vtkDelaunay3D above 100000 points (it is very slow)\n"
               "  --location   volgrid point location: visibility walk (default) or the bucket grid\n"
               "  --no-sort    volgrid: insert in input order (no BRIO/Hilbert sort)\n");
}

std::string jsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    }
    else
      out += c;
  }
  return out + "\"";
}

std::string jsonNumber(double v, const char* fmt = "%.6g")
{
  if (!std::isfinite(v))
    return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

} // namespace

int main(int argc, char** argv)
{
  std::string engine, input;
  long long n = -1;
  unsigned long long seed = 1;
  bool force = false;
  volgrid_bench::VolGridSettings volgridSettings;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> const char*
    {
      if (i + 1 >= argc)
      {
        std::fprintf(stderr, "volgrid_bench_delaunay: %s needs a value\n", name);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--engine")
      engine = value("--engine");
    else if (a == "--input")
      input = value("--input");
    else if (a == "--n")
      n = std::strtoll(value("--n"), nullptr, 10);
    else if (a == "--seed")
      seed = std::strtoull(value("--seed"), nullptr, 10);
    else if (a == "--force")
      force = true;
    else if (a == "--location")
      volgridSettings.location = value("--location");
    else if (a == "--no-sort")
      volgridSettings.spatialSort = false;
    else if (a == "-h" || a == "--help")
    {
      usage(stdout);
      return 0;
    }
    else
    {
      std::fprintf(stderr, "volgrid_bench_delaunay: unknown argument '%s'\n", a.c_str());
      usage(stderr);
      return 2;
    }
  }
  if (engine.empty() || input.empty() || n <= 0)
  {
    usage(stderr);
    return 2;
  }

  volgrid_bench::EngineResult result;
  volgrid_bench::Meter meter;
  std::vector<double> xyz;
  std::string error;
  bool ok = volgrid_bench::generatePoints(input, n, seed, xyz, error);
  if (ok)
  {
    if (engine == "volgrid")
      ok = volgrid_bench::runVolGrid(xyz, volgridSettings, meter, result);
    else if (engine == "tetgen")
      ok = volgrid_bench::runTetGen(xyz, meter, result);
    else if (engine == "cgal")
      ok = volgrid_bench::runCGAL(xyz, meter, result);
    else if (engine == "vtk")
    {
      if (n > 100000 && !force)
      {
        ok = false;
        result.error = "vtkDelaunay3D is only run up to 100000 points (use --force)";
      }
      else
        ok = volgrid_bench::runVtkDelaunay3D(xyz, meter, result);
    }
    else
    {
      ok = false;
      result.error = "unknown engine '" + engine + "' (volgrid, tetgen, cgal, vtk)";
    }
    error = result.error;
  }

  std::string line = "{\"engine\":" + jsonString(engine) + ",\"input\":" + jsonString(input) +
    ",\"n\":" + std::to_string(n) + ",\"seed\":" + std::to_string(seed) + ",\"ok\":" + (ok ? "true" : "false");
  if (ok)
  {
    const double tets = static_cast<double>(result.tets);
    line += ",\"seconds\":" + jsonNumber(meter.seconds(), "%.4f");
    line += ",\"tets\":" + std::to_string(result.tets);
    line += ",\"tets_per_s\":" + jsonNumber(tets > 0 ? tets / meter.seconds() : NAN, "%.0f");
    line += ",\"peak_rss_mb\":" + jsonNumber(meter.peakMb(), "%.1f");
    line += ",\"baseline_rss_mb\":" + jsonNumber(meter.baselineMb(), "%.1f");
    line +=
      ",\"bytes_per_tet_beyond_input\":" + jsonNumber(tets > 0 ? meter.peakBeyondBaselineBytes() / tets : NAN, "%.1f");
    line += ",\"threads\":" + std::to_string(result.threads);
    if (result.points >= 0)
      line += ",\"mesh_points\":" + std::to_string(result.points);
    line += std::string(",\"peak_reset\":") + (meter.peakWasReset() ? "true" : "false");
    if (!result.note.empty())
      line += ",\"note\":" + jsonString(result.note);
  }
  else
    line += ",\"error\":" + jsonString(error.empty() ? std::string("failed") : error);
  line += "}";
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
  return ok ? 0 : 1;
}
