// volgrid delaunay: exact Delaunay tetrahedralization of a point set (TetGen .node file or random points).
#include "CliSupport.h"
#include "Commands.h"
#include "FlagParser.h"
#include "NodeFile.h"
#include "OutputPaths.h"
#include "SizeLimit.h"
#include "VolGridConversion.h"
#include "XmlDataFiles.h"

#include "Delaunay.h"
#include "MeshChecker.h"

#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace
{
const char* kUsage =
  "usage: volgrid delaunay INPUT.node | --random N [--seed S]\n"
  "                        [--check] [--json] [--out FILE.vtu] [--no-sort] [--location walk|grid]\n"
  "                        [--threads N]\n"
  "  Tetrahedralizes the points exactly (Delaunay, symbolic tie-breaking). Exactly coincident points\n"
  "  are merged. --check verifies orientation, adjacency, empty spheres and the hull (exit 1 if not).\n"
  "  --threads: 0 (default) = all cores, N = N threads; the output is the same for any value.\n"
  "  --max-tets N: refuse before any work when about N tets would be exceeded (default: what the available\n"
  "  memory holds); at most 67108864 points are supported. --out FILE.vtu is replaced atomically.\n";

struct Arguments
{
  std::string nodeFile;
  long long randomCount = -1;
  long long seed = 1;
  bool check = false;
  bool json = false;
  long long maxTets = 0;
  std::string out;
  volgrid::DelaunayOptions options;
};

// The flags of `volgrid delaunay` (the usage text is kUsage's).
void declareFlags(volgrid::cli::FlagParser& p, Arguments& args, long long& threads, std::string& location)
{
  p.add("--random", args.randomCount).accept = [&p, &args](const char*)
  { return args.randomCount >= 0 || p.fail("--random needs a non-negative count"); };
  p.add("--max-tets", args.maxTets).accept = [&args](const char* v)
  { return volgrid::cli::parseMaxTets("delaunay", v, args.maxTets); };
  p.add("--seed", args.seed);
  p.add("--out", args.out);
  p.add("--location", location).accept = [&p, &args](const char* v)
  {
    if (std::strcmp(v, "walk") == 0)
      args.options.location = volgrid::PointLocation::Walk;
    else if (std::strcmp(v, "grid") == 0)
      args.options.location = volgrid::PointLocation::BucketGrid;
    else
      return p.fail(std::string("--location is walk or grid, not '") + v + "'");
    return true;
  };
  p.add("--threads", threads).accept = [&p, &threads](const char*)
  {
    return (threads >= 0 && threads <= 1024) ||
      p.fail("--threads is 0 (all cores) or 1..1024, not " + std::to_string(threads));
  };
  p.add("--check", args.check, true);
  p.add("--json", args.json, true);
  p.add("--no-sort", args.options.spatialSort, false);
}

// 2 (after the message) when the arguments are bad, 0 after --help, -1 to go on.
int parseArguments(int argc, char** argv, Arguments& args)
{
  long long threads = args.options.threads;
  std::string location;
  volgrid::cli::FlagParser p("delaunay", kUsage);
  declareFlags(p, args, threads, location);
  std::vector<std::string> positional;
  if (const int code = p.scan(argc, argv, positional); code >= 0)
    return code;
  if (positional.size() > 1)
    return p.fail("more than one input ('" + positional[1] + "')"), 2;
  if (!positional.empty())
    args.nodeFile = positional[0];
  if (args.nodeFile.empty() == (args.randomCount < 0))
    return p.fail("give either an input .node file or --random N", true), 2;
  args.options.threads = static_cast<int>(threads);
  args.options.seed = static_cast<uint64_t>(args.seed) * 0x9E3779B97F4A7C15ull + 1;
  return -1;
}

// The Delaunay kernel's own limit (Delaunay.cxx: 2^29 / 8 points).
constexpr long long kMaxPoints = (1ll << 29) / 8;

bool refuseIfTooLarge(const Arguments& args, double points, const std::string& cause)
{
  return volgrid::cli::refuseIfTooLarge("delaunay", volgrid::estimateDelaunaySize(points), args.maxTets, cause);
}

// Uniform random points in the unit cube, the same for a given seed on every run.
std::vector<double> randomPoints(long long n, long long seed)
{
  std::mt19937_64 generator(static_cast<uint64_t>(seed));
  std::vector<double> xyz(3 * static_cast<size_t>(n));
  for (double& c : xyz)
  {
    c = static_cast<double>(generator() >> 11) * 0x1.0p-53;
  }
  return xyz;
}
} // namespace

