#include "DomainSizing.h"

#include "CoarseBoundaryFloor.h"
#include "DomainThickness.h"
#include "OctreeSizing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

namespace volgrid
{
namespace
{
// The box of a tet.
void tetBox(const TetMesh& mesh, int32_t t, double lo[3], double hi[3])
{
  for (int a = 0; a < 3; ++a)
    lo[a] = hi[a] = mesh.point(mesh.vertex(t, 0))[a];
  for (int i = 1; i < 4; ++i)
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], mesh.point(mesh.vertex(t, i))[a]);
      hi[a] = std::max(hi[a], mesh.point(mesh.vertex(t, i))[a]);
    }
}

// Where the domain's tets are: the field points query the sizes only there. The pyramid's cube is the
// tets' own (the mesh's points may reach further: the corners of the Delaunay's bounding box).
OccupancyPyramid domainBoxes(const TetMesh& mesh)
{
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  mesh.forEachTet(
    [&](int32_t t)
    {
      double bl[3], bh[3];
      tetBox(mesh, t, bl, bh);
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], bl[a]);
        hi[a] = std::max(hi[a], bh[a]);
      }
    });
  const double size = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] }) * 1.001 + 1e-300;
  OccupancyPyramid domain;
  domain.reset(lo, size, 7);
  mesh.forEachTet(
    [&](int32_t t)
    {
      double bl[3], bh[3];
      tetBox(mesh, t, bl, bh);
      domain.addBox(bl, bh);
    });
  return domain;
}

// The floor under the size cap (CoarseBoundaryFloor.h), or none when there is no cap, no gradation or no
// boundary node coarser than the cap (after the depth limit; the depth: DomainThickness.h).
Status coarseBoundaryFloor(const TetMesh& mesh, const SurfaceMesh& surface, const std::vector<int32_t>& boundaryPoint,
                           const std::vector<double>& xyz, const std::vector<double>& h, const SizingOptions& sizing,
                           std::shared_ptr<const CoarseBoundaryFloor>& out)
{
  out.reset();
  const double cap = sizing.maxEdgeLength, slope = sizing.gradation - 1;
  const size_t nBoundary = boundaryPoint.size();
  if (!(cap > 0) || !(slope > 0) || nBoundary == 0 ||
      std::none_of(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(nBoundary), [&](double x) { return x > cap; }))
    return Status::success();
  const int32_t nSurface = std::min(surface.numberOfPoints(), mesh.numVertices());
  const std::vector<double> depth = inwardThickness(mesh, nSurface);
  std::vector<double> spacing(nBoundary);
  for (size_t j = 0; j < nBoundary; ++j)
  {
    const int32_t i = boundaryPoint[j];
    const bool same = i < nSurface && std::equal(surface.point(i), surface.point(i) + 3, mesh.point(i));
    spacing[j] = std::min(h[j], cap + slope * kFloorShareOfDepth * (same ? depth[static_cast<size_t>(i)] : 0.0));
  }
  if (std::none_of(spacing.begin(), spacing.end(), [&](double x) { return x > cap; }))
    return Status::success();
  auto floor = std::make_shared<CoarseBoundaryFloor>();
  Status s = floor->build(xyz.data(), spacing.data(), nBoundary, h.size(), slope);
  if (s.ok())
    out = floor;
  return s;
}
} // namespace

