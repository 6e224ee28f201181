#include "SurfaceMesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace volgrid
{

int32_t SurfaceMesh::addPoint(double x, double y, double z)
{
  points.push_back(x);
  points.push_back(y);
  points.push_back(z);
  return numberOfPoints() - 1;
}

int32_t SurfaceMesh::addTriangle(int32_t a, int32_t b, int32_t c, int32_t patch)
{
  if (patch != -1 && patchIds.size() != triangles.size() / 3)
  {
    patchIds.resize(triangles.size() / 3, -1);
  }
  triangles.push_back(a);
  triangles.push_back(b);
  triangles.push_back(c);
  if (!patchIds.empty() || patch != -1)
  {
    patchIds.push_back(patch);
  }
  return numberOfTriangles() - 1;
}

void SurfaceMesh::append(const SurfaceMesh& other)
{
  const int32_t shift = numberOfPoints();
  const int32_t nt = numberOfTriangles();
  points.insert(points.end(), other.points.begin(), other.points.end());
  if (hasPatchIds() || other.hasPatchIds())
  {
    patchIds.resize(nt, -1);
    if (other.hasPatchIds())
    {
      patchIds.insert(patchIds.end(), other.patchIds.begin(), other.patchIds.end());
    }
    else
    {
      patchIds.resize(nt + other.numberOfTriangles(), -1);
    }
  }
  triangles.reserve(triangles.size() + other.triangles.size());
  for (int32_t v : other.triangles)
  {
    triangles.push_back(v + shift);
  }
  patchNames.insert(other.patchNames.begin(), other.patchNames.end());
}

void SurfaceMesh::clear()
{
  points.clear();
  triangles.clear();
  patchIds.clear();
  patchNames.clear();
}

double BoundingBox::diagonal() const
{
  if (!valid)
  {
    return 0.0;
  }
  const double dx = max[0] - min[0], dy = max[1] - min[1], dz = max[2] - min[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

void BoundingBox::add(const double* p)
{
  if (!valid)
  {
    for (int k = 0; k < 3; ++k)
    {
      min[k] = max[k] = p[k];
    }
    valid = true;
    return;
  }
  for (int k = 0; k < 3; ++k)
  {
    min[k] = std::min(min[k], p[k]);
    max[k] = std::max(max[k], p[k]);
  }
}

BoundingBox boundingBox(const SurfaceMesh& mesh, bool referencedOnly)
{
  BoundingBox box;
  if (referencedOnly)
  {
    for (int32_t v : mesh.triangles)
    {
      if (v >= 0 && v < mesh.numberOfPoints())
      {
        box.add(mesh.point(v));
      }
    }
  }
  else
  {
    for (int32_t i = 0; i < mesh.numberOfPoints(); ++i)
    {
      box.add(mesh.point(i));
    }
  }
  return box;
}

namespace
{
struct KahanSum
{
  double sum = 0, c = 0;
  void add(double v)
  {
    const double y = v - c;
    const double t = sum + y;
    c = (t - sum) - y;
    sum = t;
  }
};

double tetVolume6(const double* o, const double* a, const double* b, const double* c)
{
  const double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2];
  const double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
  const double cx = c[0] - o[0], cy = c[1] - o[1], cz = c[2] - o[2];
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}
} // namespace

double signedVolume(const SurfaceMesh& mesh)
{
  std::vector<int32_t> all(mesh.numberOfTriangles());
  std::iota(all.begin(), all.end(), 0);
  return signedVolume(mesh, all);
}

double signedVolume(const SurfaceMesh& mesh, const std::vector<int32_t>& triangleIds)
{
  BoundingBox box;
  for (int32_t t : triangleIds)
  {
    for (int k = 0; k < 3; ++k)
    {
      box.add(mesh.point(mesh.triangle(t)[k]));
    }
  }
  if (!box.valid)
  {
    return 0.0;
  }
  const double o[3] = { 0.5 * (box.min[0] + box.max[0]), 0.5 * (box.min[1] + box.max[1]),
                        0.5 * (box.min[2] + box.max[2]) };
  KahanSum s;
  for (int32_t t : triangleIds)
  {
    const int32_t* v = mesh.triangle(t);
    s.add(tetVolume6(o, mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])));
  }
  return s.sum / 6.0;
}

