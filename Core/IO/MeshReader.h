// Solver mesh readers: a tet mesh (with its boundary-layer prisms, pyramids and quads too; TetGen: tets
// only) with its named boundary patches and regions back into a SolverMesh, so that `volgrid
// convert`, `refine` and `quality` take a solver's mesh. One format per file
// (MeshReaderMedit.cxx, MeshReaderGmsh.cxx, MeshReaderSU2.cxx,
// MeshReaderTetGen.cxx, MeshReaderOpenFOAM.cxx, MeshReaderCGNS.cxx, MeshReaderExodus.cxx). Errors name the file, the
// line and the problem.
#pragma once

#include "SolverMesh.h"
#include "Status.h"

#include <string>

namespace volgrid
{

// True when readSolverMesh knows the path's extension.
bool solverMeshReaderSupports(const std::string& path);

// Reads by extension (.mesh, .msh, .su2, .node/.ele/.face, .cgns, .exo/.e/.ex2), or an OpenFOAM case
// directory. The mesh is cleared first. Quads are kept only with prisms or pyramids (finishReadCells).
Status readSolverMesh(const std::string& path, SolverMesh& mesh);

// Medit .mesh (ASCII): Vertices, Triangles and Quadrilaterals (ref = patch), Tetrahedra, Prisms and
// Pyramids (ref = region); other sections skipped. Names from VolGrid's "# VolGrid patch|region LABEL NAME" comment
// lines.
Status readMeditVolume(const std::string& path, SolverMesh& mesh);

// gmsh .msh, ASCII 2.2 and 4.1: triangles and quads (patch = physical tag of the entity, else the entity
// tag), tets, prisms and pyramids (region likewise); names from $PhysicalNames.
Status readGmshVolume(const std::string& path, SolverMesh& mesh);
// SU2 (.su2, ASCII, 3D): tets, prisms, pyramids, and triangle and quad markers; marker k (file order) is
// patch k named by MARKER_TAG.
Status readSU2(const std::string& path, SolverMesh& mesh);
// TetGen STEM.node/.ele/.face (`path` any of them or the stem): region = first tet attribute (else 1),
// patch = face marker (else 1); 0- or 1-based as the first node says. No names.
Status readTetGenVolume(const std::string& path, SolverMesh& mesh);
// CGNS: the first unstructured zone; TETRA_4 sections are regions (named after the section), PENTA_6 and
// PYRA_5 sections "<region>_prisms" / "<region>_pyramids" join that region; boundary conditions over TRI_3
// and QUAD_4 elements (or their vertices) are patches named after the condition.
Status readCGNS(const std::string& path, SolverMesh& mesh);
// Exodus II: TETRA element blocks are regions, WEDGE and PYRAMID blocks "<region>_prisms" /
// "<region>_pyramids" join that region; side sets (tet, wedge and pyramid sides: triangles and quads) are
// patches; named as in the file.
Status readExodus(const std::string& path, SolverMesh& mesh);
// True when `path` is a directory with constant/polyMesh/faces.
bool isOpenFoamCase(const std::string& path);
// OpenFOAM polyMesh of CASE (ASCII): tets, prisms (2 triangles + 3 quads) and pyramids (1 quad + 4
// triangles) from their faces; patches (triangles and quads) labelled 1.. in the boundary file's order
// with their names, region 1.
Status readOpenFOAM(const std::string& caseDir, SolverMesh& mesh);

} // namespace volgrid
