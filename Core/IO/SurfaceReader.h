// VTK-free readers for the surface formats VTK lacks or reads wrongly:
//   .off (OFF/COFF/NOFF/CNOFF/STOFF, polygons triangulated), Medit .mesh (ASCII; Triangles and
//   Quadrilaterals, everything else skipped), TetGen .poly/.smesh (polygon facets triangulated by ear
//   clipping in the facet plane, facets with several polygons and hole points as planar regions with
//   holes; nodes from the sibling .node file when the node list is empty),
//   gmsh .msh (ASCII v2.x and v4.x; triangles and quadrangles), .stl (ASCII and binary; lenient ASCII:
//   several solids, text after the last `endsolid`), .ply (ASCII and binary, strips), .obj.
// Each format may be gzip-compressed: "name.stl.gz" is decompressed in memory and read as .stl.
// Every error is a Status whose message names the file, the line and the problem; a malformed file
// never crashes the reader. Status.h has no dedicated I/O kind: unreadable/malformed files use
// ErrorKind::InvalidOption (the file argument is invalid), empty files ErrorKind::EmptyInput,
// NaN/Inf coordinates ErrorKind::NonFinitePoint.
#pragma once

#include "Status.h"
#include "SurfaceMesh.h"

#include <string>
#include <vector>

namespace volgrid
{

struct SurfaceReadOptions
{
  // Merge exactly coincident points after reading (point order of first occurrences kept). STL is
  // always merged (it has no connectivity); for the other formats the file's numbering is kept when
  // false.
  bool mergeCoincidentPoints = true;
};

struct SurfaceReadInfo
{
  std::string format;          // "OFF", "Medit", "TetGen poly", "TetGen smesh", "gmsh 2.2", "STL ascii"...
  int64_t filePoints = 0;      // point records in the file (STL: 3 per facet)
  int64_t fileFaces = 0;       // faces/facets/elements read (before triangulation)
  int64_t polygonFaces = 0;    // faces with more than three corners that were triangulated
  int64_t fanFallbacks = 0;    // polygons that ear clipping could not handle (fan used instead)
  int64_t holeRegions = 0;     // TetGen facet regions cut away by hole points
  int64_t mergedPoints = 0;    // points removed by exact merging
  int64_t skippedElements = 0; // elements of other kinds skipped (tets, edges, ...)
  int64_t solids = 0;          // STL solids
  std::vector<std::string> warnings;
};

// True when readSurface knows the file's extension (case-insensitive; a trailing ".gz" is skipped).
bool surfaceReaderSupports(const std::string& path);

// Reads by extension. The mesh is cleared first.
Status readSurface(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
                   const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