int runDelaunayCommand(int argc, char** argv)
{
  Arguments args;
  if (const int code = parseArguments(argc, argv, args); code >= 0)
    return code;
  if (!args.out.empty())
  {
    if (const int code = volgrid::cli::checkOutputPath("delaunay", "--out", args.out, { "vtu" }, { args.nodeFile }))
      return code;
  }
  std::vector<double> xyz;
  if (!args.nodeFile.empty())
  {
    const volgrid::Status read = volgrid::readNodeFile(args.nodeFile, xyz);
    if (!read.ok())
    {
      std::fprintf(stderr, "volgrid delaunay: %s\n", read.message.c_str());
      return 1;
    }
  }
  else
  {
    if (args.randomCount > kMaxPoints)
    {
      std::fprintf(stderr,
                   "volgrid delaunay: --random %lld: at most %lld points are supported (that many would "
                   "make about %.2g tets); nothing was done\n",
                   args.randomCount, kMaxPoints,
                   volgrid::estimateDelaunaySize(static_cast<double>(args.randomCount)).tets);
      return 1;
    }
    if (refuseIfTooLarge(args, static_cast<double>(args.randomCount), "--random " + std::to_string(args.randomCount)))
      return 1;
    xyz = randomPoints(args.randomCount, args.seed);
  }
  const size_t n = xyz.size() / 3;
  if (!args.nodeFile.empty() &&
      refuseIfTooLarge(args, static_cast<double>(n), "'" + args.nodeFile + "' (" + std::to_string(n) + " points)"))
    return 1;

  volgrid::TetMesh mesh;
  std::vector<int32_t> inputToVertex;
  volgrid::DelaunayReport report;
  const volgrid::cli::Stopwatch watch;
  const volgrid::Status status =
    volgrid::buildDelaunay(xyz.data(), n, args.options, mesh, inputToVertex, nullptr, &report);
  const double seconds = watch.seconds();
  if (!status.ok())
  {
    std::fprintf(stderr, "volgrid delaunay: %s\n", status.message.c_str());
    return 1;
  }

  volgrid::MeshCheckReport check;
  double checkSeconds = 0;
  if (args.check)
  {
    const volgrid::cli::Stopwatch checkWatch;
    check = volgrid::checkMesh(mesh);
    checkSeconds = checkWatch.seconds();
  }

  if (args.check && !check.valid)
    std::fprintf(stderr, "volgrid delaunay: check failed: %s%s\n", check.summary().c_str(),
                 args.out.empty() ? "" : " (nothing written)");
  else if (!args.out.empty())
  {
    std::vector<int32_t> kept;
    for (size_t i = 0; i < n; ++i)
    {
      if (inputToVertex[i] == static_cast<int32_t>(i))
        kept.push_back(static_cast<int32_t>(i));
    }
    vtkNew<vtkUnstructuredGrid> grid;
    VolGridFillUnstructuredGrid(mesh, kept, grid);
    vtkNew<vtkIdTypeArray> inputIds;
    inputIds->SetName("InputPointId");
    inputIds->SetNumberOfValues(static_cast<vtkIdType>(kept.size()));
    for (size_t o = 0; o < kept.size(); ++o)
      inputIds->SetValue(static_cast<vtkIdType>(o), kept[o]);
    grid->GetPointData()->AddArray(inputIds);
    std::string error;
    if (!volgrid::cli::writeXmlDataSet(args.out, grid, error))
    {
      std::fprintf(stderr, "volgrid delaunay: %s\n", error.c_str());
      return 1;
    }
  }

  const long long tets = mesh.numFiniteTets();
  if (args.json)
  {
    std::printf("{\"input_points\": %zu, \"points\": %zu, \"duplicates\": %zu, \"tets\": %lld, "
                "\"seconds\": %.6f, \"tets_per_s\": %.0f, \"peak_rss_mb\": %.1f",
                n, report.numVertices, report.numDuplicates, tets, seconds, seconds > 0 ? tets / seconds : 0.0,
                volgrid::cli::peakResidentMiB());
    if (args.check)
    {
      std::printf(", \"valid\": %s, \"check_seconds\": %.6f, \"check\": %s", check.valid ? "true" : "false",
                  checkSeconds, volgrid::cli::jsonString(check.summary()).c_str());
    }
    std::printf("}\n");
  }
  else
  {
    std::printf("%zu input points, %zu distinct (%zu duplicates merged), %lld tetrahedra in %.3f s "
                "(%.0f tets/s), peak memory %.1f MiB\n",
                n, report.numVertices, report.numDuplicates, tets, seconds, seconds > 0 ? tets / seconds : 0.0,
                volgrid::cli::peakResidentMiB());
    if (args.check)
    {
      std::printf("check: %s (%.3f s)\n", check.summary().c_str(), checkSeconds);
    }
  }
  return args.check && !check.valid ? 1 : 0;
}
