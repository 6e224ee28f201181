// Export options, patch renaming and solver-format output for the CLI (see MeshExport.h).
#include "MeshExport.h"

#include "CliSupport.h"

#include "Mesher.h"
#include "SurfaceFile.h"
#include "SurfaceMesh.h"

#include <cstdio>
#include <cstring>
#include <utility>

namespace volgrid
{
namespace cli
{
const char* const kExportUsage =
  "Solver output (by OUT's extension: .msh gmsh 4.1, .su2, .mesh Medit, .node/.ele/.face TetGen,\n"
  ".cgns CGNS, .exo/.e Exodus II; .vtu VTK):\n"
  "  --format NAME        gmsh | gmsh22 | su2 | openfoam (OUT is a new case directory: OUT/constant/polyMesh)\n"
  "                       | medit | tetgen | cgns | exodus | vtu, when the extension does not say it\n"
  "  --patch NAME=ID,...  names boundary patches and groups input patch ids under a name, e.g.\n"
  "                       --patch farfield=1,symmetry=2,wing=3,4,5 (new PatchId 1, 2, 3 in that order;\n"
  "                       ids not listed keep their own patch after these)\n"
  "  --patch-type NAME=TYPE  OpenFOAM patch type (default: symmetryPlane for names with 'symmetry',\n"
  "                       patch for 'farfield'/'inlet'/'outlet', wall otherwise)\n";

bool takeExportOptions(const char* command, int& argc, char** argv, ExportRequest& request)
{
  int kept = 1;
  for (int i = 1; i < argc; ++i)
  {
    const bool format = std::strcmp(argv[i], "--format") == 0;
    const bool patch = std::strcmp(argv[i], "--patch") == 0;
    const bool type = std::strcmp(argv[i], "--patch-type") == 0;
    if (!format && !patch && !type)
    {
      argv[kept++] = argv[i];
      continue;
    }
    if (i + 1 >= argc)
    {
      reportMissingValue(command, argv[i]);
      return false;
    }
    const std::string value = argv[++i];
    if (format)
      request.format = value;
    else if (patch)
    {
      const Status s = parsePatchAssignment(value, request.patches);
      if (!s.ok())
      {
        std::fprintf(stderr, "volgrid %s: %s\n", command, s.message.c_str());
        return false;
      }
    }
    else
    {
      const size_t eq = value.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == value.size())
      {
        std::fprintf(stderr, "volgrid %s: --patch-type expects NAME=TYPE, not '%s'\n", command, value.c_str());
        return false;
      }
      request.writeOptions.openFoamPatchTypes[value.substr(0, eq)] = value.substr(eq + 1);
    }
  }
  argc = kept;
  argv[argc] = nullptr;
  return true;
}

bool chooseFormat(const char* command, const std::string& out, const ExportRequest& request, MeshFormat& format,
                  bool& vtk)
{
  vtk = false;
  if (!request.format.empty())
  {
    vtk = request.format == "vtu" || request.format == "vtk";
    format = meshFormatFromName(request.format);
    if (vtk || format != MeshFormat::Unknown)
      return true;
    std::fprintf(stderr,
                 "volgrid %s: unknown --format '%s' (gmsh, gmsh22, su2, openfoam, medit, tetgen, cgns, exodus, vtu)\n",
                 command, request.format.c_str());
    return false;
  }
  format = meshFormatFromPath(out);
  const std::string ext = surfaceFileExtension(out);
  vtk = ext == "vtu" || ext == "vtk" || ext == "vtp";
  if (vtk || format != MeshFormat::Unknown)
    return true;
  std::fprintf(
    stderr,
    "volgrid %s: cannot tell the output format of '%s' from its extension '%s' (.vtu .msh .su2 .mesh .node .cgns .exo; "
    "--format NAME for others, e.g. --format openfoam)\n",
    command, out.c_str(), ext.c_str());
  return false;
}

bool solverMeshFromResult(const char* command, const ExportRequest& request, const SurfaceMesh& surface,
                          MesherResult& result, SolverMesh& mesh)
{
  mesh.patchNames = surface.hasPatchIds() ? surface.patchNames : NameTable();
  if (!request.patches.empty())
  {
    const Status s = applyPatchAssignment(request.patches, result.boundaryPatch, mesh.patchNames);
    if (!s.ok())
    {
      std::fprintf(stderr, "volgrid %s: %s\n", command, s.message.c_str());
      return false;
    }
  }
  return true;
}

void moveGeometry(MesherResult& result, SolverMesh& mesh)
{
  mesh.points = std::move(result.points);
  mesh.tets = std::move(result.tets);
  mesh.tetRegion = std::move(result.tetRegion);
  mesh.triangles = std::move(result.boundaryTriangles);
  mesh.trianglePatch = std::move(result.boundaryPatch);
}

bool writeSolverOutput(const char* command, const std::string& out, MeshFormat format, SolverMesh mesh,
                       const ExportRequest& request, bool quiet)
{
  normalizeLabels(mesh);
  const Status s = writeSolverMesh(out, mesh, format, request.writeOptions);
  if (!s.ok())
  {
    std::fprintf(stderr, "volgrid %s: %s\n", command, s.message.c_str());
    return false;
  }
  if (quiet)
    return true;
  std::printf("wrote %s '%s': %lld points, %lld tets", meshFormatName(format), out.c_str(),
              static_cast<long long>(mesh.numberOfPoints()), static_cast<long long>(mesh.numberOfTets()));
  if (!mesh.prisms.empty())
    std::printf(", %lld prisms", static_cast<long long>(mesh.prisms.size() / 6));
  if (!mesh.pyramids.empty())
    std::printf(", %lld pyramids", static_cast<long long>(mesh.pyramids.size() / 5));
  std::printf(", patches");
  std::vector<int32_t> faces = mesh.trianglePatch; // boundary faces: triangles and prism side quads
  faces.insert(faces.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  const std::vector<int32_t> patches = distinctLabels(faces);
  const std::vector<int64_t> counts = labelCounts(faces, patches);
  for (size_t k = 0; k < patches.size(); ++k)
    std::printf(" %s (%lld)", labelName(mesh.patchNames, patches[k], "patch").c_str(),
                static_cast<long long>(counts[k]));
  std::printf("\n");
  return true;
}
} // namespace cli
} // namespace volgrid
