#include "MeshSmoothing.h"

#include "Predicates.h"
#include "PredicatesInline.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace volgrid
{

namespace
{
struct Scratch
{
  std::vector<int32_t> star, nbrs;
  std::vector<double> q, qAt; // star qualities (star order) at the current and at a trial position
  std::vector<int32_t> order; // star indices, worst tet first
  // Optional, in star order (smoothVertexWeighted): a tet scores weight * quality, and a position where its
  // quality falls under its floor scores -1. Null: every tet scores its quality.
  const double* weight = nullptr;
  const double* floorQ = nullptr;
};

inline double tetQ(const TetMesh& m, int32_t t)
{
  const int32_t* w = m.vertices(t);
  return tetSineQuality(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3]));
}

// The score of the star's i-th tet at the current coordinates.
inline double starScore(const TetMesh& m, const Scratch& s, size_t i)
{
  const double q = tetQ(m, s.star[i]);
  if (!s.weight)
    return q;
  return q < s.floorQ[i] ? -1.0 : q * s.weight[i];
}

// The visiting order of tryPosition: the star's tets by quality at the current position, worst first
// (ties by index). A trial position mostly fails at a tet that is already bad, so the scan stops early;
// the order changes no decision (the minimum over the whole star is the same in any order).
void rankStar(Scratch& s)
{
  s.order.resize(s.star.size());
  for (size_t i = 0; i < s.order.size(); ++i)
    s.order[i] = static_cast<int32_t>(i);
  std::sort(s.order.begin(), s.order.end(),
            [&](int32_t a, int32_t b) { return s.q[a] < s.q[b] || (s.q[a] == s.q[b] && a < b); });
}

bool starPositive(const TetMesh& m, const std::vector<int32_t>& star)
{
  for (int32_t t : star)
  {
    const int32_t* w = m.vertices(t);
    if (predicates::orient3dInline(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3])) <= 0)
      return false;
  }
  return true;
}

// Star minimum score with v at x (written into the mesh, then restored to `home`); -2 when a tet is not
// strictly positive (exact). Only a result above `floor` is used: the scan (in s.order) stops at the
// first tet at or below it (most trial positions fail there) and returns that tet's quality. A result
// above `floor` has every tet's quality at x in s.qAt (star order).
double tryPosition(TetMesh& m, int32_t v, const double* x, const double* home, Scratch& s, double floor)
{
  double* p = m.points.data() + 3 * static_cast<size_t>(v);
  p[0] = x[0];
  p[1] = x[1];
  p[2] = x[2];
  s.qAt.resize(s.star.size());
  double q = 2.0;
  for (int32_t i : s.order)
  {
    s.qAt[i] = starScore(m, s, static_cast<size_t>(i));
    q = std::min(q, s.qAt[i]);
    if (q <= floor)
      break;
  }
  if (q > floor && q > 0 && !starPositive(m, s.star)) // the exact test only for a position that would count
    q = -2;
  p[0] = home[0];
  p[1] = home[1];
  p[2] = home[2];
  return q;
}

void setPoint(TetMesh& m, int32_t v, const double* x)
{
  double* p = m.points.data() + 3 * static_cast<size_t>(v);
  p[0] = x[0];
  p[1] = x[1];
  p[2] = x[2];
}

// Gradient of tet t's quality with respect to the position of v (central differences).
void qualityGradient(TetMesh& m, int32_t t, int32_t v, double eps, double g[3])
{
  double* p = m.points.data() + 3 * static_cast<size_t>(v);
  for (int k = 0; k < 3; ++k)
  {
    const double x0 = p[k];
    p[k] = x0 + eps;
    const double qp = tetQ(m, t);
    p[k] = x0 - eps;
    const double qm = tetQ(m, t);
    p[k] = x0;
    g[k] = (qp - qm) / (2 * eps);
  }
}

// The move of v given its star in s.star (qualities in s.q, worst q0) and its neighbours in s.nbrs.
SmoothMove moveInStar(TetMesh& m, int32_t v, double q0, Scratch& s, const SmoothingOptions& options)
{
  const double home[3] = { m.point(v)[0], m.point(v)[1], m.point(v)[2] };
  // 1. Laplacian.
  double c[3] = { 0, 0, 0 };
  double scale = 0;
  for (int32_t u : s.nbrs)
  {
    const double* p = m.point(u);
    c[0] += p[0];
    c[1] += p[1];
    c[2] += p[2];
    scale += std::sqrt((p[0] - home[0]) * (p[0] - home[0]) + (p[1] - home[1]) * (p[1] - home[1]) +
                       (p[2] - home[2]) * (p[2] - home[2]));
  }
  const double inv = 1.0 / s.nbrs.size();
  c[0] *= inv;
  c[1] *= inv;
  c[2] *= inv;
  scale *= inv;
  rankStar(s);
  const double qL = tryPosition(m, v, c, home, s, q0);
  if (qL > q0)
  {
    setPoint(m, v, c);
    return SmoothMove::Laplacian;
  }
  if (!options.optimize || !(scale > 0))
    return SmoothMove::None;
  // 2. Hill climbing on the star's minimum.
  double x[3] = { home[0], home[1], home[2] };
  double qCur = q0;
  double step = 0.1 * scale;
  bool moved = false;
  const double eps = 1e-7 * scale;
  for (int it = 0; it < options.optimizeIterations; ++it)
  {
    // Nearly-worst tets and their quality gradients (s.q: the star at x, from the start or from the
    // accepted trial).
    const double tol = std::max(1e-3, 0.02 * std::fabs(qCur));
    double dir[3] = { 0, 0, 0 }, gWorst[3] = { 0, 0, 0 };
    size_t worst = 0;
    for (size_t i = 1; i < s.star.size(); ++i)
      if (s.q[i] < s.q[worst])
        worst = i;
    int active = 0;
    for (size_t i = 0; i < s.star.size(); ++i)
    {
      if (s.q[i] > s.q[worst] + tol)
        continue;
      double g[3];
      qualityGradient(m, s.star[i], v, eps, g);
      const double n = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      if (i == worst)
        for (int k = 0; k < 3; ++k)
          gWorst[k] = n > 0 ? g[k] / n : 0;
      if (n > 0)
        for (int k = 0; k < 3; ++k)
          dir[k] += g[k] / n;
      ++active;
    }
    bool improved = false;
    for (int attempt = 0; attempt < 2 && !improved; ++attempt)
    {
      const double* d = attempt == 0 ? dir : gWorst;
      if (attempt == 1 && active == 1)
        break;
      const double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(dn > 0))
        continue;
      double h = step;
      for (int ls = 0; ls < 10; ++ls, h *= 0.5)
      {
        const double y[3] = { x[0] + h * d[0] / dn, x[1] + h * d[1] / dn, x[2] + h * d[2] / dn };
        const double qy = tryPosition(m, v, y, x, s, qCur);
        if (qy > qCur)
        {
          std::swap(s.q, s.qAt);
          rankStar(s);
          x[0] = y[0];
          x[1] = y[1];
          x[2] = y[2];
          setPoint(m, v, x);
          qCur = qy;
          improved = true;
          step = std::min(2 * h, 0.2 * scale);
          break;
        }
      }
    }
    if (!improved)
      break;
    moved = true;
  }
  return moved ? SmoothMove::Optimized : SmoothMove::None;
}

