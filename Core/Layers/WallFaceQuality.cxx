// Wall-edge skewness and non-orthogonality: the thin-layer limits of OpenFOAM's measures of prism side faces.
#include "WallFaceQuality.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace volgrid
{
namespace
{
struct Vec
{
  double x, y, z;
};
Vec operator-(Vec a, Vec b)
{
  return { a.x - b.x, a.y - b.y, a.z - b.z };
}
Vec operator+(Vec a, Vec b)
{
  return { a.x + b.x, a.y + b.y, a.z + b.z };
}
Vec operator*(double s, Vec a)
{
  return { s * a.x, s * a.y, s * a.z };
}
double dot(Vec a, Vec b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
double norm(Vec a)
{
  return std::sqrt(dot(a, a));
}
Vec cross(Vec a, Vec b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
Vec unit(Vec a)
{
  const double n = norm(a);
  return n > 0 ? (1 / n) * a : Vec{ 0, 0, 0 };
}

Vec pointAt(const std::vector<double>& points, int32_t v)
{
  return { points[3 * size_t(v)], points[3 * size_t(v) + 1], points[3 * size_t(v) + 2] };
}

struct Triangle
{
  Vec centroid, normal; // normal: unit, 0 when degenerate
};

Triangle triangleAt(const std::vector<double>& points, const int32_t* t)
{
  const Vec a = pointAt(points, t[0]), b = pointAt(points, t[1]), c = pointAt(points, t[2]);
  return { { (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3 }, unit(cross(b - a, c - a)) };
}

// The skewness of the side face over edge ab between the triangles with centroids p (owner) and q.
double edgeSkewness(Vec a, Vec b, Vec p, Vec q)
{
  const Vec face = 0.5 * Vec{ a.x + b.x, a.y + b.y, a.z + b.z };
  const Vec d = q - p, ownerToFace = face - p, along = b - a;
  const double length = norm(along);
  if (length == 0)
    return 0;
  const Vec e = (1 / length) * along;
  Vec normal = d - dot(d, e) * e; // the side face's normal: across the edge, in the plane of e and d
  const double nn = norm(normal);
  if (nn == 0 || dot(normal, d) == 0)
    return 0;
  normal = (1 / nn) * normal;
  const Vec crossing = (dot(normal, ownerToFace) / dot(normal, d)) * d;
  const Vec miss = ownerToFace - crossing; // face centre to the crossing point
  const double missLength = norm(miss);
  if (missLength == 0)
    return 0;
  const double extent = std::max(0.2 * norm(d), std::abs(dot((1 / missLength) * miss, a - face)));
  return missLength / extent;
}

// The non-orthogonality (degrees) of the side face over edge ab between triangles p and q: the angle between
// the line of their centroids and the face's normal, across the edge and across the marching direction (the
// mean of the two normals; 0 where they cancel, a knife edge, where no single side face stands).
double edgeNonOrthogonality(Vec a, Vec b, const Triangle& p, const Triangle& q)
{
  const Vec march = p.normal + q.normal;
  const Vec faceNormal = unit(cross(b - a, march));
  const Vec d = q.centroid - p.centroid;
  const double length = norm(d);
  if (dot(faceNormal, faceNormal) == 0 || length == 0)
    return 0;
  const double c = std::min(1.0, std::abs(dot(faceNormal, d)) / length);
  return std::acos(c) * 180.0 / 3.14159265358979323846;
}

void account(WallEdgeExtreme& e, double value, double limit, Vec a, Vec b)
{
  e.edgesOverLimit += value > limit;
  if (value > e.worst)
  {
    e.worst = value;
    e.worstPoint[0] = 0.5 * (a.x + b.x);
    e.worstPoint[1] = 0.5 * (a.y + b.y);
    e.worstPoint[2] = 0.5 * (a.z + b.z);
  }
}

// Calls visit(a, b, p, q) once per edge ab shared by exactly two of `triangles`, p and q its triangles.
template <typename Visit>
void forEachInteriorEdge(const std::vector<double>& points, const std::vector<int32_t>& triangles, Visit visit)
{
  // Sorted edge -> (first triangle, count).
  std::unordered_map<uint64_t, std::pair<int32_t, int>> edges;
  const size_t n = triangles.size() / 3;
  edges.reserve(3 * n);
  const auto key = [](int32_t a, int32_t b)
  { return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b)); };
  for (size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i)
      ++edges.try_emplace(key(triangles[3 * t + i], triangles[3 * t + (i + 1) % 3]), int32_t(t), 0).first->second.second;
  for (size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i)
    {
      const int32_t a = triangles[3 * t + i], b = triangles[3 * t + (i + 1) % 3];
      const auto& entry = edges.find(key(a, b))->second;
      if (entry.second == 2 && entry.first != int32_t(t))
        visit(a, b, triangleAt(points, &triangles[3 * size_t(entry.first)]), triangleAt(points, &triangles[3 * t]));
    }
}
} // namespace

WallFaceQuality wallFaceQuality(const std::vector<double>& points, const std::vector<int32_t>& triangles,
                                double skewnessLimit, double nonOrthogonalityLimitDegrees)
{
  WallFaceQuality result;
  forEachInteriorEdge(points, triangles,
                      [&](int32_t ia, int32_t ib, const Triangle& p, const Triangle& q)
                      {
                        const Vec a = pointAt(points, ia), b = pointAt(points, ib);
                        account(result.skewness, edgeSkewness(a, b, p.centroid, q.centroid), skewnessLimit, a, b);
                        account(result.nonOrthogonality, edgeNonOrthogonality(a, b, p, q),
                                nonOrthogonalityLimitDegrees, a, b);
                      });
  return result;
}

std::vector<int32_t> skewedWallEdges(const std::vector<double>& points, const std::vector<int32_t>& triangles,
                                     double skewnessLimit)
{
  std::vector<int32_t> edges;
  forEachInteriorEdge(points, triangles,
                      [&](int32_t a, int32_t b, const Triangle& p, const Triangle& q)
                      {
                        if (edgeSkewness(pointAt(points, a), pointAt(points, b), p.centroid, q.centroid) > skewnessLimit)
                          edges.insert(edges.end(), { a, b });
                      });
  return edges;
}

std::vector<std::string> wallFaceWarnings(const WallFaceQuality& quality)
{
  std::vector<std::string> warnings;
  char text[600];
  const WallEdgeExtreme& skew = quality.skewness;
  if (skew.edgesOverLimit > 0)
  {
    std::snprintf(text, sizeof text,
                  "%lld wall edge(s) have a skewness above 4 in the surface itself (worst %.3g at (%.6g, %.6g, %.6g), "
                  "between two triangles whose centroids miss the edge): every prism side face over such an edge "
                  "inherits it, so OpenFOAM's checkMesh reports highly skew faces whatever the layers; refine the "
                  "wall triangulation there",
                  (long long)skew.edgesOverLimit, skew.worst, skew.worstPoint[0], skew.worstPoint[1],
                  skew.worstPoint[2]);
    warnings.push_back(text);
  }
  const WallEdgeExtreme& ortho = quality.nonOrthogonality;
  if (ortho.edgesOverLimit > 0)
  {
    std::snprintf(text, sizeof text,
                  "%lld wall edge(s) have a non-orthogonality above 70 deg in the surface itself (worst %.3g deg at "
                  "(%.6g, %.6g, %.6g), between two triangles whose centroids line up along the edge rather than "
                  "across it): every prism side face over such an edge inherits it, so OpenFOAM's checkMesh counts "
                  "about that many severely non-orthogonal faces in every layer; re-triangulate the wall there with "
                  "triangles closer to equilateral",
                  (long long)ortho.edgesOverLimit, ortho.worst, ortho.worstPoint[0], ortho.worstPoint[1],
                  ortho.worstPoint[2]);
    warnings.push_back(text);
  }
  return warnings;
}

} // namespace volgrid
