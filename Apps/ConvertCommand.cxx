// volgrid convert: a volume mesh from one format to another, patches and regions kept by name.
#include "Commands.h"
#include "FlagParser.h"
#include "MeshExport.h"

#include "MeshReader.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace
{
const char* kUsage =
  "usage: volgrid convert IN OUT [--format NAME] [--patch NAME=ID,...] [--patch-type NAME=TYPE]\n"
  "  Reads the tet mesh IN (.mesh Medit with its refs, .msh gmsh 2.2/4.1 with its physical groups,\n"
  "  .su2 with its markers, TetGen .node/.ele/.face with attributes and markers, .cgns with its boundary\n"
  "  conditions, .exo/.e with its element blocks and side sets, an OpenFOAM case) and writes it as\n"
  "  OUT.\n";
} // namespace

int runConvertCommand(int argc, char** argv)
{
  volgrid::cli::ExportRequest request;
  if (!volgrid::cli::takeExportOptions("convert", argc, argv, request))
    return 2;
  // --format, --patch and --patch-type were taken above; convert has no flags of its own.
  volgrid::cli::FlagParser p("convert", kUsage);
  p.moreHelp = volgrid::cli::kExportUsage;
  std::vector<std::string> positional;
  if (const int code = p.scan(argc, argv, positional); code >= 0)
    return code;
  if (positional.size() != 2)
    return p.fail("expected IN and OUT", true), 2;
  volgrid::MeshFormat format = volgrid::MeshFormat::Unknown;
  bool vtk = false;
  if (!volgrid::cli::chooseFormat("convert", positional[1], request, format, vtk))
    return 2;
  if (vtk)
  {
    std::fprintf(stderr, "volgrid convert: VTK output is written by 'volgrid mesh'; choose a solver format\n");
    return 2;
  }
  volgrid::SolverMesh mesh;
  volgrid::Status s = volgrid::readSolverMesh(positional[0], mesh);
  if (s.ok() && !request.patches.empty())
    s = volgrid::applyPatchAssignment(request.patches, mesh.trianglePatch, mesh.patchNames);
  if (!s.ok())
  {
    std::fprintf(stderr, "volgrid convert: %s\n", s.message.c_str());
    return 1;
  }
  return volgrid::cli::writeSolverOutput("convert", positional[1], format, std::move(mesh), request, false) ? 0 : 1;
}