Status buildDomainSizing(const TetMesh& mesh, const SurfaceMesh& surface, const ImprovementOptions& options,
                         SizingField& fast, ImprovementStatistics& stats, Progress* progress)
{
  SizingField sizing;
  std::shared_ptr<OctreeSizing> octree;
  const size_t nCluster = options.clusterPoints.size() / 3;
  Status s;
  if (options.sizingFunction)
    sizing.setUserFunction(options.sizingFunction);
  if (!options.sizingPoints.empty())
    sizing.setBackgroundCloud(options.sizingPoints.data(), options.sizingValues.data(), options.sizingValues.size());
  if (!options.clusterSizes.empty())
    sizing.addSizedPoints(options.clusterPoints.data(), options.clusterSizes.data(), nCluster);
  if (options.fieldPoints)
  {
    // The boundary points with their PDF (eq. 3) become sized nodes, each moved by a millionth of its
    // own PDF: the background Delaunay of the sizing field then sees no cospherical or coplanar sets
    // (spheres, boxes), which would send every insphere test to exact arithmetic, and the interpolated
    // sizes change by a negligible amount. The mesh itself is untouched.
    const std::vector<double> pdf = pointDistributionFunction(surface.points.data(), surface.numberOfPoints(),
                                                              surface.triangles.data(), surface.numberOfTriangles());
    std::vector<double> xyz, h;
    std::vector<int32_t> boundaryPoint; // the surface point of each boundary node
    xyz.reserve(surface.points.size());
    h.reserve(pdf.size());
    uint64_t state = 0x9E3779B97F4A7C15ull;
    for (int32_t i = 0; i < surface.numberOfPoints(); ++i)
    {
      if (!(pdf[i] > 0))
        continue;
      for (int k = 0; k < 3; ++k)
      {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const double u = static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0) - 0.5; // [-0.5, 0.5)
        xyz.push_back(surface.points[3 * static_cast<size_t>(i) + k] + 2e-6 * u * pdf[i]);
      }
      h.push_back(pdf[i] * options.sizing.scale);
      boundaryPoint.push_back(i);
    }
    // Growth away from the boundary: a jittered lattice of nodes over the bounding box with an
    // unbounded size. The gradation limit (Dijkstra over the background Delaunay edges) then gives each
    // one min over the boundary nodes u of h(u) + (G - 1) * path length, so the size grows away from
    // the boundary at the gradation's rate instead of staying at the boundary spacing inside thick
    // bodies (the plain interpolation of eq. 3's PDF between opposite sides of a body).
    const size_t nBoundary = h.size();
    if (options.sizing.gradation > 1 && !h.empty())
    {
      double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
      for (size_t i = 0; i < h.size(); ++i)
        for (int k = 0; k < 3; ++k)
        {
          lo[k] = std::min(lo[k], xyz[3 * i + k]);
          hi[k] = std::max(hi[k], xyz[3 * i + k]);
        }
      const double ext = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
      // About (nodes / 4) lattice nodes, at most 24 per axis: a tenth of the work of the field points.
      const double cells = std::clamp(std::cbrt(static_cast<double>(h.size()) / 4.0), 2.0, 24.0);
      const double step = ext / cells;
      const double unbounded = 4 * ext + 1;
      for (double x = lo[0] + step / 2; x < hi[0]; x += step)
        for (double y = lo[1] + step / 2; y < hi[1]; y += step)
          for (double z = lo[2] + step / 2; z < hi[2]; z += step)
          {
            const double c[3] = { x, y, z };
            for (int k = 0; k < 3; ++k)
            {
              state = state * 6364136223846793005ull + 1442695040888963407ull;
              const double u = static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0) - 0.5;
              xyz.push_back(c[k] + 0.3 * u * step);
            }
            h.push_back(unbounded);
          }
      stats.latticeNodes = static_cast<int64_t>(h.size() - nBoundary);
    }
    sizing.addSizedPoints(xyz.data(), h.data(), h.size());
    std::shared_ptr<const CoarseBoundaryFloor> floor;
    s = coarseBoundaryFloor(mesh, surface, boundaryPoint, xyz, h, options.sizing, floor);
    if (!s.ok())
      return s;
    // The outer field's cap: the octree's samples carry it, or, with a floor, the cap it raises.
    SizingOptions uniformOptions = options.sizing;
    if (floor)
    {
      // The cap holds away from the boundary; next to triangles coarser than it, the size grades down
      // from their spacing (CoarseBoundaryFloor.h).
      sizing.setCapFloor(floor);
      uniformOptions.maxEdgeLength = 0;
      stats.coarseBoundaryFloor = floor->largestBoundarySize();
    }
    s = sizing.build(nullptr, 0, nullptr, 0, options.sizing, progress);
    if (!s.ok())
      return s;
    // The field points query the octree sampling of this field (see OctreeSizing).
    double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
    for (size_t i = 0; i < mesh.points.size(); i += 3)
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], mesh.points[i + k]);
        hi[k] = std::max(hi[k], mesh.points[i + k]);
      }
    const double ext = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] }) * 1.001 + 1e-300;
    const OccupancyPyramid domain = domainBoxes(mesh);
    octree = std::make_shared<OctreeSizing>();
    octree->build(sizing, lo, ext, 18, std::max<size_t>(1u << 20, 16 * static_cast<size_t>(mesh.numVertices())),
                  &domain, progress, options.threads);
    if (octree->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Sizing was cancelled.");
    std::shared_ptr<const OctreeSizing> tree = octree;
    uniformOptions.gradation = 1; // no sized points in the outer field: nothing to grade
    fast.setUserFunction([tree](const double* p) { return tree->evaluate(p); }, /*threadSafe=*/true);
    s = fast.buildUniform(std::numeric_limits<double>::max(), uniformOptions);
    if (!s.ok())
      return s;
  }
  return Status::success();
}

} // namespace volgrid
