// volgrid mesh: boundary-conforming tetrahedral mesh of the volume enclosed by closed surfaces.
#include "AtomicStream.h"
#include "CliSupport.h"
#include "Commands.h"
#include "FlagParser.h"
#include "MeshExport.h"
#include "MeshLayers.h"
#include "OutputPaths.h"
#include "PointFiles.h"
#include "SizeLimit.h"
#include "SurfaceFile.h"
#include "VolGridConversion.h"
#include "XmlDataFiles.h"

#include "BoundaryCheck.h"
#include "CoordinateRange.h"
#include "Mesher.h"
#include "OptionValues.h"
#include "SizeEstimate.h"
#include "SizeRatio.h"
#include "SurfaceMesh.h"

#include "vtkByteSwap.h"
#include "vtkErrorCode.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridWriter.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>
using volgrid::cli::readPointsWithArray; // PointFiles.h

namespace
{
namespace option = volgrid::option;
const char* kHeader =
  "usage: volgrid mesh SURFACE OUT.vtu|OUT.vtk|OUT.msh|OUT.su2|... [--json] [--boundary OUT.vtp] [--check]\n"
  "                    [--regions even-odd|orientation|keep-all] [--no-steiner] [--threads N]\n"
  "                    [density and quality options]\n"
  "  Meshes the volume enclosed by the closed shells of SURFACE (.stl .obj .ply .off .vtp .vtk .mesh\n"
  "  .poly .smesh .msh) keeping its boundary exactly. OUT.vtu gets the tets (cell array Region; OUT.vtk:\n"
  "  the same, legacy binary VTK);\n"
  "  --boundary writes the boundary triangles with PatchId. --check verifies the mesh exactly and\n"
  "  exits 1 if it fails. Exit 1 also on bad input (the message names the defect and the first ids).\n"
  "Density (field points, paper 7.2; on by default):\n";
const char* kFooter = "Writes are atomic: OUT is replaced only when the whole file was written, never on failure.\n";

struct Arguments
{
  std::string surface;
  std::string out;
  std::string boundaryOut;
  bool json = false;
  bool check = false;
  std::string sizingFile, clusterFile, sizeArray;
  double clusterSize = 0;
  long long maxTets = 0;
  std::map<std::string, std::string> given; // option -> its text, to name it in messages
  volgrid::MesherOptions options;
  volgrid::LayerOptions layers; // --layers ... (MeshLayers.h)
};

// The flags of `volgrid mesh`, in the order of their usage lines.
void declareFlags(volgrid::cli::FlagParser& p, Arguments& args, long long& threads, std::string& regions)
{
  volgrid::ImprovementOptions& im = args.options.improvement;
  const auto set = [&im](const volgrid::OptionSpec& spec, double x) { volgrid::setOption(im, spec, x); };
  p.add("--json", args.json, true);
  p.add("--check", args.check, true);
  p.add("--no-steiner", args.options.allowSteinerPoints, false);
  p.add("--boundary", args.boundaryOut);
  p.add("--regions", regions).accept = [&p, &args](const char* v)
  {
    const char* names[] = { "even-odd", "orientation", "keep-all" };
    const volgrid::RegionRule rules[] = { volgrid::RegionRule::EvenOdd, volgrid::RegionRule::Orientation,
                                          volgrid::RegionRule::KeepAll };
    for (int k = 0; k < 3; ++k)
      if (std::strcmp(v, names[k]) == 0)
      {
        args.options.regionRule = rules[k];
        return true;
      }
    return p.fail(std::string("--regions is even-odd, orientation or keep-all, not '") + v + "'");
  };
  for (const auto& row : { std::make_pair(&option::alpha, "A"), std::make_pair(&option::beta, "B"),
                           std::make_pair(&option::sizeScale, "S"), std::make_pair(&option::gradation, "G"),
                           std::make_pair(&option::maxEdge, "L"), std::make_pair(&option::maxVolume, "V") })
    p.add(*row.first, row.second, set);
  p.add("--no-field-points", im.fieldPoints, false,
        "  --no-field-points    boundary points (and recovery's interior points) only\n"
        "Clustering and sizing:\n");
  p.add("--sizing", args.sizingFile,
        "  --sizing FILE        a data set (.vtu .vtp .vtk, or text 'x y z size' lines) whose point array\n"
        "                       --size-array NAME gives target edge lengths, interpolated in space\n");
  p.add("--cluster", args.clusterFile,
        "  --cluster FILE       points (any data set, or text 'x y z [size]' lines) inserted into the volume; the\n"
        "                       point array --size-array NAME (if present) or --cluster-size H densifies around "
        "them\n");
  p.add("--size-array", args.sizeArray);
  p.add("--cluster-size", args.clusterSize).accept = [&p, &args](const char* v)
  { return args.clusterSize > 0 || p.fail(std::string("--cluster-size is out of range: ") + v + " (see --help)"); };
  p.add("--quality", im.optimize, true,
        "Quality (optimisation: flips, edge removal, smoothing; on by default):\n"
        "  --quality            optimise (default)                    --no-optimize    do not\n");
  p.add("--no-optimize", im.optimize, false);
  p.add(option::targetAngle, "DEG", set);
  p.add(option::passes, "N", set);
  p.add("--no-smoothing", im.optimization.smoothing, false, "  --no-smoothing       flips only\n");
  p.add("--orthogonality-first", im.orthogonalityFirst, true,
        "  --orthogonality-first  for finite-volume solvers: the quality stage adds no severely non-orthogonal\n"
        "                       face (checkMesh: > 70 deg) and no tet under the target where it edits, except\n"
        "                       to fix tets under 2 deg; a quarter to a half of the severe faces, a smaller\n"
        "                       worst dihedral angle\n");
  p.add("--max-tets", args.maxTets,
        "Limits:\n"
        "  --max-tets N         refuse before any work when the mesh is estimated to exceed N tets (default:\n"
        "                       what the available memory holds)\n")
    .accept = [&args](const char* v) { return volgrid::cli::parseMaxTets("mesh", v, args.maxTets); };
  p.add("--threads", threads, "  --threads N          0 (default) = all cores; the mesh is byte-identical for any N\n")
    .accept = [&p, &threads](const char* v)
  {
    return (threads >= 0 && threads <= 1024) ||
      p.fail(std::string("--threads is out of range: ") + v + " (see --help)");
  };
}

// 2 (after the message) when the arguments are bad, 0 after --help, -1 to go on meshing.
int parseArguments(int argc, char** argv, Arguments& args)
{
  long long threads = args.options.threads;
  std::string regions;
  volgrid::cli::FlagParser p("mesh", kHeader, kFooter);
  declareFlags(p, args, threads, regions);
  p.moreHelp = volgrid::cli::kLayerUsage + volgrid::cli::kExportUsage;
  p.before = [&args](int n, char** v, int& i) { return volgrid::cli::parseLayerOption(n, v, i, args.layers); };
  std::vector<std::string> positional;
  if (const int code = p.scan(argc, argv, positional); code >= 0)
    return code;
  args.options.threads = static_cast<int>(threads);
  args.given = p.given();
  if (!args.layers.enabled() &&
      (args.layers.firstHeight != 0 || args.layers.yPlus != 0 || args.layers.thickness != 0 ||
       !args.layers.patchNames.empty() || !args.layers.patchIds.empty() || args.layers.splitPrisms ||
       args.layers.keepWallTriangles))
  {
    p.fail("--first-height, --y-plus, --layer-thickness, --layer-patches, --split-prisms and --keep-wall-triangles "
           "need --layers N");
    return 2;
  }
  if (positional.size() != 2)
  {
    p.fail("expected SURFACE and OUT.vtu", true);
    return 2;
  }
  args.surface = positional[0];
  args.out = positional[1];
  volgrid::ImprovementOptions& im = args.options.improvement;
  if (!args.sizingFile.empty() &&
      !readPointsWithArray("mesh", args.sizingFile, args.sizeArray, true, im.sizingPoints, im.sizingValues))
    return 2;
  if (!args.clusterFile.empty())
  {
    if (!readPointsWithArray("mesh", args.clusterFile, args.sizeArray, false, im.clusterPoints, im.clusterSizes))
      return 2;
    if (args.clusterSize > 0)
      im.clusterSizes.assign(im.clusterPoints.size() / 3, args.clusterSize);
  }
  return -1;
}

// vtkDataWriter asks OpenVTKFile() for its stream and deletes it when done: a stream over the atomic
// temporary (AtomicStream.h), never the target itself.
class LegacyStreamWriter : public vtkUnstructuredGridWriter
{
public:
  static LegacyStreamWriter* New()
  {
    auto* writer = new LegacyStreamWriter;
    writer->InitializeObjectBase();
    return writer;
  }
  std::ostream* Target = nullptr;
  ostream* OpenVTKFile() override { return new std::ostream(Target->rdbuf()); }

protected:
  // vtkUnstructuredGridWriter::WriteData as in VTK 9.2, but the cells written as they are stored:
  // VTK's own copies every cell into a new 64-bit cell array first (WriteCellsAndFaces, for polyhedra),
  // which took 0.23 s of the 0.34 s that writing a 1M-tet mesh took; a tet mesh has no polyhedra.
  void WriteData() override
  {
    vtkUnstructuredGrid* input = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
    if (!input || input->GetFaces())
      return vtkUnstructuredGridWriter::WriteData();
    ostream* fp = this->OpenVTKFile();
    bool ok = fp && this->WriteHeader(fp);
    if (ok)
    {
      *fp << "DATASET UNSTRUCTURED_GRID\n";
      ok = this->WriteDataSetData(fp, input) && this->WritePoints(fp, input->GetPoints()) &&
        this->WriteCells(fp, input->GetCells(), "CELLS");
    }
    if (ok && input->GetCells())
    {
      const vtkIdType ncells = input->GetNumberOfCells();
      std::vector<int> types(static_cast<size_t>(ncells));
      for (vtkIdType c = 0; c < ncells; ++c)
        types[static_cast<size_t>(c)] = input->GetCellType(c);
      *fp << "CELL_TYPES " << ncells << "\n";
      vtkByteSwap::SwapWrite4BERange(types.data(), ncells, fp);
      *fp << "\n";
    }
    ok = ok && this->WriteCellData(fp, input) && this->WritePointData(fp, input);
    if (!ok)
      this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
    if (fp)
      this->CloseVTKFile(fp);
  }
};

// OUT.vtk: the legacy binary format (for tools that read only legacy VTK), written atomically.
bool writeLegacy(const std::string& path, vtkUnstructuredGrid* data)
{
  auto write = [data](std::ostream& stream, const std::string& temporary, std::string& writerError)
  {
    vtkSmartPointer<LegacyStreamWriter> writer = vtkSmartPointer<LegacyStreamWriter>::New();
    writer->Target = &stream;
    writer->SetFileName(temporary.c_str()); // what VTK's own messages name
    writer->SetInputData(data);
    writer->SetFileTypeToBinary();
    const bool ok = writer->Write() == 1 && writer->GetErrorCode() == 0;
    writerError = "VTK could not encode the mesh";
    return ok;
  };
  std::string error;
  if (!volgrid::cli::writeStreamAtomically(path, write, error))
  {
    std::fprintf(stderr, "volgrid mesh: %s\n", error.c_str());
    return false;
  }
  return true;
}

// The option (with its value) that drives the estimate, as the user typed it.
std::string sizeCause(const Arguments& args, volgrid::SizeDriver driver)
{
  auto named = [&](const char* option)
  {
    const auto it = args.given.find(option);
    return std::string(option) + " " + (it == args.given.end() ? std::string("(default)") : it->second);
  };
  switch (driver)
  {
    case volgrid::SizeDriver::MaxEdge:
      return named("--max-edge");
    case volgrid::SizeDriver::MaxVolume:
      return named("--max-volume");
    case volgrid::SizeDriver::SizeScale:
      return named("--size-scale");
    case volgrid::SizeDriver::Alpha:
      return named("--alpha");
    default:
      return "the surface's point spacing of '" + args.surface + "'";
  }
}

bool write(const std::string& path, vtkDataSet* data)
{
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".vtk") == 0 && vtkUnstructuredGrid::SafeDownCast(data))
    return writeLegacy(path, vtkUnstructuredGrid::SafeDownCast(data));
  std::string error;
  if (!volgrid::cli::writeXmlDataSet(path, data, error))
  {
    std::fprintf(stderr, "volgrid mesh: %s\n", error.c_str());
    return false;
  }
  return true;
}

