// Marching directions, layer points and the exact validity checks of the columns.
#include "BoundaryLayersMarching.h"

#include "Predicates.h"
#include "SurfaceChecks.h"

#include <algorithm>
#include <cmath>

namespace volgrid
{
namespace layers_detail
{
namespace
{
void sub(const double* a, const double* b, double* out)
{
  for (int i = 0; i < 3; ++i)
    out[i] = a[i] - b[i];
}
void cross(const double* u, const double* v, double* out)
{
  out[0] = u[1] * v[2] - u[2] * v[1];
  out[1] = u[2] * v[0] - u[0] * v[2];
  out[2] = u[0] * v[1] - u[1] * v[0];
}
double dot(const double* u, const double* v)
{
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}
bool normalize(double* v)
{
  const double n = std::sqrt(dot(v, v));
  if (!(n > 0))
    return false;
  for (int i = 0; i < 3; ++i)
    v[i] /= n;
  return true;
}
double angle(const double* apex, const double* p, const double* q)
{
  double u[3], v[3];
  sub(p, apex, u);
  sub(q, apex, v);
  if (!normalize(u) || !normalize(v))
    return 0;
  return std::acos(std::max(-1.0, std::min(1.0, dot(u, v))));
}

// Unit normal of each oriented wall triangle.
std::vector<double> faceNormals(const Walls& walls)
{
  const double* p = walls.points->data();
  const size_t n = walls.triangles.size() / 3;
  std::vector<double> normals(3 * n, 0.0);
  for (size_t t = 0; t < n; ++t)
  {
    const int32_t* v = walls.triangles.data() + 3 * t;
    double u[3], w[3];
    sub(p + 3 * size_t(v[1]), p + 3 * size_t(v[0]), u);
    sub(p + 3 * size_t(v[2]), p + 3 * size_t(v[0]), w);
    cross(u, w, normals.data() + 3 * t);
    normalize(normals.data() + 3 * t);
  }
  return normals;
}
} // namespace

void columnNeighbours(const Walls& walls, std::vector<int32_t>& start, std::vector<int32_t>& list)
{
  const size_t nc = walls.layeredPoints.size();
  std::vector<std::vector<int32_t>> around(nc);
  for (size_t t = 0; t < walls.triangles.size(); t += 3)
    for (int i = 0; i < 3; ++i)
    {
      const int32_t a = walls.column[walls.triangles[t + i]], b = walls.column[walls.triangles[t + (i + 1) % 3]];
      around[a].push_back(b);
      around[b].push_back(a);
    }
  start.assign(nc + 1, 0);
  list.clear();
  for (size_t c = 0; c < nc; ++c)
  {
    std::sort(around[c].begin(), around[c].end());
    around[c].erase(std::unique(around[c].begin(), around[c].end()), around[c].end());
    list.insert(list.end(), around[c].begin(), around[c].end());
    start[c + 1] = static_cast<int32_t>(list.size());
  }
}

std::vector<double> marchingDirections(const Walls& walls, int passes)
{
  const double* p = walls.points->data();
  const size_t nc = walls.layeredPoints.size(), nt = walls.triangles.size() / 3;
  const std::vector<double> normals = faceNormals(walls);
  std::vector<double> dir(3 * nc, 0.0);
  std::vector<int32_t> faceStart(nc + 1, 0), faces(3 * nt);
  for (size_t k = 0; k < 3 * nt; ++k)
    ++faceStart[walls.column[walls.triangles[k]] + 1];
  for (size_t c = 0; c < nc; ++c)
    faceStart[c + 1] += faceStart[c];
  std::vector<int32_t> fill(faceStart.begin(), faceStart.end() - 1);
  for (size_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i)
    {
      const int32_t* v = walls.triangles.data() + 3 * t;
      const int32_t c = walls.column[v[i]];
      faces[fill[c]++] = static_cast<int32_t>(t);
      const double w = angle(p + 3 * size_t(v[i]), p + 3 * size_t(v[(i + 1) % 3]), p + 3 * size_t(v[(i + 2) % 3]));
      for (int d = 0; d < 3; ++d)
        dir[3 * c + d] += w * normals[3 * t + d];
    }
  for (size_t c = 0; c < nc; ++c)
    normalize(dir.data() + 3 * c);
  std::vector<int32_t> start, list;
  columnNeighbours(walls, start, list);
  std::vector<double> next(dir.size());
  for (int pass = 0; pass < passes; ++pass)
  {
    for (size_t c = 0; c < nc; ++c)
    {
      double mean[3] = { 0, 0, 0 };
      for (int32_t k = start[c]; k < start[c + 1]; ++k)
        for (int d = 0; d < 3; ++d)
          mean[d] += dir[3 * size_t(list[k]) + d];
      const double n = std::max(1, start[c + 1] - start[c]);
      for (int d = 0; d < 3; ++d)
        next[3 * c + d] = dir[3 * c + d] + mean[d] / n;
      if (!normalize(next.data() + 3 * c))
        std::copy(dir.begin() + 3 * c, dir.begin() + 3 * c + 3, next.begin() + 3 * c);
    }
    dir.swap(next);
  }
  // Smoothing may leave a direction oblique to a face at a sharp edge (a trailing edge): raise the smallest
  // dot product with the incident faces by subgradient steps, keeping the best direction seen.
  for (size_t c = 0; c < nc; ++c)
  {
    const auto worstOf = [&](const double* d, int32_t& face)
    {
      double worst = 2;
      for (int32_t k = faceStart[c]; k < faceStart[c + 1]; ++k)
      {
        double v[3] = { d[0], d[1], d[2] };
        if (walls.slipAxis[c] >= 0)
          v[walls.slipAxis[c]] = 0;
        normalize(v);
        const double x = dot(v, normals.data() + 3 * size_t(faces[k]));
        if (x < worst)
          worst = x, face = faces[k];
      }
      return worst;
    };
    int32_t face = -1;
    double best[3] = { dir[3 * c], dir[3 * c + 1], dir[3 * c + 2] }, d[3] = { best[0], best[1], best[2] };
    double bestWorst = worstOf(best, face);
    for (int round = 0; round < 200 && bestWorst < 0.3 && face >= 0; ++round)
    {
      const double step = 0.5 / (1 + round);
      for (int k = 0; k < 3; ++k)
        d[k] += step * normals[3 * size_t(face) + k];
      normalize(d);
      const double worst = worstOf(d, face);
      if (worst > bestWorst)
      {
        bestWorst = worst;
        std::copy(d, d + 3, best);
      }
    }
    std::copy(best, best + 3, dir.begin() + 3 * c);
  }
  // On a symmetry plane: exactly in the plane (a zero component keeps the coordinate bit for bit).
  for (size_t c = 0; c < nc; ++c)
    if (walls.slipAxis[c] >= 0)
    {
      dir[3 * c + walls.slipAxis[c]] = 0;
      normalize(dir.data() + 3 * c);
    }
  return dir;
}

std::vector<double> layerOffsets(const LayerOptions& options)
{
  std::vector<double> offsets(options.layers);
  double height = options.firstHeight, sum = 0;
  for (int k = 0; k < options.layers; ++k)
  {
    sum += height;
    offsets[k] = sum;
    height *= options.growth;
  }
  return offsets;
}

void placeLayerPoints(const Walls& walls, const std::vector<double>& directions, const std::vector<double>& offsets,
                      const std::vector<double>& scale, std::vector<double>& points)
{
  const size_t base = walls.points->size(), layers = offsets.size();
  points.resize(base + 3 * walls.layeredPoints.size() * layers);
  std::copy(walls.points->begin(), walls.points->end(), points.begin());
  for (size_t c = 0; c < walls.layeredPoints.size(); ++c)
  {
    const double* origin = walls.points->data() + 3 * size_t(walls.layeredPoints[c]);
    for (size_t k = 0; k < layers; ++k)
      for (int d = 0; d < 3; ++d)
        points[base + 3 * (c * layers + k) + d] = origin[d] + scale[c] * offsets[k] * directions[3 * c + d];
  }
}

int32_t layerPoint(const Walls& walls, int32_t surfacePoint, int k, int layers)
{
  const int32_t c = walls.column[surfacePoint];
  if (k < 0 || (!walls.collapsed.empty() && walls.collapsed[c]))
    return surfacePoint;
  const int32_t base = static_cast<int32_t>(walls.points->size() / 3);
  return base + c * layers + k;
}

namespace
{
// Marks the columns of surface points v[0..2] as bad, except collapsed ones (they cannot go lower).
void markColumns(const Walls& walls, const int32_t* v, std::vector<char>& bad)
{
  for (int i = 0; i < 3; ++i)
  {
    const int32_t c = walls.column[v[i]];
    if (walls.collapsed.empty() || !walls.collapsed[c])
      bad[c] = 1;
  }
}
} // namespace

std::vector<int32_t> invertedColumns(const Walls& walls, const std::vector<double>& points, int layers)
{
  std::vector<char> bad(walls.layeredPoints.size(), 0);
  for (size_t t = 0; t < walls.triangles.size(); t += 3)
  {
    const int32_t* v = walls.triangles.data() + t;
    for (int k = 0; k < layers; ++k)
    {
      int32_t q[6];
      for (int i = 0; i < 3; ++i)
      {
        q[i] = layerPoint(walls, v[i], k - 1, layers);
        q[i + 3] = layerPoint(walls, v[i], k, layers);
      }
      if (!layerCellIsValid(q, points.data()))
      {
        markColumns(walls, v, bad);
        break;
      }
    }
  }
  std::vector<int32_t> out;
  for (size_t c = 0; c < bad.size(); ++c)
    if (bad[c])
      out.push_back(static_cast<int32_t>(c));
  return out;
}

std::vector<int32_t> movedOtherTriangles(const Walls& walls, int layers)
{
  std::vector<int32_t> moved = walls.otherTriangles;
  for (int32_t& v : moved)
    if (walls.column[v] >= 0)
      v = layerPoint(walls, v, layers - 1, layers);
  return moved;
}

std::vector<int32_t> collidingColumns(const Walls& walls, const std::vector<double>& points, int layers, int threads)
{
  std::vector<char> bad(walls.layeredPoints.size(), 0);
  const std::vector<int32_t> moved = movedOtherTriangles(walls, layers);
  const auto markMoved = [&](size_t k)
  {
    for (int i = 0; i < 3; ++i)
      if (walls.column[walls.otherTriangles[k + i]] >= 0)
        bad[walls.column[walls.otherTriangles[k + i]]] = 1;
  };
  // A plane triangle whose layered corners moved must keep its orientation in the plane (exact).
  for (size_t k = 0; k < moved.size(); k += 3)
    if (moved[k] != walls.otherTriangles[k] || moved[k + 1] != walls.otherTriangles[k + 1] ||
        moved[k + 2] != walls.otherTriangles[k + 2])
    {
      int axis = -1;
      for (int i = 0; i < 3 && axis < 0; ++i)
        if (walls.column[walls.otherTriangles[k + i]] >= 0)
          axis = walls.slipAxis[walls.column[walls.otherTriangles[k + i]]];
      const auto at = [&](int32_t id) { return points.data() + 3 * size_t(id); };
      const int before = predicates::orient2dProjected(at(walls.otherTriangles[k]), at(walls.otherTriangles[k + 1]),
                                                       at(walls.otherTriangles[k + 2]), axis);
      const int after = predicates::orient2dProjected(at(moved[k]), at(moved[k + 1]), at(moved[k + 2]), axis);
      if (after == 0 || after != before)
        markMoved(k);
    }
  SurfaceMesh check;
  check.points = points;
  check.triangles = walls.triangles;
  const size_t firstOther = check.triangles.size() / 3;
  check.triangles.insert(check.triangles.end(), moved.begin(), moved.end());
  const size_t firstTop = check.triangles.size() / 3;
  std::vector<size_t> topWall; // the wall triangle under each top triangle checked
  for (size_t t = 0; t < walls.triangles.size(); t += 3)
  {
    int32_t top[3];
    for (int i = 0; i < 3; ++i)
      top[i] = layerPoint(walls, walls.triangles[t + i], layers - 1, layers);
    if (top[0] == walls.triangles[t] && top[1] == walls.triangles[t + 1] && top[2] == walls.triangles[t + 2])
      continue; // every corner collapsed: the top is the wall triangle itself
    check.triangles.insert(check.triangles.end(), top, top + 3);
    topWall.push_back(t);
  }
  SurfaceCheckOptions options;
  options.nesting = false;
  options.threads = threads;
  const SurfaceCheckReport report = checkSurface(check, options);
  const uint8_t crossing = TriangleSelfIntersecting | TriangleShellIntersecting | TriangleDegenerate;
  for (size_t t = firstOther; t < firstTop; ++t)
    if (report.triangleFlags[t] & crossing)
      markMoved(3 * (t - firstOther));
  for (size_t t = firstTop; t < report.triangleFlags.size(); ++t)
    if (report.triangleFlags[t] & crossing)
      markColumns(walls, walls.triangles.data() + topWall[t - firstTop], bad);
  std::vector<int32_t> out;
  for (size_t c = 0; c < bad.size(); ++c)
    if (bad[c])
      out.push_back(static_cast<int32_t>(c));
  return out;
}

} // namespace layers_detail
} // namespace volgrid
