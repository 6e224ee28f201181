// volgrid prep IN... OUT [--enclosure SHAPE] [--enclosure-scale S] [--edge-length L] [--merge-tolerance T]
//                        [--exact] [--fill-holes N] [--no-orient] [--axis x|y|z] [--center X,Y,Z]
//                        [--dimensions A[,B[,C]]] [--no-intersections] [--json]
// Runs vtkVolGridSurfacePrep on the input surfaces (each file a part) and writes the clean surface with its
// PatchId and diagnostic arrays. Exit code: 0 when the output is meshable, 1 when defects remain (the
// output is still written) or a file cannot be read or written, 2 for bad arguments.
#include "CliSupport.h"
#include "Commands.h"
#include "FlagParser.h"
#include "OutputPaths.h"
#include "SurfaceFile.h"

#include "VolGridSurfaceConversion.h"
#include "vtkVolGridSurfacePrep.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace
{
const char* kHeader =
  "usage: volgrid prep IN... OUT.{vtp,vtk,stl,off} [options]\n"
  "  Merges the input surfaces (each a part: PatchId), repairs them (weld, remove zero-area and duplicate\n"
  "  triangles, stitch, fill holes, orient), optionally adds an enclosure, and reports what is left.\n";
const char* kFooter =
  "  Exit 0: the output is meshable; 1: defects remain (output written) or I/O error; 2: bad arguments.\n";

// "A", "A,B" or "A,B,C" (missing values repeat the last one given).
bool parseTriple(const char* text, double out[3])
{
  char* end = nullptr;
  const char* p = text;
  int k = 0;
  for (; k < 3; ++k)
  {
    out[k] = std::strtod(p, &end);
    if (end == p || !std::isfinite(out[k]))
      return false;
    p = end;
    if (*p == '\0')
      break;
    if (*p != ',' || k == 2)
      return false;
    ++p;
  }
  for (int j = k + 1; j < 3; ++j)
    out[j] = out[k];
  return true;
}

long long count(vtkFieldData* fd, const char* name)
{
  vtkDataArray* a = fd->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? static_cast<long long>(a->GetComponent(0, 0)) : -1;
}

const char* kJsonCounts[][2] = {
  { "parts", "Parts" },
  { "input_points", "InputPoints" },
  { "input_triangles", "InputTriangles" },
  { "input_boundary_edges", "InputBoundaryEdges" },
  { "input_boundary_loops", "InputBoundaryLoops" },
  { "input_non_manifold_edges", "InputNonManifoldEdges" },
  { "input_inconsistent_edges", "InputInconsistentEdges" },
  { "input_degenerate_triangles", "InputDegenerateTriangles" },
  { "input_duplicate_triangles", "InputDuplicateTriangles" },
  { "input_shells", "InputShells" },
  { "welded_points", "WeldedPoints" },
  { "removed_degenerate", "RemovedDegenerate" },
  { "removed_duplicates", "RemovedDuplicates" },
  { "stitched_points", "StitchedPoints" },
  { "holes_filled", "LoopsFilled" },
  { "holes_left_open", "LoopsLeftOpen" },
  { "triangles_added", "TrianglesAdded" },
  { "triangles_flipped", "TrianglesFlipped" },
  { "shells_flipped", "ShellsFlipped" },
  { "points", "Points" },
  { "triangles", "Triangles" },
  { "shells", "Shells" },
  { "closed_shells", "ClosedShells" },
  { "boundary_edges", "BoundaryEdges" },
  { "boundary_loops", "BoundaryLoops" },
  { "non_manifold_edges", "NonManifoldEdges" },
  { "non_manifold_vertices", "NonManifoldVertices" },
  { "inconsistent_edges", "InconsistentEdges" },
  { "degenerate_triangles", "DegenerateTriangles" },
  { "duplicate_triangles", "DuplicateTriangles" },
  { "self_intersecting_pairs", "SelfIntersectingPairs" },
  { "shell_intersecting_pairs", "ShellIntersectingPairs" },
  { "misoriented_shells", "MisorientedShells" },
  { "enclosure_patch_id", "EnclosurePatchId" },
};
} // namespace

namespace
{
// "dir/wing.stl.gz" -> "wing": a patch name (an OpenFOAM word: other characters become '_').
std::string fileStem(const std::string& path)
{
  std::string stem = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  stem = stem.substr(0, stem.find('.'));
  for (char& c : stem)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
      c = '_';
  return stem.empty() ? "surface" : stem;
}

// One patch per input file unless the file has its own (STL solids, refs, groups): a file with a single
// unnamed patch is named after the file, several unnamed ones "<stem>_<id>".
void nameFilePatches(const std::string& file, volgrid::SurfaceMesh& mesh)
{
  if (!mesh.hasPatchIds())
    mesh.patchIds.assign(static_cast<size_t>(mesh.numberOfTriangles()), 0);
  const std::set<int32_t> ids(mesh.patchIds.begin(), mesh.patchIds.end());
  for (int32_t id : ids)
    if (!mesh.patchNames.count(id))
      mesh.patchNames[id] = ids.size() == 1 ? fileStem(file) : fileStem(file) + "_" + std::to_string(id);
}
} // namespace