// What the report says of the output mesh itself: its dihedral angles (the mesher's own summary covers only
// its improvement stage) and the size ratio between face-neighbouring tets (SizeRatio.h) against the
// gradation option. Taken before writing, so that the mesher's arrays can go before the writer runs.
struct OutputSummary
{
  volgrid::DihedralSummary dihedral;
  volgrid::SizeRatioSummary ratio;
};

// sharedFaces: the tet pairs of the shared faces, from the boundary check's face matching (released here).
OutputSummary summarizeOutput(const Arguments& args, const volgrid::MesherResult& result,
                              std::vector<std::pair<int32_t, int32_t>>& sharedFaces)
{
  OutputSummary summary;
  // The quality stage ends with the same summary of the same tets (counts, extremes: any order gives the
  // same): computed again only when the counts differ.
  const volgrid::DihedralSummary& last = result.stats.improvement.after;
  const int64_t tets = static_cast<int64_t>(result.tets.size() / 4);
  summary.dihedral = last.tets == tets
    ? last
    : volgrid::summarizeDihedrals(result.points.data(), result.tets.data(), nullptr, tets, args.options.threads);
  summary.ratio =
    volgrid::summarizeSizeRatios(result.points.data(), result.tets.data(), result.tets.size() / 4, sharedFaces,
                                 args.options.improvement.sizing.gradation, args.options.threads);
  std::vector<std::pair<int32_t, int32_t>>().swap(sharedFaces);
  return summary;
}

