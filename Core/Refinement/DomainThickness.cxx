#include "DomainThickness.h"

#include <algorithm>
#include <cmath>

namespace volgrid
{
namespace
{
void outwardNormal(const TetMesh& mesh, int32_t t, int face, double n[3], const double** on)
{
  // faceVertices(t, i) sees vertex i on the side of its right-hand normal: outward is the other way.
  int32_t f[3];
  mesh.faceVertices(t, face, f);
  const double *a = mesh.point(f[0]), *b = mesh.point(f[1]), *c = mesh.point(f[2]);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  n[0] = -(u[1] * v[2] - u[2] * v[1]);
  n[1] = -(u[2] * v[0] - u[0] * v[2]);
  n[2] = -(u[0] * v[1] - u[1] * v[0]);
  *on = a;
}

double dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The star of v (tets holding it) from one of them, by face adjacency around v.
void starOf(const TetMesh& mesh, int32_t v, int32_t t0, std::vector<int32_t>& star)
{
  star.assign(1, t0);
  for (size_t k = 0; k < star.size() && star.size() < 4096; ++k)
  {
    const int32_t t = star[k];
    const int li = mesh.localIndex(t, v);
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = i == li ? -1 : mesh.neighbor(t, i);
      bool seen = u < 0;
      for (size_t j = 0; j < star.size() && !seen; ++j)
        seen = star[j] == u;
      if (!seen)
        star.push_back(u);
    }
  }
}

// Where the ray s + lambda dir crosses the plane of face `face` of t going out of t: lambda, or NaN when
// the ray does not go out through that plane.
double crossing(const TetMesh& mesh, int32_t t, int face, const double* s, const double* dir)
{
  double n[3];
  const double* on;
  outwardNormal(mesh, t, face, n, &on);
  const double towards = dot(n, dir);
  if (!(towards > 0))
    return NAN;
  const double d[3] = { on[0] - s[0], on[1] - s[1], on[2] - s[2] };
  return dot(n, d) / towards;
}

// The ray from s along dir, through the tets from `t` (entered through its face `entry`) until a face
// without a neighbour: the distance to it, 0 when the walk gets lost.
double walk(const TetMesh& mesh, const double* s, const double* dir, int32_t t, int entry)
{
  for (int step = 0; step < 100000; ++step)
  {
    int exit = -1;
    double best = INFINITY;
    for (int i = 0; i < 4; ++i)
    {
      const double lambda = i == entry ? NAN : crossing(mesh, t, i, s, dir);
      if (lambda < best)
      {
        best = lambda;
        exit = i;
      }
    }
    if (exit < 0 || !std::isfinite(best))
      return 0;
    const int32_t next = mesh.neighbor(t, exit);
    if (next < 0)
      return std::max(0.0, best);
    entry = mesh.mirrorFace(t, exit);
    t = next;
  }
  return 0;
}
} // namespace

std::vector<double> inwardThickness(const TetMesh& mesh, int32_t count)
{
  std::vector<double> thickness(static_cast<size_t>(std::max(count, 0)), 0.0);
  std::vector<int32_t> anyTet(thickness.size(), -1);
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int32_t v = mesh.vertex(t, i);
        if (v >= 0 && v < count)
          anyTet[v] = t;
      }
    });
  std::vector<int32_t> star;
  for (int32_t v = 0; v < count; ++v)
  {
    if (anyTet[v] < 0)
      continue;
    starOf(mesh, v, anyTet[v], star);
    const double* s = mesh.point(v);
    // Inward: against the area-weighted outward normals of the boundary faces at v (none for an interior
    // vertex: towards its tets' centroids).
    double dir[3] = { 0, 0, 0 };
    for (int32_t t : star)
    {
      const int li = mesh.localIndex(t, v);
      for (int i = 0; i < 4; ++i)
        if (i != li && mesh.neighbor(t, i) < 0)
        {
          double n[3];
          const double* on;
          outwardNormal(mesh, t, i, n, &on);
          for (int k = 0; k < 3; ++k)
            dir[k] -= n[k];
        }
    }
    if (!(dot(dir, dir) > 0))
      for (int32_t t : star)
        for (int i = 0; i < 4; ++i)
          for (int k = 0; k < 3; ++k)
            dir[k] += (mesh.point(mesh.vertex(t, i))[k] - s[k]) / 4;
    const double len = std::sqrt(dot(dir, dir));
    if (!(len > 0))
      continue;
    for (double& x : dir)
      x /= len;
    // The first tet: the star tet whose faces at v the ray leaves least (the one it runs into).
    int32_t first = -1;
    double roomiest = -INFINITY;
    for (int32_t t : star)
    {
      const int li = mesh.localIndex(t, v);
      double worst = INFINITY;
      for (int i = 0; i < 4; ++i)
      {
        if (i == li)
          continue;
        double n[3];
        const double* on;
        outwardNormal(mesh, t, i, n, &on);
        const double nn = std::sqrt(dot(n, n));
        if (nn > 0)
          worst = std::min(worst, -dot(n, dir) / nn);
      }
      if (worst > roomiest)
      {
        roomiest = worst;
        first = t;
      }
    }
    if (first < 0)
      continue;
    // It leaves that tet through the face opposite v.
    const int li = mesh.localIndex(first, v);
    const int32_t next = mesh.neighbor(first, li);
    if (next >= 0)
      thickness[v] = walk(mesh, s, dir, next, mesh.mirrorFace(first, li));
    else
    {
      const double lambda = crossing(mesh, first, li, s, dir);
      thickness[v] = lambda > 0 ? lambda : 0.0;
    }
  }
  return thickness;
}

} // namespace volgrid
