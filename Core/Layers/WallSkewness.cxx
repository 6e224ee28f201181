// Wall-edge skewness: the thin-layer limit of OpenFOAM's face skewness of prism side faces.
#include "WallSkewness.h"

#include <algorithm>
#include <cmath>
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

Vec pointAt(const std::vector<double>& points, int32_t v)
{
  return { points[3 * size_t(v)], points[3 * size_t(v) + 1], points[3 * size_t(v) + 2] };
}

Vec centroid(const std::vector<double>& points, const int32_t* t)
{
  const Vec a = pointAt(points, t[0]), b = pointAt(points, t[1]), c = pointAt(points, t[2]);
  return { (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3 };
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
} // namespace

WallSkewness wallSkewness(const std::vector<double>& points, const std::vector<int32_t>& triangles, double limit)
{
  WallSkewness result;
  // Sorted edge -> (first triangle, count).
  std::unordered_map<uint64_t, std::pair<int32_t, int>> edges;
  const size_t n = triangles.size() / 3;
  edges.reserve(3 * n);
  const auto key = [](int32_t a, int32_t b)
  { return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b)); };
  for (size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i)
    {
      auto& entry =
        edges.try_emplace(key(triangles[3 * t + i], triangles[3 * t + (i + 1) % 3]), int32_t(t), 0).first->second;
      if (++entry.second != 2 || entry.first == int32_t(t))
        continue;
      const int32_t a = triangles[3 * t + i], b = triangles[3 * t + (i + 1) % 3];
      const double s =
        edgeSkewness(pointAt(points, a), pointAt(points, b), centroid(points, &triangles[3 * size_t(entry.first)]),
                     centroid(points, &triangles[3 * t]));
      result.edgesOverLimit += s > limit;
      if (s > result.worst)
      {
        result.worst = s;
        const Vec pa = pointAt(points, a), pb = pointAt(points, b);
        result.worstPoint[0] = 0.5 * (pa.x + pb.x);
        result.worstPoint[1] = 0.5 * (pa.y + pb.y);
        result.worstPoint[2] = 0.5 * (pa.z + pb.z);
      }
    }
  return result;
}

} // namespace volgrid