// The mesher's arrays, released once the output holds what it needs of them: at millions of tets the
// writer's own buffers then take their place instead of adding to them. Only the statistics stay, for the
// report.
void releaseMeshArrays(volgrid::MesherResult& result)
{
  volgrid::MesherResult statisticsOnly;
  statisticsOnly.stats = result.stats;
  result = std::move(statisticsOnly);
}

// OUT (VTK data set or solver format) and --boundary's OUT.vtp. The mesher's arrays are gone afterwards (its
// statistics stay): for VTK output they are released once the VTK data sets hold their copies, for a
// solver format they move into the solver mesh. Either way the writer's buffers take their place at the
// peak instead of adding to them. False (message printed) when a write fails.
bool writeOutputs(const Arguments& args, volgrid::MeshFormat format, bool vtkOutput,
                  const volgrid::cli::ExportRequest& request, volgrid::MesherResult& result,
                  volgrid::SolverMesh solverMesh)
{
  vtkNew<vtkUnstructuredGrid> volumeGrid;
  vtkNew<vtkPolyData> boundarySurface;
  vtkUnstructuredGrid* const volume = vtkOutput ? volumeGrid.Get() : nullptr;
  vtkPolyData* const boundary = args.boundaryOut.empty() ? nullptr : boundarySurface.Get();
  if (volume || boundary)
  {
    VolGridFillFromMesherResult(result, volume, boundary);
    VolGridSetPatchAndRegionNames(result, solverMesh.patchNames, solverMesh.regionNames, volume, boundary);
  }
  if (!vtkOutput)
    volgrid::cli::moveGeometry(result, solverMesh);
  releaseMeshArrays(result);
  const bool written = vtkOutput
    ? write(args.out, volume)
    : volgrid::cli::writeSolverOutput("mesh", args.out, format, std::move(solverMesh), request, args.json);
  return written && (!boundary || write(args.boundaryOut, boundary));
}

