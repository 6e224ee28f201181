// Where a point that splits a bad tet may go (BadTetSplitting.h, InteriorPolish.h): the positions each
// search starts from before its compass search refines the best one.
#pragma once

#include <array>
#include <cmath>
#include <vector>

namespace volgrid
{

using SplitPoint = std::array<double, 3>;

namespace splitting
{

inline double sqDist(const double* a, const double* b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}

// Circumcentre of tet p[0..3]; false when flat.
inline bool circumcentre(const double* const p[4], double* out)
{
  double e[3][3], n[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      e[i][k] = p[i + 1][k] - p[0][k];
  auto cross = [](const double* x, const double* y, double* o)
  {
    o[0] = x[1] * y[2] - x[2] * y[1];
    o[1] = x[2] * y[0] - x[0] * y[2];
    o[2] = x[0] * y[1] - x[1] * y[0];
  };
  cross(e[1], e[2], n[0]);
  cross(e[2], e[0], n[1]);
  cross(e[0], e[1], n[2]);
  const double den = 2 * (e[0][0] * n[0][0] + e[0][1] * n[0][1] + e[0][2] * n[0][2]);
  if (!(den != 0))
    return false;
  for (int k = 0; k < 3; ++k)
  {
    double num = 0;
    for (int i = 0; i < 3; ++i)
      num += (e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2]) * n[i][k];
    out[k] = p[0][k] + num / den;
  }
  return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]);
}

// n = (b - a) x (c - a); returns its length.
inline double triangleNormal(const double* a, const double* b, const double* c, double n[3])
{
  double u[3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = b[k] - a[k];
    w[k] = c[k] - a[k];
  }
  n[0] = u[1] * w[2] - u[2] * w[1];
  n[1] = u[2] * w[0] - u[0] * w[2];
  n[2] = u[0] * w[1] - u[1] * w[0];
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Appends the edge midpoints, the centroid and the circumcentre of tet p; returns its mean edge length.
inline double addCentres(const double* const p[4], std::vector<SplitPoint>& cand)
{
  double lsum = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
    {
      lsum += std::sqrt(sqDist(p[i], p[j]));
      cand.push_back({ (p[i][0] + p[j][0]) / 2, (p[i][1] + p[j][1]) / 2, (p[i][2] + p[j][2]) / 2 });
    }
  cand.push_back({ (p[0][0] + p[1][0] + p[2][0] + p[3][0]) / 4, (p[0][1] + p[1][1] + p[2][1] + p[3][1]) / 4,
                   (p[0][2] + p[1][2] + p[2][2] + p[3][2]) / 4 });
  SplitPoint cc;
  if (circumcentre(p, cc.data()))
    cand.push_back(cc);
  return lsum / 6;
}

// Appends the points over each face of tet p, on both sides, at the height of a regular tet and at half.
inline void addFaceApexes(const double* const p[4], std::vector<SplitPoint>& cand)
{
  for (int i = 0; i < 4; ++i)
  {
    // Face i (the three vertices other than i), its normal towards vertex i, apex at the regular height.
    const double* f[3];
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != i)
        f[m++] = p[k];
    double n[3];
    const double nn = triangleNormal(f[0], f[1], f[2], n);
    if (!(nn > 0))
      continue;
    const double side = (p[i][0] - f[0][0]) * n[0] + (p[i][1] - f[0][1]) * n[1] + (p[i][2] - f[0][2]) * n[2];
    const double h =
      0.8165 * (std::sqrt(sqDist(f[0], f[1])) + std::sqrt(sqDist(f[1], f[2])) + std::sqrt(sqDist(f[2], f[0]))) / 3;
    // Both sides (beyond an unconstrained face the point may replace t together with its neighbour),
    // at the regular height and at half of it.
    for (const double scale : { 1.0, -1.0, 0.5, -0.5 })
    {
      const double sgn = (side >= 0 ? h : -h) * scale / nn;
      SplitPoint apex;
      for (int k = 0; k < 3; ++k)
        apex[k] = (f[0][k] + f[1][k] + f[2][k]) / 3 + sgn * n[k];
      cand.push_back(apex);
    }
  }
}

} // namespace splitting
} // namespace volgrid