namespace
{
struct Arguments
{
  std::vector<std::string> files; // the input surfaces
  std::string out;
  bool json = false, exact = false, orient = true, intersections = true;
  std::string enclosure, axis, center, dimensions;
  double scale = 0, edgeLength = 0, mergeTolerance = 0;
  long long fillHoles = 0;
};

const char* kBadEnclosure = "--enclosure expects box, sphere, cylinder, hemisphere or ellipsoid";
const char* kBadAxis = "--axis expects x, y or z";
const char* kBadTriple = " expects one to three numbers X[,Y[,Z]]";

// A real flag of the filter's in [lo, hi]; outside, "NAME PROBLEM" and
// the usage; inside, `set` hands it to the filter.
void addRanged(volgrid::cli::FlagParser& p, const char* name, double& value, double lo, double hi, const char* problem,
               const char* help, std::function<void(double)> set)
{
  p.add(name, value, help).accept = [&p, &value, lo, hi, name, problem, set](const char*)
  {
    if (value < lo || value > hi)
      return p.fail(std::string(name) + " " + problem, true);
    set(value);
    return true;
  };
}

// The enclosure flags of `volgrid prep`, in the order of their usage lines; each check sets the filter.
void declareEnclosureFlags(volgrid::cli::FlagParser& p, Arguments& args, vtkVolGridSurfacePrep* prep)
{
  p.add("--enclosure", args.enclosure,
        "  --enclosure box|sphere|cylinder|hemisphere|ellipsoid   far-field enclosure around the input\n")
    .accept = [&p, prep](const char* v)
  {
    const char* names[] = { "none", "box", "sphere", "cylinder", "hemisphere", "ellipsoid" };
    for (int k = 0; k < 6; ++k)
      if (std::strcmp(v, names[k]) == 0)
      {
        prep->SetEnclosure(k);
        return true;
      }
    return p.fail(kBadEnclosure, true);
  };
  addRanged(p, "--enclosure-scale", args.scale, 1.0, 1.0e6, "must be in [1, 1e6]",
            "  --enclosure-scale S   enclosure size as a factor of the input's bounding box (>= 1, default 10)\n",
            [prep](double x) { prep->SetEnclosureScale(x); });
  p.add("--center", args.center,
        "  --center X,Y,Z --dimensions A[,B[,C]]   explicit enclosure (then no input is needed): box edges;\n"
        "                        sphere, hemisphere radius; cylinder radius, height; ellipsoid semi-axes\n")
    .accept = [&p, prep](const char* v)
  {
    double t[3];
    if (!parseTriple(v, t))
      return p.fail(std::string("--center") + kBadTriple, true);
    prep->SetEnclosureCenter(t);
    return true;
  };
  p.add("--dimensions", args.dimensions).accept = [&p, prep](const char* v)
  {
    double t[3];
    if (!parseTriple(v, t))
      return p.fail(std::string("--dimensions") + kBadTriple, true);
    if (t[0] <= 0 || t[1] < 0 || t[2] < 0)
      return p.fail("--dimensions must be positive", true);
    prep->SetEnclosureDimensions(t);
    return true;
  };
  p.add("--axis", args.axis, "  --axis x|y|z          cylinder / hemisphere axis (default z)\n").accept =
    [&p, prep](const char* v)
  {
    if (std::strcmp(v, "x") != 0 && std::strcmp(v, "y") != 0 && std::strcmp(v, "z") != 0)
      return p.fail(kBadAxis, true);
    prep->SetEnclosureAxis(v[0] - 'x');
    return true;
  };
  addRanged(p, "--edge-length", args.edgeLength, 0.0, std::numeric_limits<double>::infinity(), "must be >= 0",
            "  --edge-length L       target edge length of the enclosure (default 0: 1/16 of its size)\n",
            [prep](double x) { prep->SetEnclosureEdgeLength(x); });
}

// The repair flags, after the enclosure's.
void declareRepairFlags(volgrid::cli::FlagParser& p, Arguments& args, vtkVolGridSurfacePrep* prep)
{
  addRanged(p, "--merge-tolerance", args.mergeTolerance, 0.0, 0.01, "must be in [0, 0.01]",
            "  --merge-tolerance T   weld points on open edges closer than T * bounding-box diagonal (default\n"
            "                        1e-6; 0: exactly coincident points only, like --exact)\n",
            [prep](double x) { prep->SetMergeTolerance(x); });
  p.add("--exact", args.exact, true, "  --exact               merge exactly coincident points only\n");
  p.add("--fill-holes", args.fillHoles,
        "  --fill-holes N        fill holes of at most N edges (default 200; 0: leave holes open)\n")
    .accept = [&p, &args, prep](const char*)
  {
    if (args.fillHoles < 0 || args.fillHoles > 1000000)
      return p.fail("--fill-holes must be in [0, 1000000]", true);
    prep->SetFillHoles(args.fillHoles >= 3);
    if (args.fillHoles >= 3)
      prep->SetMaxHoleEdges(static_cast<int>(args.fillHoles));
    return true;
  };
  p.add("--no-orient", args.orient, false, "  --no-orient           keep the triangles' orientation\n");
  p.add("--no-intersections", args.intersections, false, "  --no-intersections    skip the self-intersection test\n");
  p.add("--json", args.json, true, "  --json                one JSON line of counts on stdout\n");
}

// 2 (after the message) when the arguments are bad, 0 after --help, -1 to go on. An enclosure alone
// (--center and --dimensions) needs no input.
int parseArguments(int argc, char** argv, Arguments& args, vtkVolGridSurfacePrep* prep)
{
  volgrid::cli::FlagParser p("prep", kHeader, kFooter);
  declareEnclosureFlags(p, args, prep);
  declareRepairFlags(p, args, prep);
  if (const int code = p.scan(argc, argv, args.files); code >= 0)
    return code;
  if (args.exact)
    prep->ExactMergeOnlyOn();
  if (!args.orient)
    prep->OrientShellsOff();
  if (!args.intersections)
    prep->CheckIntersectionsOff();
  if (args.files.empty())
  {
    p.fail("missing OUT", true);
    return 2;
  }
  args.out = args.files.back();
  args.files.pop_back();
  if (const int code =
        volgrid::cli::checkOutputPath("prep", "OUT", args.out, { "vtp", "vtk", "stl", "off" }, args.files))
    return code;
  const bool haveCenter = p.given().count("--center") > 0, haveDimensions = p.given().count("--dimensions") > 0;
  if (haveCenter != haveDimensions)
  {
    p.fail("--center and --dimensions go together", true);
    return 2;
  }
  if (haveCenter)
    prep->ExplicitEnclosureOn();
  if (args.files.empty() && (!haveCenter || prep->GetEnclosure() == vtkVolGridSurfacePrep::ENCLOSURE_NONE))
  {
    p.fail("no input surface (without input, give --enclosure with --center and --dimensions)", true);
    return 2;
  }
  return -1;
}
} // namespace

