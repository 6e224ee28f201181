// The CLI's solver hand-off: the export options shared by `volgrid mesh` and `volgrid convert`
// (--format NAME, --patch NAME=ID,..., --patch-type NAME=TYPE), the user's patch renaming, and the
// choice between VTK XML output and a solver format (Core's MeshWriter.h).
#pragma once

#include "MeshWriter.h"
#include "PatchNames.h"
#include "SolverMesh.h"

#include <string>

namespace volgrid
{
struct MesherResult;
struct SurfaceMesh;
namespace cli
{
struct ExportRequest
{
  std::string format;            // --format NAME ("" = by extension)
  PatchAssignment patches;       // --patch NAME=ID,... (several allowed)
  MeshWriteOptions writeOptions; // --patch-type NAME=TYPE (OpenFOAM)
};

extern const char* const kExportUsage; // the options' help text

// Takes --format, --patch and --patch-type (with their values) out of argv, so the command's own
// parser never sees them. False (message printed) on a missing or malformed value.
bool takeExportOptions(const char* command, int& argc, char** argv, ExportRequest& request);

// The solver format of `out`: from --format when given (an unknown name is an error), else from the
// extension. Unknown with `vtk` true for .vtu/.vtk/.vtp (VTK's writers); false (message printed) when
// neither fits.
bool chooseFormat(const char* command, const std::string& out, const ExportRequest& request, MeshFormat& format,
                  bool& vtk);

// The names of the mesher's output as a SolverMesh: patch names from the input surface, the user's --patch
// grouping applied (to `result`'s boundaryPatch as well, so the VTK outputs agree). False (message
// printed) on a bad assignment. The geometry follows with moveGeometry, once nothing else needs it.
bool solverMeshFromResult(const char* command, const ExportRequest& request, const SurfaceMesh& surface,
                          MesherResult& result, SolverMesh& mesh);

// Moves the points, tets, regions and boundary triangles of `result` into `mesh` (no copy: at millions of
// tets a copy would add to the writer's peak); `result` keeps its other arrays and its statistics.
void moveGeometry(MesherResult& result, SolverMesh& mesh);

// Writes `mesh` in `format` (by value: its labels are normalised in place, so a caller that passes it with
// std::move adds no copy); prints "wrote FORMAT PATH: points, tets, patch (faces) ..." to stdout unless
// quiet. False (message naming the path and reason printed) on failure.
bool writeSolverOutput(const char* command, const std::string& out, MeshFormat format, SolverMesh mesh,
                       const ExportRequest& request, bool quiet);
} // namespace cli
} // namespace volgrid
