// Solver mesh writers: one format per file (MeshWriterGmsh.cxx, MeshWriterSU2.cxx,
// MeshWriterOpenFOAM.cxx, MeshWriterMedit.cxx, MeshWriterTetGen.cxx, MeshWriterCGNS.cxx,
// MeshWriterExodus.cxx), chosen here by name or extension.
// Every writer takes a SolverMesh with normalized labels (SolverMesh.h), writes through OutputFile (no
// partial file on failure) and returns a Status naming the path and the reason.
#pragma once

#include "SolverMesh.h"
#include "Status.h"

#include <map>
#include <string>

namespace volgrid
{

enum class MeshFormat
{
  Unknown,
  Gmsh41,   // .msh: gmsh 4.1 ASCII with $PhysicalNames and $Entities
  Gmsh22,   // gmsh 2.2 ASCII (--format gmsh22)
  SU2,      // .su2: one MARKER_TAG per patch
  OpenFOAM, // a case directory: CASE/constant/polyMesh/{points,faces,owner,neighbour,boundary}
  Medit,    // .mesh: refs; names in "# VolGrid patch|region LABEL NAME" comment lines
  TetGen,   // .node/.ele/.face (the path is any of them or the stem) with region attributes and markers
  CGNS,     // .cgns: a section per region and per patch, one boundary condition (and family) per patch
  Exodus,   // .exo/.e: an element block per region, a side set per patch, names kept
};

// By --format name: "gmsh"/"msh"/"gmsh41", "gmsh22", "su2", "openfoam"/"polymesh", "medit"/"mesh",
// "tetgen", "cgns", "exodus"/"exo". Unknown otherwise.
MeshFormat meshFormatFromName(const std::string& name);
// By the path's extension (case-insensitive): .msh .su2 .mesh .node/.ele/.face .cgns .exo/.e/.ex2.
// Unknown otherwise
// (OpenFOAM has no extension: it is chosen by name only).
MeshFormat meshFormatFromPath(const std::string& path);

// The common stem of a TetGen file set, for its reader and its writer: "a.node", "a.ele", "a.face", "a" -> "a".
std::string tetgenStem(const std::string& path);
const char* meshFormatName(MeshFormat format);
// Whether the format's writer takes boundary-layer prisms, boundary quads and the pyramids where a layer
// column collapsed (SolverMesh::prisms, quads, pyramids).
bool writesPrisms(MeshFormat format);

struct MeshWriteOptions
{
  // OpenFOAM patch type by patch name (wall, patch, symmetryPlane, ...). Patches not listed get
  // defaultOpenFoamPatchType(name).
  std::map<std::string, std::string> openFoamPatchTypes;
};

// "symmetryPlane" for a name containing "symmetry" (any case), "patch" for one containing "farfield",
// "inlet" or "outlet", "wall" otherwise.
std::string defaultOpenFoamPatchType(const std::string& name);

// Writes `mesh` (labels normalized first on a copy when needed) in `format` to `path`.
Status writeSolverMesh(const std::string& path, const SolverMesh& mesh, MeshFormat format,
                       const MeshWriteOptions& options = MeshWriteOptions());

Status writeGmsh41(const std::string& path, const SolverMesh& mesh);
Status writeGmsh22(const std::string& path, const SolverMesh& mesh);
Status writeSU2(const std::string& path, const SolverMesh& mesh);
Status writeMedit(const std::string& path, const SolverMesh& mesh);
// `path` names the stem or any of the three files; all three are written (each atomically).
Status writeTetGen(const std::string& path, const SolverMesh& mesh);
Status writeCGNS(const std::string& path, const SolverMesh& mesh);
// Fails when a boundary triangle (quad) is not a face of a tet or prism (a side set lists element sides).
Status writeExodus(const std::string& path, const SolverMesh& mesh);
// `caseDir` must not exist; it is built under a temporary name and renamed when complete. Patch names
// must be OpenFOAM words.
Status writeOpenFOAM(const std::string& caseDir, const SolverMesh& mesh, const MeshWriteOptions& options);

} // namespace volgrid