// The run's summary on stdout (--json: one JSON line): counts, Steiner points, the output's dihedral
// angles and size ratios, the boundary and volume check, the stage times, the longest wait an abort would
// have had (AbortGapWatch).
void printReport(const Arguments& args, const volgrid::MesherStatistics& s, const OutputSummary& output,
                 const volgrid::BoundaryCheckReport& boundary, bool boundaryPreserved, double seconds,
                 double longestAbortGap)
{
  const volgrid::DihedralSummary& dihedral = output.dihedral;
  const volgrid::SizeRatioSummary& ratio = output.ratio;
  if (args.json)
  {
    const auto json = [](double v, const char* format = "%.17g") { return volgrid::cli::jsonNumber(v, format); };
    std::printf(
      "{\"input\": %s, \"input_points\": %lld, \"merged_points\": %lld, \"input_triangles\": %lld, "
      "\"points\": %lld, \"tets\": %lld, \"regions\": %lld, \"missing_edges\": %lld, "
      "\"missing_facets\": %lld, \"flips\": %lld, \"recovery_attempts\": %d, \"steiner_interior\": %lld, "
      "\"steiner_boundary\": %lld, \"boundary_preserved\": %s, \"volume\": %s, "
      "\"enclosed_volume\": %s, \"volume_relative_error\": %s, \"field_points\": %lld, "
      "\"cluster_points\": %lld, \"min_dihedral\": %s, \"max_dihedral\": %s, "
      "\"share_below_10\": %s, \"boundary_forced_below_10\": %lld, \"forced_tets\": %lld, "
      "\"interior_outside_15_165\": %lld, \"interior_outside_before_polish\": %lld, "
      "\"size_ratio_p99\": %.4f, \"size_ratio_max\": %.4f, \"size_ratio_faces_above_gradation\": %lld, "
      "\"nonortho_severe_faces\": %lld, \"nonortho_severe_before_moves\": %lld, \"nonortho_moves\": %lld, "
      "\"max_edge_floor\": %s, \"seconds_improvement\": %.6f, \"seconds_stages\": {\"check\": %.6f, \"delaunay\": "
      "%.6f, "
      "\"recovery\": %.6f, \"exterior\": %.6f, \"steiner\": %.6f, \"sizing\": %.6f, "
      "\"field_points\": %.6f, \"optimization\": %.6f, \"interior_polish\": %.6f}, "
      "\"longest_abort_gap_seconds\": %.3f, \"seconds\": %.6f, "
      "\"peak_rss_mb\": %.1f}\n",
      volgrid::cli::jsonString(args.surface).c_str(), static_cast<long long>(s.inputPoints),
      static_cast<long long>(s.mergedPoints), static_cast<long long>(s.inputTriangles),
      static_cast<long long>(s.points), static_cast<long long>(s.tets), static_cast<long long>(s.regions),
      static_cast<long long>(s.missingEdges), static_cast<long long>(s.missingFacets), static_cast<long long>(s.flips),
      s.recoveryAttempts, static_cast<long long>(s.steinerInterior), static_cast<long long>(s.steinerBoundary),
      boundaryPreserved ? "true" : "false", json(boundary.tetVolume).c_str(), json(s.enclosedVolume).c_str(),
      json(boundary.relativeVolumeError, "%.3g").c_str(), static_cast<long long>(s.improvement.fieldPoints),
      static_cast<long long>(s.improvement.clusterPoints), json(dihedral.minDihedral, "%.4f").c_str(),
      json(dihedral.maxDihedral, "%.4f").c_str(), json(dihedral.shareBelow10(), "%.6g").c_str(),
      static_cast<long long>(s.improvement.boundaryForcedBelow10), static_cast<long long>(s.forcedTets),
      static_cast<long long>(s.improvement.interiorOutside),
      static_cast<long long>(s.improvement.interiorOutsideBeforePolish), ratio.p99,
      ratio.max, static_cast<long long>(ratio.aboveThreshold), static_cast<long long>(s.improvement.severeFacesAfter),
      static_cast<long long>(s.improvement.severeFacesBefore), static_cast<long long>(s.improvement.orthogonalityMoves),
      json(s.improvement.coarseBoundaryFloor, "%.6g").c_str(), s.secondsImprovement, s.secondsCheck, s.secondsDelaunay,
      s.secondsRecovery, s.secondsExterior, s.secondsSteiner, s.improvement.secondsSizing,
      s.improvement.secondsFieldPoints, s.improvement.secondsOptimization, s.improvement.secondsPolish, longestAbortGap, seconds,
      volgrid::cli::peakResidentMiB());
  }
  else
  {
    std::printf("%s: %lld points, %lld triangles -> %lld tets on %lld points (%lld interior Steiner "
                "points, %lld on the boundary) in %.3f s\n",
                args.surface.c_str(), static_cast<long long>(s.inputPoints), static_cast<long long>(s.inputTriangles),
                static_cast<long long>(s.tets), static_cast<long long>(s.points),
                static_cast<long long>(s.steinerInterior), static_cast<long long>(s.steinerBoundary), seconds);
    std::printf("%lld field points, %lld cluster points; dihedral angles %.2f..%.2f deg, %.3g%% of the tets "
                "under 10 deg\n",
                static_cast<long long>(s.improvement.fieldPoints), static_cast<long long>(s.improvement.clusterPoints),
                dihedral.minDihedral, dihedral.maxDihedral, 100.0 * dihedral.shareBelow10());
    std::printf("size ratio between face-neighbouring tets (mean edge length): 99th percentile %.3f, max %.3f; "
                "%lld of %lld faces above the gradation %.3g\n",
                ratio.p99, ratio.max, static_cast<long long>(ratio.aboveThreshold), static_cast<long long>(ratio.faces),
                args.options.improvement.sizing.gradation);
    if (s.forcedTets > 0)
      std::printf("%lld tets forced by the input surface (four boundary vertices, a dihedral angle under 10 or "
                  "over 170 deg: cell array Forced)\n",
                  static_cast<long long>(s.forcedTets));
    std::printf("boundary %s; volume %.12g (enclosed %.12g, relative error %.2g)\n",
                boundaryPreserved ? "preserved exactly" : "NOT preserved", boundary.tetVolume, s.enclosedVolume,
                boundary.relativeVolumeError);
  }
}
} // namespace

