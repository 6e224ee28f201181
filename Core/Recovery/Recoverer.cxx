// Recoverer (Recoverer.h): recovery of one segment or facet by flips, or its split by Steiner points.
#include "Recoverer.h"

#include "Quality.h"

#include "BoundaryCensus.h"
#include "FacetPieces.h"
#include "FacetRecovery.h"
#include "PlanarFlip.h"
#include "Predicates.h"
#include "SegmentConeSplit.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace volgrid
{

using predicates::orient3d;

namespace
{

// Exact: is point u on the open segment ab (collinear and strictly between)?
bool onOpenSegment(const double* a, const double* b, const double* u)
{
  for (int k = 0; k < 3; ++k)
    if (predicates::orient2dProjected(a, b, u, k) != 0)
      return false;
  for (int k = 0; k < 3; ++k)
  {
    if (a[k] == b[k])
      continue;
    const double lo = std::min(a[k], b[k]), hi = std::max(a[k], b[k]);
    return u[k] > lo && u[k] < hi;
  }
  return false;
}

// Exact: coplanar segments ab and uv cross at a point interior to both (u, v not on line ab).
bool coplanarCross(const double* a, const double* b, const double* u, const double* v)
{
  int axis = -1;
  for (int k = 0; k < 3 && axis < 0; ++k)
    if (predicates::orient2dProjected(a, b, u, k) != 0 || predicates::orient2dProjected(a, b, v, k) != 0)
      axis = k;
  if (axis < 0)
    return false;
  const int o1 = predicates::orient2dProjected(a, b, u, axis), o2 = predicates::orient2dProjected(a, b, v, axis);
  const int o3 = predicates::orient2dProjected(u, v, a, axis), o4 = predicates::orient2dProjected(u, v, b, axis);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

// Exact: coplanar point u lies in the closed triangle abc (abc not degenerate).
bool inTriangleCoplanar(const double* a, const double* b, const double* c, const double* u)
{
  for (int k = 0; k < 3; ++k)
  {
    const int o = predicates::orient2dProjected(a, b, c, k);
    if (o == 0)
      continue;
    const int o1 = predicates::orient2dProjected(a, b, u, k), o2 = predicates::orient2dProjected(b, c, u, k),
              o3 = predicates::orient2dProjected(c, a, u, k);
    return o1 * o >= 0 && o2 * o >= 0 && o3 * o >= 0;
  }
  return false;
}

// Edge-removal attempts one segment may spend in recoverEdgeByFlips: a segment the flips cannot recover
// (long needles crossed by dozens of faces) would otherwise eat the whole work budget of the stage
// before the easy ones are tried (prt2.stl: 476 segments left for Steiner points without it, 261 with).
constexpr uint64_t kFlipWorkPerSegment = 1000;

// Rounds in which one input segment may be split by cones (splitEdgeByCones).
constexpr int kMaxConeRounds = 4;

} // namespace

bool Recoverer::traceSegment(int32_t a, int32_t b, std::vector<Crossing>& faces, std::vector<Crossing>& edges)
{
  faces.clear();
  edges.clear();
  seenFaces_.clear();
  seenEdges_.clear();
  const double *A = m_.point(a), *B = m_.point(b);
  ed_.star(a, queue_);
  const uint32_t s = seedQueue();
  int32_t f[3];
  for (size_t k = 0; k < queue_.size(); ++k)
  {
    const int32_t t = queue_[k];
    const int32_t* v = m_.vertices(t);
    for (int i = 0; i < 4; ++i)
    {
      m_.faceVertices(t, i, f);
      if (f[0] == a || f[1] == a || f[2] == a || f[0] == b || f[1] == b || f[2] == b)
        continue;
      const double *U = m_.point(f[0]), *V = m_.point(f[1]), *W = m_.point(f[2]);
      const int sa = orient3d(U, V, W, A), sb = orient3d(U, V, W, B);
      if (sa * sb >= 0)
        continue;
      const int l1 = orient3d(A, B, U, V), l2 = orient3d(A, B, V, W), l3 = orient3d(A, B, W, U);
      if ((l1 > 0 && l2 > 0 && l3 > 0) || (l1 < 0 && l2 < 0 && l3 < 0))
      {
        if (seenFaces_.insert(TriKey(f[0], f[1], f[2])).second)
          faces.push_back({ t, i, 0 });
        pushOnce(m_.neighbor(t, i), s);
      }
      else if ((l1 == 0) + (l2 == 0) + (l3 == 0) >= 2)
        return false; // through a vertex
    }
    static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (auto& e : kEdge)
    {
      const int32_t x = v[e[0]], y = v[e[1]];
      if (x == a || x == b || y == a || y == b)
        continue;
      const double *X = m_.point(x), *Y = m_.point(y);
      if (orient3d(A, B, X, Y) != 0)
        continue;
      if (onOpenSegment(A, B, X) || onOpenSegment(A, B, Y))
        return false;
      if (!coplanarCross(A, B, X, Y))
        continue;
      if (seenEdges_.insert(edgeKey(x, y)).second)
        edges.push_back({ t, x, y });
      // Tets around the edge: neighbours across the two faces containing it.
      for (int i = 0; i < 4; ++i)
        if (i != e[0] && i != e[1])
          pushOnce(m_.neighbor(t, i), s);
    }
  }
  return true;
}

bool Recoverer::traceFacet(int32_t a, int32_t b, int32_t c, std::vector<Crossing>& edges, std::vector<int32_t>* visited)
{
  edges.clear();
  seenEdges_.clear();
  const double *A = m_.point(a), *B = m_.point(b), *C = m_.point(c);
  const int32_t t0 = ed_.findEdge(a, b);
  if (t0 < 0)
    return false;
  std::vector<int32_t> ring, tets;
  queue_.clear();
  if (!ed_.edgeRing(t0, a, b, ring, tets))
    ed_.star(a, queue_);
  else
    queue_ = tets;
  const uint32_t s = seedQueue();
  for (size_t k = 0; k < queue_.size(); ++k)
  {
    const int32_t t = queue_[k];
    const int32_t* v = m_.vertices(t);
    int sv[4];
    for (int i = 0; i < 4; ++i)
    {
      if (v[i] == a || v[i] == b || v[i] == c)
      {
        sv[i] = 2;
        continue;
      }
      sv[i] = orient3d(A, B, C, m_.point(v[i]));
      if (sv[i] == 0 && inTriangleCoplanar(A, B, C, m_.point(v[i])))
        return false;
    }
    static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (auto& e : kEdge)
    {
      if (sv[e[0]] == 2 || sv[e[1]] == 2 || sv[e[0]] * sv[e[1]] >= 0)
        continue;
      const double *X = m_.point(v[e[0]]), *Y = m_.point(v[e[1]]);
      const int l1 = orient3d(X, Y, A, B), l2 = orient3d(X, Y, B, C), l3 = orient3d(X, Y, C, A);
      if (!((l1 >= 0 && l2 >= 0 && l3 >= 0) || (l1 <= 0 && l2 <= 0 && l3 <= 0)))
        continue;
      if (seenEdges_.insert(edgeKey(v[e[0]], v[e[1]])).second)
        edges.push_back({ t, v[e[0]], v[e[1]] });
      for (int i = 0; i < 4; ++i)
        if (i != e[0] && i != e[1])
          pushOnce(m_.neighbor(t, i), s);
    }
  }
  if (visited)
    *visited = queue_;
  return true;
}

void Recoverer::undo(const std::vector<int32_t>& created)
{
  std::vector<std::array<int32_t, 4>> old = ed_.lastRemoved;
  // A point the undone edit added (flipInPlane's interior point) is used by no tet afterwards.
  std::vector<int32_t> added;
  for (int32_t t : created)
    for (int i = 0; i < 4; ++i)
    {
      const int32_t v = m_.vertex(t, i);
      bool inOld = false;
      for (const auto& o : old)
        inOld = inOld || o[0] == v || o[1] == v || o[2] == v || o[3] == v;
      if (!inOld)
        added.push_back(v);
    }
  ed_.replace(created, old, nullptr);
  for (int32_t v : added)
    kinds_[static_cast<size_t>(v)] = VertexKind::Unused;
}

std::array<int32_t, 2> Recoverer::inPlaneChord(int32_t a, int32_t b, const Crossing& c)
{
  std::array<int32_t, 2> chord = { -1, -1 };
  std::vector<int32_t> ring, tets;
  if (!ed_.edgeRing(c.tet, c.a, c.b, ring, tets))
    return chord;
  const double *A = m_.point(a), *B = m_.point(b), *X = m_.point(c.a);
  int found = 0;
  for (int32_t r : ring)
    if (orient3d(A, B, X, m_.point(r)) == 0)
    {
      if (found < 2)
        chord[found] = r;
      ++found;
    }
  return found == 2 ? chord : std::array<int32_t, 2>{ -1, -1 };
}

bool Recoverer::recoverEdgeInPlane(int32_t a, int32_t b, const std::vector<Crossing>& edges)
{
  // Copies: flipInPlane may add a point, which moves the coordinate array.
  const double A[3] = { m_.point(a)[0], m_.point(a)[1], m_.point(a)[2] };
  const double B[3] = { m_.point(b)[0], m_.point(b)[1], m_.point(b)[2] };
  std::deque<std::array<int32_t, 2>> queue;
  for (const Crossing& c : edges)
    queue.push_back({ c.a, c.b });
  std::vector<int32_t> created;
  // Sloan: at most k(k-1)/2 flips for k crossing edges (each pair of crossing diagonals flips once).
  const size_t k = edges.size(), limit = k * (k + 1) / 2 + 4 * k + 100;
  size_t idle = 0; // consecutive refusals: a full pass of them means no convex quad is left
  for (size_t step = 0; step < limit && !queue.empty() && idle <= queue.size(); ++step)
  {
    const std::array<int32_t, 2> e = queue.front();
    queue.pop_front();
    const int32_t t = ed_.findEdge(e[0], e[1]);
    if (t < 0)
      continue; // flipped away meanwhile
    const std::array<int32_t, 2> chord = inPlaneChord(a, b, { t, e[0], e[1] });
    if (chord[0] < 0 || !flipInPlane(ed_, t, e[0], e[1], chord[0], chord[1], &bc_, &created, &kinds_))
    {
      queue.push_back(e);
      ++idle;
      continue;
    }
    idle = 0;
    if (coplanarCross(A, B, m_.point(chord[0]), m_.point(chord[1])))
      queue.push_back(chord);
  }
  return ed_.findEdge(a, b) >= 0;
}

bool Recoverer::recoverEdgeByFlips(int32_t a, int32_t b)
{
  std::vector<Crossing> faces, edges, f2, e2;
  std::vector<int32_t> created;
  int sideways = 0;
  const uint64_t work0 = ed_.removalAttempts;
  for (int iter = 0; iter < 500; ++iter)
  {
    if (ed_.findEdge(a, b) >= 0)
      return true;
    if (ed_.removalAttempts - work0 > kFlipWorkPerSegment)
      return false; // hopeless here: leave the budget to the others (a Steiner point will split it)
    if (!traceSegment(a, b, faces, edges))
      return false;
    const size_t m0 = faces.size() + edges.size();
    if (m0 == 0)
      return false;
    if (iter == 0 && faces.empty() && recoverEdgeInPlane(a, b, edges))
      return true;
    bool progress = false;
    for (const Crossing& c : faces)
    {
      if (m_.isFree(c.tet) || !ed_.flip23(c.tet, c.a, &bc_, &created))
        continue;
      if (ed_.findEdge(a, b) >= 0)
        return true;
      if (traceSegment(a, b, f2, e2) && f2.size() + e2.size() < m0)
      {
        progress = true;
        break;
      }
      undo(created);
    }
    if (progress)
      continue;
    for (const Crossing& c : edges)
    {
      // First as a 2D flip in the plane of the segment and the crossing edge (the chord between the
      // two ring vertices in that plane), then any valid removal.
      // (a failed attempt restores the tets under new ids: look the edge up again before each)
      int32_t t = ed_.findEdge(c.a, c.b);
      if (t < 0)
        continue;
      const std::array<int32_t, 2> chord = inPlaneChord(a, b, { t, c.a, c.b });
      if (!ed_.removeEdgeDeep(t, c.a, c.b, &bc_, &created, 2, chord) &&
          (chord[0] < 0 || (t = ed_.findEdge(c.a, c.b)) < 0 ||
           !flipInPlane(ed_, t, c.a, c.b, chord[0], chord[1], &bc_, &created, &kinds_)) &&
          ((t = ed_.findEdge(c.a, c.b)) < 0 || !ed_.removeEdgeDeep(t, c.a, c.b, &bc_, &created, 2)))
        continue;
      if (ed_.findEdge(a, b) >= 0)
        return true;
      if (fewerCrossings(a, b, m0, sideways))
      {
        progress = true;
        break;
      }
      undo(created);
    }
    if (!progress)
      progress = removeCrossingFaceEdge(a, b, m0, sideways);
    if (!progress)
      return false;
  }
  return false;
}

bool Recoverer::removeCrossingFaceEdge(int32_t a, int32_t b, size_t m0, int& sideways)
{
  std::vector<Crossing> faces, edges;
  std::vector<int32_t> created;
  if (!traceSegment(a, b, faces, edges))
    return false;
  std::unordered_set<uint64_t> tried;
  int32_t fv[3];
  for (const Crossing& c : faces)
  {
    if (m_.isFree(c.tet))
      continue;
    m_.faceVertices(c.tet, c.a, fv);
    for (int k = 0; k < 3; ++k)
    {
      const int32_t x = fv[k], y = fv[(k + 1) % 3];
      if (!tried.insert(edgeKey(x, y)).second)
        continue;
      const int32_t t = ed_.findEdge(x, y);
      if (t < 0 || !ed_.removeEdgeDeep(t, x, y, &bc_, &created, 1))
        continue;
      if (ed_.findEdge(a, b) >= 0 || fewerCrossings(a, b, m0, sideways))
        return true;
      undo(created);
    }
  }
  return false;
}

bool Recoverer::fewerCrossings(int32_t a, int32_t b, size_t m0, int& sideways)
{
  std::vector<Crossing> faces, edges;
  if (!traceSegment(a, b, faces, edges))
    return false;
  const size_t m = faces.size() + edges.size();
  if (m < m0)
    return true;
  if (m > m0 || sideways >= 64)
    return false;
  ++sideways;
  return true;
}

bool Recoverer::recoverFacetByFlips(int32_t a, int32_t b, int32_t c)
{
  std::vector<Crossing> edges, e2;
  std::vector<int32_t> created, visited;
  int32_t f[3];
  for (int iter = 0; iter < 500; ++iter)
  {
    if (ed_.findFace(a, b, c) >= 0)
      return true;
    if (!traceFacet(a, b, c, edges, &visited))
      return false;
    std::unordered_set<uint64_t> crossing;
    for (const Crossing& cr : edges)
      crossing.insert(edgeKey(cr.a, cr.b));
    const size_t m0 = edges.size();
    if (m0 == 0)
      return false;
    auto better = [&]()
    {
      if (ed_.findFace(a, b, c) >= 0)
        return true;
      return traceFacet(a, b, c, e2, nullptr) && e2.size() < m0;
    };
    bool progress = false;
    for (const Crossing& cr : edges)
    {
      if (m_.isFree(cr.tet) || !ed_.removeEdgeDeep(cr.tet, cr.a, cr.b, &bc_, &created, 2))
        continue;
      if (better())
      {
        progress = true;
        break;
      }
      undo(created);
    }
    if (!progress)
    {
      // 2-3 flips of faces that contain a crossing edge.
      for (int32_t t : visited)
      {
        if (m_.isFree(t))
          continue;
        for (int i = 0; i < 4 && !progress; ++i)
        {
          m_.faceVertices(t, i, f);
          bool has = false;
          for (int k = 0; k < 3 && !has; ++k)
            has = crossing.count(edgeKey(f[k], f[(k + 1) % 3])) != 0;
          if (!has || m_.neighbor(t, i) < t)
            continue;
          if (!ed_.flip23(t, i, &bc_, &created))
            continue;
          if (better())
          {
            progress = true;
            break;
          }
          undo(created);
        }
        if (progress)
          break;
      }
      if (!progress)
        return false;
    }
  }
  return false;
}

void Recoverer::presplitPoint(int32_t a, int32_t b, double* p)
{
  const double *A = m_.point(a), *B = m_.point(b);
  double d[3];
  for (int k = 0; k < 3; ++k)
  {
    d[k] = B[k] - A[k];
    p[k] = 0.5 * (A[k] + B[k]);
  }
  const double len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  std::vector<Crossing> faces, edges;
  if (traceSegment(a, b, faces, edges))
  {
    double bestCos = 2, bestT = 0.5;
    auto consider = [&](int32_t q)
    {
      if (q == a || q == b)
        return;
      const double* Q = m_.point(q);
      double u[3], w[3];
      for (int k = 0; k < 3; ++k)
      {
        u[k] = A[k] - Q[k];
        w[k] = B[k] - Q[k];
      }
      const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      const double nw = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      const double c = (u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / (nu * nw);
      if (c < bestCos)
      {
        bestCos = c;
        bestT = -(u[0] * d[0] + u[1] * d[1] + u[2] * d[2]) / len2;
      }
    };
    int32_t fv[3];
    for (const Crossing& c : faces)
    {
      m_.faceVertices(c.tet, c.a, fv);
      for (int32_t q : fv)
        consider(q);
    }
    for (const Crossing& c : edges)
    {
      consider(c.a);
      consider(c.b);
    }
    if (bestCos < 2 && bestT > 0.2 && bestT < 0.8)
    {
      for (int k = 0; k < 3; ++k)
        p[k] = A[k] + bestT * d[k];
      return;
    }
  }
  const bool inputA = kinds_[a] == VertexKind::Boundary, inputB = kinds_[b] == VertexKind::Boundary;
  if (inputA != inputB)
  {
    const double* O = inputA ? A : B;
    const double* E = inputA ? B : A;
    const double len = std::sqrt(len2);
    const double t = std::exp2(std::round(std::log2(0.5 * len))) / len;
    for (int k = 0; k < 3; ++k)
      p[k] = O[k] + t * (E[k] - O[k]);
  }
}

bool Recoverer::splitEdge(int32_t a, int32_t b, bool presplit)
{
  const std::array<int32_t, 2>* ef = bc_.edgeFaces(a, b);
  if (!ef)
    return false;
  const std::array<int32_t, 2> fs = *ef;
  const double *A = m_.point(a), *B = m_.point(b);
  double p[3] = { 0.5 * (A[0] + B[0]), 0.5 * (A[1] + B[1]), 0.5 * (A[2] + B[2]) };
  if (presplit)
    presplitPoint(a, b, p);
  const int32_t v = m_.addPoint(p);
  bool sameParent = fs[0] >= 0 && fs[1] >= 0 && bc_.parent[fs[0]] == bc_.parent[fs[1]];
  kinds_.push_back(sameParent ? VertexKind::SteinerFacet : VertexKind::SteinerSegment);
  if (!ed_.insertVertex(v, ed_.tetOf(a), presplit ? nullptr : &bc_))
  {
    m_.points.resize(m_.points.size() - 3);
    kinds_.pop_back();
    return false;
  }
  splitConstraintEdge(a, b, v, sameParent);
  return true;
}

bool Recoverer::splitEdgeByCones(int32_t a, int32_t b, size_t maxPoints)
{
  const std::array<int32_t, 2>* ef = bc_.edgeFaces(a, b);
  if (!ef)
    return false;
  const std::array<int32_t, 2> fs = *ef;
  const bool sameParent = fs[0] >= 0 && fs[1] >= 0 && bc_.parent[fs[0]] == bc_.parent[fs[1]];
  const uint64_t seg = bc_.segmentOf(a, b);
  // Two segments meeting at a small angle can take turns to advance a little each round, closing in
  // on their common end without end: a few rounds per segment, then the midpoint split takes over.
  if (++coneRounds_[seg] > kMaxConeRounds)
    return false;
  std::vector<int32_t> added; // points of this call, on the line too
  auto onLine = [&](int32_t w)
  { return w == a || w == b || std::find(added.begin(), added.end(), w) != added.end() || bc_.onSegment(w, seg); };
  int32_t from = a;
  bool any = false;
  for (size_t n = 0; n < maxPoints; ++n)
  {
    int32_t v = -1;
    const ConeStep step = coneStepAlongSegment(ed_, bc_, from, b, onLine, &v);
    if (step == ConeStep::Recovered)
      return true;
    if (step == ConeStep::Failed)
      return any;
    kinds_.push_back(sameParent ? VertexKind::SteinerFacet : VertexKind::SteinerSegment);
    splitConstraintEdge(from, b, v, sameParent);
    added.push_back(v);
    from = v;
    any = true;
  }
  return any;
}

void Recoverer::splitConstraintEdge(int32_t a, int32_t b, int32_t v, bool sameParent)
{
  const std::array<int32_t, 2> fs = *bc_.edgeFaces(a, b);
  if (!sameParent)
    bc_.addSegmentPoint(v, a, b);
  for (int32_t fid : fs)
  {
    if (fid < 0)
      continue;
    const int32_t s[3] = { bc_.subface(fid)[0], bc_.subface(fid)[1], bc_.subface(fid)[2] };
    const int32_t par = bc_.parent[fid];
    int i = 0;
    while (!((s[i] == a && s[(i + 1) % 3] == b) || (s[i] == b && s[(i + 1) % 3] == a)))
      ++i;
    bc_.removeSubface(fid);
    bc_.addSubface(s[i], v, s[(i + 2) % 3], par);
    bc_.addSubface(v, s[(i + 1) % 3], s[(i + 2) % 3], par);
  }
  if (sameParent)
    ++steinerFacet;
  else
    ++steinerSegment;
}

bool Recoverer::splitFacet(int32_t fid)
{
  const int32_t s[3] = { bc_.subface(fid)[0], bc_.subface(fid)[1], bc_.subface(fid)[2] };
  const double *A = m_.point(s[0]), *B = m_.point(s[1]), *C = m_.point(s[2]);
  double p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = (A[k] + B[k] + C[k]) / 3.0;
  const int32_t v = m_.addPoint(p);
  kinds_.push_back(VertexKind::SteinerFacet);
  if (!ed_.insertVertex(v, ed_.tetOf(s[0]), &bc_))
  {
    m_.points.resize(m_.points.size() - 3);
    kinds_.pop_back();
    return false;
  }
  const int32_t par = bc_.parent[fid];
  bc_.removeSubface(fid);
  bc_.addSubface(s[0], s[1], v, par);
  bc_.addSubface(s[1], s[2], v, par);
  bc_.addSubface(s[2], s[0], v, par);
  ++steinerFacet;
  return true;
}

} // namespace volgrid