bool allPointsFinite(const SurfaceMesh& mesh, int32_t* firstBad)
{
  for (size_t i = 0; i < mesh.points.size(); ++i)
  {
    if (!std::isfinite(mesh.points[i]))
    {
      if (firstBad)
      {
        *firstBad = static_cast<int32_t>(i / 3);
      }
      return false;
    }
  }
  return true;
}

namespace
{
// Total order on doubles that treats -0.0 as 0.0 and puts NaN last (NaN never equals anything).
inline bool lessCoord(double a, double b)
{
  if (std::isnan(a))
  {
    return false;
  }
  if (std::isnan(b))
  {
    return true;
  }
  return a < b;
}
} // namespace

int64_t exactCoincidenceMap(const std::vector<double>& points, std::vector<int32_t>& oldToNew)
{
  const int32_t n = static_cast<int32_t>(points.size() / 3);
  std::vector<int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const double* p = points.data();
  auto lessPoint = [p](int32_t i, int32_t j)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double a = p[3 * size_t(i) + k], b = p[3 * size_t(j) + k];
      if (lessCoord(a, b))
      {
        return true;
      }
      if (lessCoord(b, a))
      {
        return false;
      }
    }
    return i < j;
  };
  auto samePoint = [p](int32_t i, int32_t j)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (!(p[3 * size_t(i) + k] == p[3 * size_t(j) + k]))
      {
        return false; // also false for NaN
      }
    }
    return true;
  };
  std::sort(order.begin(), order.end(), lessPoint);
  std::vector<int32_t> representative(n);
  for (int32_t s = 0; s < n;)
  {
    int32_t e = s + 1;
    while (e < n && samePoint(order[s], order[e]))
    {
      ++e;
    }
    for (int32_t k = s; k < e; ++k)
    {
      representative[order[k]] = order[s]; // smallest id of the group: order sorted ties by id
    }
    s = e;
  }
  oldToNew.assign(n, -1);
  int32_t next = 0;
  for (int32_t i = 0; i < n; ++i)
  {
    const int32_t r = representative[i];
    if (r == i)
    {
      oldToNew[i] = next++;
    }
    else
    {
      oldToNew[i] = oldToNew[r];
    }
  }
  return n - next;
}

void remapPoints(SurfaceMesh& mesh, const std::vector<int32_t>& oldToNew, int32_t newCount)
{
  std::vector<double> pts(3 * size_t(newCount), 0.0);
  std::vector<char> set(newCount, 0);
  for (int32_t i = 0; i < mesh.numberOfPoints(); ++i)
  {
    const int32_t j = oldToNew[i];
    if (j >= 0 && !set[j])
    {
      set[j] = 1;
      for (int k = 0; k < 3; ++k)
      {
        pts[3 * size_t(j) + k] = mesh.points[3 * size_t(i) + k];
      }
    }
  }
  mesh.points.swap(pts);
  for (int32_t& v : mesh.triangles)
  {
    v = (v >= 0 && v < static_cast<int32_t>(oldToNew.size())) ? oldToNew[v] : -1;
  }
}

MergeResult mergeCoincidentPoints(SurfaceMesh& mesh)
{
  MergeResult result;
  result.mergedPoints = exactCoincidenceMap(mesh.points, result.oldToNew);
  if (result.mergedPoints > 0)
  {
    remapPoints(mesh, result.oldToNew, mesh.numberOfPoints() - static_cast<int32_t>(result.mergedPoints));
  }
  return result;
}

int64_t removeUnreferencedPoints(SurfaceMesh& mesh, std::vector<int32_t>* oldToNewOut)
{
  const int32_t n = mesh.numberOfPoints();
  std::vector<int32_t> oldToNew(n, -1);
  for (int32_t v : mesh.triangles)
  {
    if (v >= 0 && v < n)
    {
      oldToNew[v] = 0;
    }
  }
  int32_t next = 0;
  for (int32_t i = 0; i < n; ++i)
  {
    if (oldToNew[i] == 0)
    {
      oldToNew[i] = next++;
    }
  }
  if (next != n)
  {
    remapPoints(mesh, oldToNew, next);
  }
  if (oldToNewOut)
  {
    oldToNewOut->swap(oldToNew);
  }
  return n - next;
}

} // namespace volgrid