int runMeshCommand(int argc, char** argv)
{
  volgrid::cli::ExportRequest exportRequest; // --format, --patch, --patch-type (MeshExport.h)
  if (!volgrid::cli::takeExportOptions("mesh", argc, argv, exportRequest))
    return 2;
  Arguments args;
  if (const int code = parseArguments(argc, argv, args); code >= 0)
    return code;
  volgrid::MeshFormat format = volgrid::MeshFormat::Unknown;
  bool vtkOutput = true;
  if (!volgrid::cli::chooseFormat("mesh", args.out, exportRequest, format, vtkOutput))
    return 2;
  const std::vector<std::string> inputs = { args.surface, args.sizingFile, args.clusterFile };
  // chooseFormat accepted OUT's format; an OpenFOAM case is a directory, checked by its writer.
  const std::vector<std::string> outExtensions = vtkOutput
    ? std::vector<std::string>{ "vtu", "vtk" }
    : std::vector<std::string>{ volgrid::surfaceFileExtension(args.out) };
  if (format != volgrid::MeshFormat::OpenFOAM)
    if (const int code = volgrid::cli::checkOutputPath("mesh", "OUT", args.out, outExtensions, inputs))
      return code;
  if (!args.boundaryOut.empty())
  {
    std::vector<std::string> notThese = inputs;
    notThese.push_back(args.out);
    if (const int code = volgrid::cli::checkOutputPath("mesh", "--boundary", args.boundaryOut, { "vtp" }, notThese))
      return code;
  }

  volgrid::SurfaceMesh surface;
  std::string readInfo;
  // Keep the file's own numbering: the mesher merges coincident points itself and reports them.
  const volgrid::Status read = volgrid::readAnySurface(args.surface, surface, readInfo, false);
  if (!read.ok())
  {
    std::fprintf(stderr, "volgrid mesh: %s\n", read.message.c_str());
    return 1;
  }

  const volgrid::Status range = volgrid::checkCoordinateRange(surface, args.surface);
  if (!range.ok())
  {
    std::fprintf(stderr, "volgrid mesh: %s\n", range.message.c_str());
    return 1;
  }
  const volgrid::SizeEstimate estimate = volgrid::estimateMeshSize(surface, args.options.improvement);
  if (volgrid::cli::refuseIfTooLarge("mesh", estimate, args.maxTets, sizeCause(args, estimate.driver)))
    return 1;

  args.options.verify = args.check;
  if (args.layers.enabled()) // boundary layers: prisms + tets, written by MeshLayers.cxx
  {
    if (!args.boundaryOut.empty())
    {
      std::fprintf(stderr, "volgrid mesh: --boundary is not supported together with --layers yet\n");
      return 2;
    }
    return volgrid::cli::runLayeredMesh(surface, args.surface, args.out, format, vtkOutput, exportRequest, args.options,
                                        args.layers, args.json);
  }
  volgrid::MesherResult result;
  const volgrid::cli::Stopwatch watch;
  volgrid::cli::AbortGapWatch abortGaps;
  const volgrid::Status status = volgrid::meshSurface(surface, args.options, result, &abortGaps);
  abortGaps.finish();
  const double seconds = watch.seconds();
  if (!status.ok())
  {
    std::fprintf(stderr, "volgrid mesh: %s: %s\n", args.surface.c_str(), status.message.c_str());
    return 1;
  }
  for (const std::string& warning : result.warnings)
    std::fprintf(stderr, "volgrid mesh: warning: %s\n", warning.c_str());

  // Independent of the mesher's own verification: the boundary faces of the tets against the input
  // triangles (in output point ids), and the volume against the enclosed volume.
  std::vector<int32_t> inputTriangles(surface.triangles.size());
  for (size_t k = 0; k < surface.triangles.size(); ++k)
    inputTriangles[k] = result.inputToOutputPoint[surface.triangles[k]];
  // Its face matching also gives the neighbours that the size ratios need.
  std::vector<std::pair<int32_t, int32_t>> sharedFaces;
  const volgrid::BoundaryCheckReport boundary =
    volgrid::checkBoundaryConformity(result.points, result.numInputPoints, result.tets, inputTriangles,
                                     result.stats.enclosedVolume, &sharedFaces, args.options.threads);
  const bool boundaryPreserved = boundary.meshValid() && boundary.boundaryEqualsInput();
  const OutputSummary output = summarizeOutput(args, result, sharedFaces);

  volgrid::SolverMesh solverMesh; // named patches; --patch applied to result.boundaryPatch too
  if (!volgrid::cli::solverMeshFromResult("mesh", exportRequest, surface, result, solverMesh))
    return 1;
  // A failed --check leaves the earlier output files as they were.
  const bool checkFailed = args.check && !(boundaryPreserved && boundary.relativeVolumeError <= 1e-9);
  if (!checkFailed && !writeOutputs(args, format, vtkOutput, exportRequest, result, std::move(solverMesh)))
    return 1;

  printReport(args, result.stats, output, boundary, boundaryPreserved, seconds, abortGaps.longestGapSeconds());
  if (checkFailed)
  {
    std::fprintf(stderr, "volgrid mesh: check failed (nothing written): %s\n", boundary.summary().c_str());
    return 1;
  }
  return 0;
}
