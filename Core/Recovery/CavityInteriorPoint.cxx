// CavityInteriorPoint (CavityInteriorPoint.h): candidates near p, then the kernel's Chebyshev centre.
#include "CavityInteriorPoint.h"

#include "Predicates.h"
#include "Quality.h"

#include <algorithm>
#include <cmath>

namespace volgrid
{

using predicates::orient3d;

bool CavityInteriorPoint::find(int32_t p, const std::vector<std::array<int32_t, 3>>& faces, double* out)
{
  const double* P = m_.point(p);
  if (faces.empty())
    return false;
  // Unit inward normals, the distance of p from each face plane and a length scale.
  const size_t nf = faces.size();
  normals_.assign(nf, {});
  std::vector<double> dist(nf, 0);
  double L = 0, cen[3] = { 0, 0, 0 };
  for (size_t i = 0; i < nf; ++i)
  {
    const double *A = m_.point(faces[i][0]), *B = m_.point(faces[i][1]), *C = m_.point(faces[i][2]);
    double u[3], v[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = B[k] - A[k];
      v[k] = C[k] - A[k];
      cen[k] += (A[k] + B[k] + C[k]) / (3.0 * static_cast<double>(nf));
    }
    // orient3d(A,B,C,X) > 0  <=>  (X - A) . ((B - A) x (C - A)) > 0 (Predicates.h).
    double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (nn > 0)
      for (int k = 0; k < 3; ++k)
        n[k] /= nn;
    normals_[i] = { { n[0], n[1], n[2] } };
    dist[i] = (P[0] - A[0]) * n[0] + (P[1] - A[1]) * n[1] + (P[2] - A[2]) * n[2];
    for (const double* X : { A, B, C })
      L = std::max(
        L, std::sqrt((X[0] - P[0]) * (X[0] - P[0]) + (X[1] - P[1]) * (X[1] - P[1]) + (X[2] - P[2]) * (X[2] - P[2])));
  }
  if (!(L > 0))
    return false;
  // Mean normal of the faces (nearly) through p.
  double dir[3] = { 0, 0, 0 };
  double dmin = 1e300;
  for (size_t i = 0; i < nf; ++i)
    dmin = std::min(dmin, std::fabs(dist[i]));
  for (size_t i = 0; i < nf; ++i)
    if (std::fabs(dist[i]) <= dmin + 1e-9 * L)
      for (int k = 0; k < 3; ++k)
        dir[k] += normals_[i][k];
  const double dl = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  std::vector<std::array<double, 3>>& cands = cands_;
  cands.clear();
  for (double t : { 1.0, 0.5, 0.25 })
    cands.push_back({ { P[0] + t * (cen[0] - P[0]), P[1] + t * (cen[1] - P[1]), P[2] + t * (cen[2] - P[2]) } });
  if (dl > 0)
  {
    double delta = 0.25 * L;
    for (int k = 0; k < 40; ++k, delta *= 0.5)
      cands.push_back({ { P[0] + delta * dir[0] / dl, P[1] + delta * dir[1] / dl, P[2] + delta * dir[2] / dl } });
  }
  for (auto& fc : faces)
  {
    double g[3];
    for (int k = 0; k < 3; ++k)
      g[k] = (m_.point(fc[0])[k] + m_.point(fc[1])[k] + m_.point(fc[2])[k] + P[k]) / 4.0;
    for (double t : { 1.0, 0.1, 0.001 })
      cands.push_back({ { P[0] + t * (g[0] - P[0]), P[1] + t * (g[1] - P[1]), P[2] + t * (g[2] - P[2]) } });
  }
  if (pickCandidate(faces, out))
    return true;
  // Kernel search: maximise r subject to n_i . (x - P) - r * L >= -dist_i (x near P, scaled by L).
  double y[3];
  if (!chebyshevCentre(dist, L, y))
    return false;
  cands.clear();
  for (double t : { 1.0, 0.5, 0.25, 0.125, 1.0 / 16, 1.0 / 64, 1.0 / 256, 1.0 / 4096 })
    cands.push_back({ { P[0] + t * L * y[0], P[1] + t * L * y[1], P[2] + t * L * y[2] } });
  return pickCandidate(faces, out);
}

bool CavityInteriorPoint::pickCandidate(const std::vector<std::array<int32_t, 3>>& faces, double* out)
{
  double bestQ = -1;
  bool found = false;
  int validSeen = 0;
  for (auto& c : cands_)
  {
    bool ok = true;
    double q = 1e300;
    for (auto& fc : faces)
    {
      const double *A = m_.point(fc[0]), *B = m_.point(fc[1]), *C = m_.point(fc[2]);
      if (orient3d(A, B, C, c.data()) <= 0)
      {
        ok = false;
        break;
      }
      q = std::min(q, quality::tetShapeMeasure(A, B, C, c.data()));
    }
    if (!ok)
      continue;
    if (!found || q > bestQ)
    {
      bestQ = q;
      std::copy(c.begin(), c.end(), out);
      found = true;
    }
    if (++validSeen >= 4)
      break;
  }
  return found;
}

// Chebyshev centre of {y : n_i . y * L + dist_i >= 0} in units of L around p: maximise r subject to
// -n_i . y + r <= dist_i / L, |y_k| <= 1, 0 <= r <= 1, by a dense simplex (Bland's rule; p, y = 0, is
// feasible once the tiny negative distances of faces through p are clamped to 0). False when the
// kernel has no interior (r = 0) or the programme did not finish.
bool CavityInteriorPoint::chebyshevCentre(const std::vector<double>& dist, double L, double* y)
{
  const int nf = static_cast<int>(dist.size());
  const int n = 7;            // y+ (3), y- (3), r
  const int m = nf + 7;       // faces, |y_k| <= 1 (6), r <= 1
  const int cols = n + m + 1; // variables, slacks, right-hand side
  std::vector<double>& T = tableau_;
  T.assign(static_cast<size_t>(m + 1) * cols, 0.0);
  auto at = [&](int i, int j) -> double& { return T[static_cast<size_t>(i) * cols + j]; };
  for (int i = 0; i < nf; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      at(i, k) = -normals_[i][k];
      at(i, 3 + k) = normals_[i][k];
    }
    at(i, 6) = 1;
    at(i, cols - 1) = std::max(0.0, dist[i] / L);
  }
  for (int k = 0; k < 3; ++k)
  {
    at(nf + 2 * k, k) = 1;
    at(nf + 2 * k, 3 + k) = -1;
    at(nf + 2 * k, cols - 1) = 1;
    at(nf + 2 * k + 1, k) = -1;
    at(nf + 2 * k + 1, 3 + k) = 1;
    at(nf + 2 * k + 1, cols - 1) = 1;
  }
  at(nf + 6, 6) = 1;
  at(nf + 6, cols - 1) = 1;
  for (int i = 0; i < m; ++i)
    at(i, n + i) = 1;
  at(m, 6) = -1; // objective row: maximise r
  std::vector<int> basis(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i)
    basis[i] = n + i;
  const double eps = 1e-12;
  bool optimal = false;
  for (int iter = 0; iter < 50 * (m + n); ++iter)
  {
    int j = -1;
    for (int c = 0; c < n + m; ++c)
      if (at(m, c) < -eps)
      {
        j = c;
        break;
      }
    if (j < 0)
    {
      optimal = true;
      break;
    }
    int r = -1;
    double best = 0;
    for (int i = 0; i < m; ++i)
    {
      const double a = at(i, j);
      if (a <= eps)
        continue;
      const double ratio = at(i, cols - 1) / a;
      if (r < 0 || ratio < best - 1e-15 || (ratio <= best + 1e-15 && basis[i] < basis[r]))
      {
        r = i;
        best = ratio;
      }
    }
    if (r < 0)
      return false; // unbounded (cannot happen with the box)
    const double piv = at(r, j);
    for (int c = 0; c < cols; ++c)
      at(r, c) /= piv;
    for (int i = 0; i <= m; ++i)
    {
      if (i == r)
        continue;
      const double f = at(i, j);
      if (f == 0)
        continue;
      for (int c = 0; c < cols; ++c)
        at(i, c) -= f * at(r, c);
    }
    basis[r] = j;
  }
  if (!optimal)
    return false;
  double x[7] = { 0, 0, 0, 0, 0, 0, 0 };
  for (int i = 0; i < m; ++i)
    if (basis[i] < n)
      x[basis[i]] = at(i, cols - 1);
  if (!(x[6] > 1e-14))
    return false;
  for (int k = 0; k < 3; ++k)
    y[k] = x[k] - x[3 + k];
  return true;
}

} // namespace volgrid
