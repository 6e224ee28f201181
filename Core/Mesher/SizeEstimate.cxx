#include "SizeEstimate.h"

#include "CoarseBoundaryFloor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace volgrid
{

namespace
{
// Tets of mean edge h per unit volume: 6 sqrt(2) / h^3 regular tets fit in a unit volume; Delaunay meshes
// of that mean edge have somewhat more (measured on spheres and boxes).
constexpr double kTetsPerUnitVolume = 6.0 * 1.41421356237 * 1.5;
constexpr double kTetsPerPoint = 6.0;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

double length(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

double triangleArea(const double* a, const double* b, const double* c)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Integral over depth 0..D of 1/h(d)^3 with h(d) = min(h0 + g d, cap), h0 <= cap.
double inverseCubeIntegral(double h0, double g, double cap, double depth)
{
  if (g <= 0 || h0 >= cap)
    return depth / (h0 * h0 * h0);
  const double reach = (cap - h0) / g; // depth where h reaches the cap (infinite cap: never)
  const double graded = std::min(depth, reach);
  const double hEnd = h0 + g * graded;
  double sum = (1.0 / (h0 * h0) - 1.0 / (hEnd * hEnd)) / (2.0 * g);
  if (depth > reach)
    sum += (depth - reach) / (cap * cap * cap);
  return sum;
}

// Integral over depth 0..D of 1/h(d)^3 with h(d) = max(cap, s0 - g d), s0 > cap: a size cap below the
// boundary's spacing s0 is met only from (s0 - cap) / g in (CoarseBoundaryFloor.h).
double flooredInverseCubeIntegral(double s0, double g, double cap, double depth)
{
  const double reach = (s0 - cap) / g;
  const double graded = std::min(depth, reach);
  const double hEnd = s0 - g * graded;
  double sum = (1.0 / (hEnd * hEnd) - 1.0 / (s0 * s0)) / (2.0 * g);
  if (depth > reach)
    sum += (depth - reach) / (cap * cap * cap);
  return sum;
}

double domainVolume(const SurfaceMesh& surface)
{
  const double v = std::fabs(signedVolume(surface));
  if (v > 0 && std::isfinite(v))
    return v;
  const BoundingBox box = boundingBox(surface, true);
  return 0.5 * (box.max[0] - box.min[0]) * (box.max[1] - box.min[1]) * (box.max[2] - box.min[2]);
}

SizeEstimate finish(double tets, SizeDriver driver)
{
  SizeEstimate e;
  e.tets = std::isfinite(tets) ? tets : kInfinity;
  e.points = e.tets / kTetsPerPoint;
  e.bytes = e.tets * kBytesPerTet;
  e.driver = driver;
  return e;
}

// Which option makes the boundary size h0 what it is.
SizeDriver meshDriver(const ImprovementOptions& o, double volumeCap)
{
  const double edgeCap = o.sizing.maxEdgeLength > 0 ? o.sizing.maxEdgeLength : kInfinity;
  if (volumeCap < kInfinity && volumeCap <= edgeCap)
    return SizeDriver::MaxVolume;
  if (edgeCap < kInfinity)
    return SizeDriver::MaxEdge;
  if (o.sizing.scale < 1)
    return SizeDriver::SizeScale;
  if (o.fieldPointOptions.alpha < 0.75)
    return SizeDriver::Alpha;
  return SizeDriver::SurfaceSpacing;
}
} // namespace

SizeEstimate estimateMeshSize(const SurfaceMesh& surface, const ImprovementOptions& o)
{
  const double triangles = surface.numberOfTriangles();
  if (!o.fieldPoints || triangles == 0)
    return finish(4.0 * triangles, SizeDriver::SurfaceSpacing);
  const FieldPointOptions& f = o.fieldPointOptions;
  const double volumeCap = f.maxVolume > 0 ? std::cbrt(f.maxVolume * 6.0 * std::sqrt(2.0)) : kInfinity;
  const double edgeCap = o.sizing.maxEdgeLength > 0 ? o.sizing.maxEdgeLength : kInfinity;
  const double cap = std::min(edgeCap, volumeCap);
  const double g = o.sizing.gradation > 1 ? o.sizing.gradation - 1 : 0;
  double area = 0;
  for (int32_t t = 0; t < surface.numberOfTriangles(); ++t)
  {
    const int32_t* v = surface.triangle(t);
    area += triangleArea(surface.point(v[0]), surface.point(v[1]), surface.point(v[2]));
  }
  // The domain as a slab of the boundary's area and the depth that gives its volume.
  const double depth = area > 0 ? domainVolume(surface) / area : 0;
  double perVolume = 0; // sum over triangles of area * integral of 1/h^3 over depth
  for (int32_t t = 0; t < surface.numberOfTriangles() && depth > 0; ++t)
  {
    const int32_t* v = surface.triangle(t);
    const double* a = surface.point(v[0]);
    const double* b = surface.point(v[1]);
    const double* c = surface.point(v[2]);
    const double spacing = (length(a, b) + length(b, c) + length(c, a)) / 3.0;
    // The cap's floor next to coarse triangles, with its depth limit (CoarseBoundaryFloor.h).
    const double s0 = std::min(spacing * o.sizing.scale, edgeCap + g * kFloorShareOfDepth * depth);
    const double h0 = std::min(s0, cap);
    if (g > 0 && s0 > cap && cap == edgeCap && std::isfinite(s0))
      perVolume += triangleArea(a, b, c) * flooredInverseCubeIntegral(s0, g, cap, depth);
    else if (h0 > 0 && std::isfinite(h0))
      perVolume += triangleArea(a, b, c) * inverseCubeIntegral(h0, g, cap, depth);
  }
  const double alphaFactor = std::pow(std::max(0.75 / f.alpha, 1.0), 3.0);
  const double tets = kTetsPerUnitVolume * alphaFactor * perVolume + 4.0 * triangles;
  return finish(tets, meshDriver(o, volumeCap));
}

SizeEstimate estimateRefineSize(const std::vector<double>& points, const std::vector<int32_t>& tets,
                                const std::vector<double>& targetSize, double alpha)
{
  const double alphaFactor = std::pow(std::max(0.75 / alpha, 1.0), 3.0);
  const size_t numPoints = points.size() / 3;
  double sum = 0;
  for (size_t t = 0; t + 3 < tets.size(); t += 4)
  {
    const double* p[4];
    double h = kInfinity;
    bool valid = true;
    for (int k = 0; k < 4; ++k)
    {
      const int32_t id = tets[t + k];
      valid = valid && id >= 0 && static_cast<size_t>(id) < numPoints;
      if (!valid)
        break;
      p[k] = points.data() + 3 * static_cast<size_t>(id);
      const double s = static_cast<size_t>(id) < targetSize.size() ? targetSize[id] : 0;
      if (s > 0 && std::isfinite(s))
        h = std::min(h, s);
    }
    double here = 1;
    if (valid && h < kInfinity)
    {
      const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
      const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
      const double w[3] = { p[3][0] - p[0][0], p[3][1] - p[0][1], p[3][2] - p[0][2] };
      const double volume = std::fabs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                                      u[2] * (v[0] * w[1] - v[1] * w[0])) /
        6.0;
      here = std::max(1.0, kTetsPerUnitVolume * alphaFactor * volume / (h * h * h));
    }
    sum += here;
  }
  return finish(sum, SizeDriver::TargetSize);
}

SizeEstimate estimateDelaunaySize(double numPoints)
{
  SizeEstimate e;
  e.points = numPoints;
  e.tets = 6.6 * numPoints;
  e.bytes = kBytesPerDelaunayPoint * numPoints;
  e.driver = SizeDriver::PointCount;
  return e;
}

} // namespace volgrid