// The star's scores into s.q; returns their minimum.
double rateStar(const TetMesh& m, Scratch& s)
{
  s.q.resize(s.star.size());
  double q0 = 2.0;
  for (size_t i = 0; i < s.star.size(); ++i)
  {
    s.q[i] = starScore(m, s, i);
    q0 = std::min(q0, s.q[i]);
  }
  return q0;
}
} // namespace

SmoothMove smoothVertex(TetEditor& editor, int32_t v, const SmoothingOptions& options)
{
  static thread_local Scratch s;
  editor.star(v, s.star);
  if (s.star.empty())
    return SmoothMove::None;
  const double q0 = rateStar(editor.mesh, s);
  if (sineQualityToDegrees(q0) >= options.belowDegrees)
    return SmoothMove::None;
  editor.neighbors(v, s.star, s.nbrs);
  if (s.nbrs.empty())
    return SmoothMove::None;
  return moveInStar(editor.mesh, v, q0, s, options);
}

SmoothMove smoothVertexInStar(TetMesh& mesh, int32_t v, const int32_t* star, size_t starSize, const int32_t* nbrs,
                              size_t nbrCount, const SmoothingOptions& options)
{
  static thread_local Scratch s;
  if (starSize == 0 || nbrCount == 0)
    return SmoothMove::None;
  s.star.assign(star, star + starSize);
  const double q0 = rateStar(mesh, s);
  if (sineQualityToDegrees(q0) >= options.belowDegrees)
    return SmoothMove::None;
  s.nbrs.assign(nbrs, nbrs + nbrCount);
  return moveInStar(mesh, v, q0, s, options);
}

SmoothMove smoothVertexWeighted(TetMesh& mesh, int32_t v, const std::vector<int32_t>& star,
                                const std::vector<int32_t>& nbrs, const std::vector<double>& weight,
                                const std::vector<double>& floorQ, const SmoothingOptions& options)
{
  static thread_local Scratch s; // its own: the unweighted calls' scratch never sees the pointers
  if (star.empty() || nbrs.empty() || weight.size() != star.size() || floorQ.size() != star.size())
    return SmoothMove::None;
  s.star = star;
  s.nbrs = nbrs;
  s.weight = weight.data();
  s.floorQ = floorQ.data();
  const double q0 = rateStar(mesh, s);
  const SmoothMove move = q0 > 0 ? moveInStar(mesh, v, q0, s, options) : SmoothMove::None;
  s.weight = s.floorQ = nullptr;
  return move;
}

Status smoothMesh(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                  const SmoothingOptions& options, Progress* progress, SmoothingReport* reportOut)
{
  const auto t0 = std::chrono::steady_clock::now();
  if (mesh.numGhostTets() > 0)
    return Status::failure(ErrorKind::InvalidOption, "Smoothing works on a mesh without ghost tets.");
  SmoothingReport local;
  SmoothingReport& report = reportOut ? *reportOut : local;
  TetEditor editor(mesh, constraints, nullptr);
  std::vector<uint8_t> lock = editor.lockedVertices();
  if (locked)
    for (size_t v = 0; v < lock.size() && v < locked->size(); ++v)
      lock[v] |= (*locked)[v];
  const int32_t nv = mesh.numVertices();
  for (int pass = 0; pass < options.passes; ++pass)
  {
    int64_t moves = 0;
    for (int32_t v = 0; v < nv; ++v)
    {
      if ((v & 8191) == 8191 && progress)
      {
        if (progress->cancelled())
          return Status::failure(ErrorKind::Cancelled, "Smoothing was cancelled.");
        progress->report((pass + double(v) / nv) / options.passes, "Smoothing");
      }
      if (lock[v])
        continue;
      const SmoothMove mv = smoothVertex(editor, v, options);
      if (mv == SmoothMove::Laplacian)
        ++report.laplacianMoves;
      else if (mv == SmoothMove::Optimized)
        ++report.optimizedMoves;
      else
        ++report.rejected;
      moves += mv != SmoothMove::None;
    }
    report.passes = pass + 1;
    if (moves == 0)
      break;
  }
  report.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return Status::success();
}

} // namespace volgrid
