// volgrid prep IN... OUT [--enclosure SHAPE] [--enclosure-scale S] [--edge-length L] [--merge-tolerance T]
//                        [--exact] [--fill-holes N] [--no-orient] [--axis x|y|z] [--center X,Y,Z]
//                        [--dimensions A[,B[,C]]] [--no-intersections] [--json]
// Runs vtkVolGridSurfacePrep on the input surfaces (each file a part) and writes the clean surface with its
// PatchId and diagnostic arrays. Exit code: 0 when the output is meshable, 1 when defects remain (the
// output is still written) or a file cannot be read or written, 2 for bad arguments.
#include "CliSupport.h"
#include "Commands.h"
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
#include <set>
#include <string>
#include <vector>

namespace
{
const char* kUsage =
  "usage: volgrid prep IN... OUT.{vtp,vtk,stl,off} [options]\n"
  "  Merges the input surfaces (each a part: PatchId), repairs them (weld, remove zero-area and duplicate\n"
  "  triangles, stitch, fill holes, orient), optionally adds an enclosure, and reports what is left.\n"
  "  --enclosure box|sphere|cylinder|hemisphere|ellipsoid   far-field enclosure around the input\n"
  "  --enclosure-scale S   enclosure size as a factor of the input's bounding box (>= 1, default 10)\n"
  "  --center X,Y,Z --dimensions A[,B[,C]]   explicit enclosure (then no input is needed): box edges;\n"
  "                        sphere, hemisphere radius; cylinder radius, height; ellipsoid semi-axes\n"
  "  --axis x|y|z          cylinder / hemisphere axis (default z)\n"
  "  --edge-length L       target edge length of the enclosure (default 0: 1/16 of its size)\n"
  "  --merge-tolerance T   weld points closer than T * bounding-box diagonal (default 1e-6; 0: exactly\n"
  "                        coincident points only, like --exact)\n"
  "  --exact               merge exactly coincident points only\n"
  "  --fill-holes N        fill holes of at most N edges (default 200; 0: leave holes open)\n"
  "  --no-orient           keep the triangles' orientation\n"
  "  --no-intersections    skip the self-intersection test\n"
  "  --json                one JSON line of counts on stdout\n"
  "  Exit 0: the output is meshable; 1: defects remain (output written) or I/O error; 2: bad arguments.\n";

int usage(const std::string& problem)
{
  std::fprintf(stderr, "volgrid prep: %s\n%s", problem.c_str(), kUsage);
  return 2;
}

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

int runPrepCommand(int argc, char** argv)
{
  std::vector<std::string> files;
  bool json = false;
  vtkNew<vtkVolGridSurfacePrep> prep;
  bool haveCenter = false, haveDimensions = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    double number = 0;
    if (a == "--json")
      json = true;
    else if (a == "-h" || a == "--help")
    {
      std::fputs(kUsage, stdout);
      return 0;
    }
    else if (a == "--exact")
      prep->ExactMergeOnlyOn();
    else if (a == "--no-orient")
      prep->OrientShellsOff();
    else if (a == "--no-intersections")
      prep->CheckIntersectionsOff();
    else if (a == "--enclosure")
    {
      const char* v = value();
      const std::string shape = v ? v : "";
      const char* names[] = { "none", "box", "sphere", "cylinder", "hemisphere", "ellipsoid" };
      int found = -1;
      for (int k = 0; k < 6; ++k)
        if (shape == names[k])
          found = k;
      if (found < 0)
        return usage("--enclosure expects box, sphere, cylinder, hemisphere or ellipsoid");
      prep->SetEnclosure(found);
    }
    else if (a == "--axis")
    {
      const char* v = value();
      const std::string axis = v ? v : "";
      if (axis != "x" && axis != "y" && axis != "z")
        return usage("--axis expects x, y or z");
      prep->SetEnclosureAxis(axis[0] - 'x');
    }
    else if (a == "--center" || a == "--dimensions")
    {
      const char* v = value();
      double t[3];
      if (!v || !parseTriple(v, t))
        return usage(a + " expects one to three numbers X[,Y[,Z]]");
      if (a == "--center")
        prep->SetEnclosureCenter(t), haveCenter = true;
      else
      {
        if (t[0] <= 0 || t[1] < 0 || t[2] < 0)
          return usage("--dimensions must be positive");
        prep->SetEnclosureDimensions(t), haveDimensions = true;
      }
    }
    else if (a == "--enclosure-scale" || a == "--edge-length" || a == "--merge-tolerance")
    {
      const char* v = value();
      if (!v || !volgrid::cli::parseDouble("prep", a.c_str(), v, number))
        return v ? 2 : usage(a + " needs a number");
      if (a == "--enclosure-scale")
      {
        if (number < 1.0 || number > 1.0e6)
          return usage("--enclosure-scale must be in [1, 1e6]");
        prep->SetEnclosureScale(number);
      }
      else if (a == "--edge-length")
      {
        if (number < 0.0)
          return usage("--edge-length must be >= 0");
        prep->SetEnclosureEdgeLength(number);
      }
      else
      {
        if (number < 0.0 || number > 0.01)
          return usage("--merge-tolerance must be in [0, 0.01]");
        prep->SetMergeTolerance(number);
      }
    }
    else if (a == "--fill-holes")
    {
      const char* v = value();
      long long n = 0;
      if (!v || !volgrid::cli::parseLong("prep", "--fill-holes", v, n))
        return v ? 2 : usage("--fill-holes needs a number");
      if (n < 0 || n > 1000000)
        return usage("--fill-holes must be in [0, 1000000]");
      prep->SetFillHoles(n >= 3);
      if (n >= 3)
        prep->SetMaxHoleEdges(static_cast<int>(n));
    }
    else if (!a.empty() && a[0] == '-')
      return usage("unknown option " + a);
    else
      files.push_back(a);
  }
  if (files.empty())
    return usage("missing OUT");
  const std::string out = files.back();
  files.pop_back();
  if (const int code = volgrid::cli::checkOutputPath("prep", "OUT", out, { "vtp", "vtk", "stl", "off" }, files))
    return code;
  if (haveCenter != haveDimensions)
    return usage("--center and --dimensions go together");
  if (haveCenter)
    prep->ExplicitEnclosureOn();
  if (files.empty() && (!haveCenter || prep->GetEnclosure() == vtkVolGridSurfacePrep::ENCLOSURE_NONE))
    return usage("no input surface (without input, give --enclosure with --center and --dimensions)");

  volgrid::cli::Stopwatch clock;
  for (const std::string& file : files)
  {
    volgrid::SurfaceMesh mesh;
    std::string info;
    const volgrid::Status status = volgrid::readAnySurface(file, mesh, info);
    if (!status.ok())
    {
      std::fprintf(stderr, "volgrid prep: %s\n", status.message.c_str());
      return 1;
    }
    if (!json)
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
  if (!volgrid::writeSurfaceFile(out, result, error))
  {
    std::fprintf(stderr, "volgrid prep: %s\n", error.c_str());
    return 1;
  }
  vtkFieldData* fd = result->GetFieldData();
  const bool meshable = prep->GetMeshable();
  if (json)
  {
    std::string line = "{\"output\":" + volgrid::cli::jsonString(out);
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
    std::printf("wrote %s (%lld points, %lld triangles) in %.2f s\n", out.c_str(),
                static_cast<long long>(result->GetNumberOfPoints()), static_cast<long long>(result->GetNumberOfCells()),
                clock.seconds());
  }
  return meshable ? 0 : 1;
}
