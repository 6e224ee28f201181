// How big a mesh will get, estimated before any work from the domain and the size field, so that absurd
// size options (--max-edge 1e-9, --size-scale 1e-300, refine to 1e-9, 10^9 random points) are refused
// up front with the figure instead of running until memory or time runs out.
//
// The estimate is an order of magnitude (typically within a factor of 2 to 3 of the real count): tets of
// mean edge h fill a volume v with about kTetsPerUnitVolume * v / h^3 tets; h grows away from the boundary
// at the gradation rate; field points' alpha scales the density like (0.75 / alpha)^3.
#pragma once

#include "MeshImprovement.h"
#include "SurfaceMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

// What made the estimate as large as it is, so that messages can name the option.
enum class SizeDriver
{
  SurfaceSpacing, // the input surface's own point spacing
  SizeScale,      // sizing.scale < 1
  MaxEdge,        // sizing.maxEdgeLength
  MaxVolume,      // fieldPointOptions.maxVolume
  Alpha,          // fieldPointOptions.alpha below its default
  TargetSize,     // refine: the per-point target sizes
  PointCount      // Delaunay: the number of points
};

struct SizeEstimate
{
  double points = 0;
  double tets = 0;
  double bytes = 0; // peak memory of the run, roughly
  SizeDriver driver = SizeDriver::SurfaceSpacing;
};

// Peak bytes per output tet of a whole meshing run (mesher, improvement, conversion, output), with room
// for error. Measured peak RSS of `volgrid mesh` on the ONERA M6 domain: 88 B/tet at 5.3M tets, 168 at
// 1.04M (60 MB of it the libraries); the mesher alone 72 B/tet at 5.3M. 300 leaves the ParaView filter its
// input and output data sets and the tet estimate a factor 2 of error (it gave 7.7M for 5.3M there).
// 1000 until session 12, when the CLI's output document and face list dominated: it refused meshes that
// fit in a third of the memory it asked for.
constexpr double kBytesPerTet = 300.0;
// Peak bytes per input point of volgrid delaunay (points, mesh, inverse map, output), measured.
constexpr double kBytesPerDelaunayPoint = 900.0;

// volgrid mesh / vtkVolGridTetrahedralize on a closed surface with these options.
SizeEstimate estimateMeshSize(const SurfaceMesh& surface, const ImprovementOptions& options);

// volgrid refine: a tet mesh (4 point ids per tet) and one target size per point (non-finite or <= 0: none).
SizeEstimate estimateRefineSize(const std::vector<double>& points, const std::vector<int32_t>& tets,
                                const std::vector<double>& targetSize, double alpha);

// volgrid delaunay on n points.
SizeEstimate estimateDelaunaySize(double numPoints);

} // namespace volgrid
