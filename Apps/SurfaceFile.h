// Reading and writing surface files for the CLI (volgrid prep, check, mesh).
#pragma once

#include "Status.h"
#include "SurfaceMesh.h"

#include <string>

class vtkPolyData;

namespace volgrid
{
// Reads any surface file into `mesh` (cleared first), by extension (case-insensitive):
//   .off .mesh .poly .smesh .msh .stl  Core readers (SurfaceReader.h; patch ids from the file's
//                                      references, STL solids, gmsh entities)
//   .obj .ply .vtp .vtk                VTK readers (OBJ, PLY, XML poly data, legacy VTK: polydata or an
//                                      unstructured grid's 2D cells; a "PatchId" cell array is kept)
// Any of them may be gzip-compressed (name.stl.gz, name.obj.gz ...): Core decompresses in memory, the
// VTK formats go through a temporary decompressed copy.
// Polygons and strips are triangulated and exactly coincident points merged. `info` receives a one-line
// description (format, points, triangles, warnings). Failures name the file and the problem.
Status readAnySurface(const std::string& path, SurfaceMesh& mesh, std::string& info);
// The same; with mergeCoincidentPoints false the file's own point numbering is kept (STL, which has no
// numbering, and OBJ, whose VTK reader splits points by texture coordinate, are still merged).
Status readAnySurface(const std::string& path, SurfaceMesh& mesh, std::string& info, bool mergeCoincidentPoints);

// True when readAnySurface knows the extension.
bool surfaceFileSupported(const std::string& path);

// Writes a surface by extension: .vtp (XML, with all arrays), .vtk (legacy, with all arrays), .stl (binary),
// .off (points and triangles). Returns false with `error` set on failure.
bool writeSurfaceFile(const std::string& path, vtkPolyData* surface, std::string& error);

// Lower-case extension without the dot ("" when none).
std::string surfaceFileExtension(const std::string& path);
} // namespace volgrid