int runPrepCommand(int argc, char** argv)
{
  vtkNew<vtkVolGridSurfacePrep> prep;
  Arguments args;
  if (const int code = parseArguments(argc, argv, args, prep); code >= 0)
    return code;
  volgrid::cli::Stopwatch clock;
  for (const std::string& file : args.files)
  {
    volgrid::SurfaceMesh mesh;
    std::string info;
    const volgrid::Status status = volgrid::readAnySurface(file, mesh, info);
    if (!status.ok())
    {
      std::fprintf(stderr, "volgrid prep: %s\n", status.message.c_str());
      return 1;
    }
    if (!args.json)
      std::printf("read %s: %s\n", file.c_str(), info.c_str());
    nameFilePatches(file, mesh);
    vtkNew<vtkPolyData> part;
    VolGridSurfaceMeshToPolyData(mesh, part, "PatchId");
    prep->AddInputData(part);
  }
  prep->Update();
  vtkPolyData* result = prep->GetOutput();
  if (result->GetNumberOfCells() == 0)
  {
    std::fprintf(stderr, "volgrid prep: the output is empty (see the messages above)\n");
    return 1;
  }
  std::string error;
  if (!volgrid::writeSurfaceFile(args.out, result, error))
  {
    std::fprintf(stderr, "volgrid prep: %s\n", error.c_str());
    return 1;
  }
  vtkFieldData* fd = result->GetFieldData();
  const bool meshable = prep->GetMeshable();
  if (args.json)
  {
    std::string line = "{\"output\":" + volgrid::cli::jsonString(args.out);
    for (const auto& entry : kJsonCounts)
      line += std::string(",\"") + entry[0] + "\":" + std::to_string(count(fd, entry[1]));
    char tail[96];
    std::snprintf(tail, sizeof tail, ",\"meshable\":%s,\"seconds\":%.3f}", meshable ? "true" : "false",
                  clock.seconds());
    std::printf("%s%s\n", line.c_str(), tail);
  }
  else
  {
    vtkStringArray* text = vtkStringArray::SafeDownCast(fd->GetAbstractArray("SurfacePrepReport"));
    if (text && text->GetNumberOfValues() > 0)
      std::fputs(text->GetValue(0).c_str(), stdout);
    std::printf("wrote %s (%lld points, %lld triangles) in %.2f s\n", args.out.c_str(),
                static_cast<long long>(result->GetNumberOfPoints()), static_cast<long long>(result->GetNumberOfCells()),
                clock.seconds());
  }
  return meshable ? 0 : 1;
}
