// volgrid check SURFACE [--json] [--no-intersections] [--keep-points]
// Diagnoses a surface (the checks the mesher runs, with exact predicates) without changing it. Prints the
// report, or with --json one JSON line of counts. Exit code: 0 when the surface is clean (closed, manifold,
// consistently oriented and oriented for its domain, no degenerate/duplicate/intersecting triangles), 1
// when it has defects or cannot be read, 2 for bad arguments.
#include "CliSupport.h"
#include "Commands.h"
#include "FlagParser.h"
#include "SurfaceFile.h"

#include "SurfaceChecks.h"

#include <cstdio>
#include <string>
#include <vector>

namespace
{
const char* kUsage =
  "usage: volgrid check SURFACE.{off,mesh,poly,smesh,msh,stl,obj,ply,vtp,vtk} [--json] [--no-intersections]\n"
  "                    [--keep-points]\n"
  "  Diagnoses the surface: open and non-manifold edges, orientation, degenerate, duplicate and\n"
  "  self-intersecting triangles, shells and their nesting. Exactly coincident points are merged first\n"
  "  (as the mesher does); --keep-points keeps the file's point numbering (STL, OBJ merged).\n"
  "  Exit 0 when clean, 1 with defects or an unreadable file, 2 for bad arguments.\n";

int64_t misoriented(const volgrid::SurfaceCheckReport& r)
{
  int64_t n = 0;
  for (const volgrid::SurfaceShell& s : r.shells)
    if (s.closed && s.consistent && s.signedVolume != 0.0 && ((s.depth % 2 == 0) != (s.signedVolume > 0.0)))
      ++n;
  return n;
}

std::string ids(const std::vector<int32_t>& v)
{
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i)
    s += (i ? "," : "") + std::to_string(v[i]);
  return s + "]";
}
} // namespace

int runCheckCommand(int argc, char** argv)
{
  bool json = false;
  bool intersections = true;
  bool merge = true;
  volgrid::cli::FlagParser p("check", kUsage);
  p.add("--json", json, true);
  p.add("--no-intersections", intersections, false);
  p.add("--keep-points", merge, false);
  std::string path;
  if (const int code = p.scan(argc, argv, path, "missing SURFACE", "only one surface file"); code >= 0)
    return code;

  volgrid::cli::Stopwatch clock;
  volgrid::SurfaceMesh mesh;
  std::string info;
  const volgrid::Status read = volgrid::readAnySurface(path, mesh, info, merge);
  if (!read.ok())
  {
    std::fprintf(stderr, "volgrid check: %s\n", read.message.c_str());
    return 1;
  }
  volgrid::SurfaceCheckOptions options;
  options.selfIntersections = intersections;
  const volgrid::SurfaceCheckReport r = volgrid::checkSurface(mesh, options);
  const volgrid::Status status = volgrid::surfaceStatus(r);
  const int64_t wrongWay = misoriented(r);
  const bool clean =
    status.ok() && r.consistentlyOriented() && wrongWay == 0 && r.nonManifoldVertices == 0 && r.coincidentPoints == 0;

  if (json)
  {
    std::printf(
      "{\"file\":%s,\"format\":%s,\"points\":%d,\"triangles\":%d,\"shells\":%zu,\"watertight\":%s,"
      "\"boundary_edges\":%lld,\"boundary_loops\":%lld,\"non_manifold_edges\":%lld,"
      "\"non_manifold_vertices\":%lld,\"inconsistent_edges\":%lld,\"degenerate_triangles\":%lld,"
      "\"duplicate_triangles\":%lld,\"self_intersecting_pairs\":%lld,\"shell_intersecting_pairs\":%lld,"
      "\"inward_shells\":%d,\"misoriented_shells\":%lld,\"unreferenced_points\":%lld,\"coincident_points\":%lld,"
      "\"first_boundary_edge_triangles\":%s,\"first_non_manifold_edge_triangles\":%s,"
      "\"first_self_intersecting_pairs\":%s,\"meshable\":%s,\"clean\":%s,\"status\":%s,\"seconds\":%.3f}\n",
      volgrid::cli::jsonString(path).c_str(), volgrid::cli::jsonString(info).c_str(), r.points, r.triangles,
      r.shells.size(), r.watertight() ? "true" : "false", static_cast<long long>(r.boundaryEdges),
      static_cast<long long>(r.boundaryLoops), static_cast<long long>(r.nonManifoldEdges),
      static_cast<long long>(r.nonManifoldVertices), static_cast<long long>(r.inconsistentEdges),
      static_cast<long long>(r.degenerateTriangles), static_cast<long long>(r.duplicateTriangles),
      intersections ? static_cast<long long>(r.selfIntersectingPairs) : -1LL,
      intersections ? static_cast<long long>(r.shellIntersectingPairs) : -1LL, r.inwardShells(),
      static_cast<long long>(wrongWay), static_cast<long long>(r.unreferencedPoints),
      static_cast<long long>(r.coincidentPoints), ids(r.firstBoundaryEdgeTriangles).c_str(),
      ids(r.firstNonManifoldEdgeTriangles).c_str(), ids(r.firstSelfIntersectingPairs).c_str(),
      r.meshable() ? "true" : "false", clean ? "true" : "false",
      volgrid::cli::jsonString(status.ok() ? "meshable" : status.message).c_str(), clock.seconds());
  }
  else
  {
    std::printf("%s: %s\n", path.c_str(), info.c_str());
    std::fputs(volgrid::formatSurfaceReport(r).c_str(), stdout);
    if (wrongWay > 0)
      std::printf("misoriented shells         %lld (not oriented away from the domain)\n",
                  static_cast<long long>(wrongWay));
    std::printf("result                     %s\n", clean ? "clean" : "defects found");
  }
  return clean ? 0 : 1;
}
