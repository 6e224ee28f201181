// volgrid delaunay: exact Delaunay tetrahedralization of a point set (TetGen .node file or random points).
#include "CliSupport.h"
#include "Commands.h"
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

bool parseArguments(int argc, char** argv, Arguments& args)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> const char*
    {
      if (i + 1 >= argc)
      {
        std::fprintf(stderr, "volgrid delaunay: %s needs a value\n", name);
        return nullptr;
      }
      return argv[++i];
    };
    if (a == "--random")
    {
      const char* v = value("--random");
      if (!v || !volgrid::cli::parseLong("delaunay", "--random", v, args.randomCount))
        return false;
      if (args.randomCount < 0)
      {
        std::fprintf(stderr, "volgrid delaunay: --random needs a non-negative count\n");
        return false;
      }
    }
    else if (a == "--max-tets")
    {
      const char* v = value("--max-tets");
      if (!v || !volgrid::cli::parseMaxTets("delaunay", v, args.maxTets))
        return false;
    }
    else if (a == "--seed")
    {
      const char* v = value("--seed");
      if (!v || !volgrid::cli::parseLong("delaunay", "--seed", v, args.seed))
        return false;
    }
    else if (a == "--out")
    {
      const char* v = value("--out");
      if (!v)
        return false;
      args.out = v;
    }
    else if (a == "--location")
    {
      const char* v = value("--location");
      if (!v)
        return false;
      if (std::strcmp(v, "walk") == 0)
        args.options.location = volgrid::PointLocation::Walk;
      else if (std::strcmp(v, "grid") == 0)
        args.options.location = volgrid::PointLocation::BucketGrid;
      else
      {
        std::fprintf(stderr, "volgrid delaunay: --location is walk or grid, not '%s'\n", v);
        return false;
      }
    }
    else if (a == "--threads")
    {
      const char* v = value("--threads");
      long long t = 0;
      if (!v || !volgrid::cli::parseLong("delaunay", "--threads", v, t))
        return false;
      if (t < 0 || t > 1024)
      {
        std::fprintf(stderr, "volgrid delaunay: --threads is 0 (all cores) or 1..1024, not %lld\n", t);
        return false;
      }
      args.options.threads = static_cast<int>(t);
    }
    else if (a == "--check")
      args.check = true;
    else if (a == "--json")
      args.json = true;
    else if (a == "--no-sort")
      args.options.spatialSort = false;
    else if (a == "--help" || a == "-h")
    {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    else if (!a.empty() && a[0] == '-')
    {
      std::fprintf(stderr, "volgrid delaunay: unknown option '%s'\n%s", a.c_str(), kUsage);
      return false;
    }
    else if (args.nodeFile.empty())
      args.nodeFile = a;
    else
    {
      std::fprintf(stderr, "volgrid delaunay: more than one input ('%s')\n", a.c_str());
      return false;
    }
  }
  if (args.nodeFile.empty() == (args.randomCount < 0))
  {
    std::fprintf(stderr, "volgrid delaunay: give either an input .node file or --random N\n%s", kUsage);
    return false;
  }
  args.options.seed = static_cast<uint64_t>(args.seed) * 0x9E3779B97F4A7C15ull + 1;
  return true;
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
  if (!parseArguments(argc, argv, args))
  {
    return 2;
  }
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
