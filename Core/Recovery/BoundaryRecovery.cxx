#include "BoundaryRecovery.h"

#include "Quality.h"

#include "BoundaryCensus.h"
#include "FacetPieces.h"
#include "FacetRecovery.h"
#include "PlanarFlip.h"
#include "Predicates.h"
#include "SegmentConeSplit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <string>

namespace volgrid
{

using predicates::orient3d;

// ------------------------------------------------------------------------------------------------
// Recovery

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

struct Crossing
{
  int32_t tet;
  int32_t a, b; // edge endpoints (edges) or face index in a (faces)
};

// Edge-removal attempts one segment may spend in recoverEdgeByFlips: a segment the flips cannot recover
// (long needles crossed by dozens of faces) would otherwise eat the whole work budget of the stage
// before the easy ones are tried (prt2.stl: 476 segments left for Steiner points without it, 261 with).
constexpr uint64_t kFlipWorkPerSegment = 1000;

// Rounds in which one input segment may be split by cones (splitEdgeByCones).
constexpr int kMaxConeRounds = 4;

class Recoverer
{
public:
  Recoverer(MeshEditor& ed, BoundaryConstraints& bc, std::vector<VertexKind>& kinds)
    : ed_(ed)
    , m_(ed.mesh)
    , bc_(bc)
    , kinds_(kinds)
  {
  }

  // Crossings of the open segment ab. Returns false when a vertex lies on it.
  bool traceSegment(int32_t a, int32_t b, std::vector<Crossing>& faces, std::vector<Crossing>& edges)
  {
    faces.clear();
    edges.clear();
    seenFaces_.clear();
    seenEdges_.clear();
    const double *A = m_.point(a), *B = m_.point(b);
    ed_.star(a, queue_);
    const uint32_t s = ed_.newStamp();
    for (int32_t t : queue_)
      ed_.tetStamp[t] = s;
    auto push = [&](int32_t u)
    {
      if (u >= 0 && ed_.tetStamp[u] != s)
      {
        ed_.tetStamp[u] = s;
        queue_.push_back(u);
      }
    };
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
          push(m_.neighbor(t, i));
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
            push(m_.neighbor(t, i));
      }
    }
    return true;
  }

  // Edges crossing the interior of triangle abc (its edges present). False when a vertex lies in it.
  bool traceFacet(int32_t a, int32_t b, int32_t c, std::vector<Crossing>& edges, std::vector<int32_t>* visited)
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
    const uint32_t s = ed_.newStamp();
    for (int32_t t : queue_)
      ed_.tetStamp[t] = s;
    auto push = [&](int32_t u)
    {
      if (u >= 0 && ed_.tetStamp[u] != s)
      {
        ed_.tetStamp[u] = s;
        queue_.push_back(u);
      }
    };
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
            push(m_.neighbor(t, i));
      }
    }
    if (visited)
      *visited = queue_;
    return true;
  }

  void undo(const std::vector<int32_t>& created)
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

  // For edge c crossing segment ab in a common plane: the two vertices of c's ring in that plane (the
  // diagonal a 2D flip would create), or {-1, -1}.
  std::array<int32_t, 2> inPlaneChord(int32_t a, int32_t b, const Crossing& c)
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

  // Segment ab lies in a flat part of the mesh where it crosses only edges of that plane, each with the
  // two in-plane ring vertices of a 2D triangulation (a flat CAD face): Sloan's 2D algorithm. Crossing
  // edges wait in a queue; one whose quad is convex is flipped in the plane (flipInPlane refuses the
  // others, which go back to the queue), and the new diagonal joins the queue if it still crosses ab.
  // In 2D a convex one always exists, so this ends; the crossing count never grows but may stay the
  // same for many flips, which the greedy search below does not allow.
  bool recoverEdgeInPlane(int32_t a, int32_t b, const std::vector<Crossing>& edges)
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

  bool recoverEdgeByFlips(int32_t a, int32_t b)
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

  // The 2-3 flip of a face the segment crosses is invalid when one of the face's edges is reflex; then
  // that edge has to go first (TetGen's removefacebyflips does the same). Tries each edge of each crossing
  // face; keeps a removal that lowers the crossing count (or keeps it, a bounded number of times).
  bool removeCrossingFaceEdge(int32_t a, int32_t b, size_t m0, int& sideways)
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

  // After a flip: does segment ab cross fewer than m0 faces and edges? Like Sloan's 2D algorithm, a flip
  // that keeps the count may still be needed (coplanar crossings): up to 64 such sideways steps per
  // segment are accepted too.
  bool fewerCrossings(int32_t a, int32_t b, size_t m0, int& sideways)
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

  bool recoverFacetByFlips(int32_t a, int32_t b, int32_t c)
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

  // Where the presplit stage splits missing subsegment ab (the mesh is Delaunay, nothing flipped yet):
  // at the foot of the vertex that encroaches most on it (largest angle a-q-b among the vertices of the
  // faces it crosses), which then no longer encroaches on either piece; when that foot is near an end,
  // at a power-of-two distance from the piece's input end point (concentric shells: pieces of segments
  // meeting at a small angle do not keep encroaching on each other), else at the midpoint.
  void presplitPoint(int32_t a, int32_t b, double* p)
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

  // Steiner point on subsegment ab: at its midpoint, or (presplit stage) at presplitPoint() inserted
  // by plain Delaunay insertion.
  bool splitEdge(int32_t a, int32_t b, bool presplit = false)
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

  // Missing subsegment ab recovered at once by points on it (SegmentConeSplit.h); false when that does
  // not apply (the caller then splits it at its midpoint).
  bool splitEdgeByCones(int32_t a, int32_t b, size_t maxPoints)
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

  // Subsegment ab of the constraints becomes av + vb; the subfaces on it are split in two.
  void splitConstraintEdge(int32_t a, int32_t b, int32_t v, bool sameParent)
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

  bool splitFacet(int32_t fid)
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

  int64_t steinerSegment = 0, steinerFacet = 0;

private:
  MeshEditor& ed_;
  TetMesh& m_;
  BoundaryConstraints& bc_;
  std::vector<VertexKind>& kinds_;
  std::vector<int32_t> queue_;
  std::unordered_set<TriKey, TriKeyHash> seenFaces_;
  std::unordered_set<uint64_t> seenEdges_;
  std::unordered_map<uint64_t, int> coneRounds_; // per input segment (edgeKey), splitEdgeByCones calls
};

// The final census: the unrecovered edges and facets counted into `rep`; returns the input triangles of
// the first five of each (edges first).
std::vector<int64_t> finalCensus(MeshEditor& ed, BoundaryConstraints& bc, BoundaryCensus& census, RecoveryReport& rep)
{
  std::vector<int64_t> badEdges, badFaces;
  if (!census.upToDate(ed, bc))
    census.take(ed, bc);
  // A live subface none of whose edges was counted missing above, yet not a face, is a missing facet.
  std::vector<uint8_t> edgeMissing(static_cast<size_t>(bc.capacity()), 0);
  census.forEachSubfaceEdge(bc,
                            [&](int32_t f, int32_t, int32_t, int32_t id, bool first)
                            {
                              if (first && (id < 0 || !census.edgePresent(id)))
                              {
                                ++rep.unrecoveredEdges;
                                edgeMissing[static_cast<size_t>(f)] = 1;
                                if (badEdges.size() < 5)
                                  badEdges.push_back(bc.parent[f]);
                              }
                            });
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f) && !edgeMissing[static_cast<size_t>(f)] && census.faceCode(f) < 0)
    {
      ++rep.unrecoveredFacets;
      if (badFaces.size() < 5)
        badFaces.push_back(bc.parent[f]);
    }
  badEdges.insert(badEdges.end(), badFaces.begin(), badFaces.end());
  return badEdges;
}

// Cavity retetrahedralization of each input triangle with missing subfaces (all its segments present):
// the whole triangle, its pieces, or the slab; a triangle none of them recovers is marked in `fallback`.
Status recoverFacetCavities(MeshEditor& ed, BoundaryConstraints& bc, const std::vector<int32_t>& missingFaces,
                            std::vector<char>& fallback, FacetCavityStats& cavityStats, Progress& progress)
{
  std::unordered_map<int32_t, std::vector<int32_t>> byParent;
  for (int32_t f : missingFaces)
    if (!fallback[static_cast<size_t>(bc.parent[f])])
      byParent.emplace(bc.parent[f], std::vector<int32_t>());
  if (byParent.empty())
    return Status::success();
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f))
    {
      auto it = byParent.find(bc.parent[f]);
      if (it != byParent.end())
        it->second.push_back(f);
    }
  size_t done = 0;
  for (auto& [par, subs] : byParent)
  {
    if (++done % 256 == 0)
    {
      progress.report(0.5 + 0.5 * static_cast<double>(done) / byParent.size(), "Recovering boundary facets");
      if (progress.cancelled())
        return Status::failure(ErrorKind::Cancelled, "Boundary recovery was cancelled.");
    }
    if (!recoverFacetByCavity(ed, bc, par, subs, &cavityStats) &&
        !recoverFacetByPieces(ed, bc, par, subs, &cavityStats) && !recoverFacetBySlab(ed, bc, par, subs, &cavityStats))
      fallback[static_cast<size_t>(par)] = 1;
  }
  return Status::success();
}

// The presplit stage: rounds that split each missing listed segment at its midpoint (insertVertex without
// constraints is the Bowyer-Watson insertion, so the mesh stays Delaunay) until all are edges (true) or
// `budget` points are used or a round splits nothing (false).
template<class CollectMissing>
bool presplit(Recoverer& rec, MeshEditor& ed, BoundaryConstraints& bc, const std::unordered_set<uint64_t>& segments,
              int64_t budget, CollectMissing&& collectMissingEdges,
              const std::vector<std::pair<int32_t, int32_t>>& missingEdges, int64_t& steinerUsed, RecoveryReport& rep)
{
  for (int round = 0; round < 64 && steinerUsed < budget; ++round)
  {
    collectMissingEdges(&segments);
    if (missingEdges.empty())
      return true;
    bool split = false;
    for (auto [a, b] : missingEdges)
      if (bc.isEdge(a, b) && ed.findEdge(a, b) < 0 && steinerUsed < budget && rec.splitEdge(a, b, true))
      {
        ++steinerUsed;
        ++rep.presplitPoints;
        split = true;
      }
    if (!split)
      return false;
  }
  return false;
}

} // namespace

// Stop adding Steiner points after this many consecutive rounds in which the number of missing edges grew.
static constexpr int kMaxGrowingRounds = 3;
// Work budget of the flip stages, in edge-removal attempts: kWorkPerMissingEdge per initially missing edge
// plus kWorkBase. Most cases need far less (< 10 per missing edge); CAD models with long thin triangles
// need up to ~1000. Once it is spent, flips stop and what is missing gets Steiner points (bounded by the
// Steiner budget and the growth guard), so hopeless cases still end in seconds.
static constexpr uint64_t kWorkPerMissingEdge = 1000, kWorkBase = 100000;

Status recoverBoundary(MeshEditor& ed, BoundaryConstraints& bc, std::vector<VertexKind>& kinds,
                       const RecoveryOptions& options, Progress* progress, RecoveryReport* report)
{
  const auto t0 = std::chrono::steady_clock::now();
  SilentProgress silent;
  Progress* pr = progress ? progress : &silent;
  RecoveryReport rep;
  Recoverer rec(ed, bc, kinds);
  const int64_t budget =
    options.maxSteinerPoints >= 0 ? options.maxSteinerPoints : 4 * static_cast<int64_t>(bc.numInputTriangles()) + 1000;
  const uint64_t f23 = ed.flips23, f32 = ed.flips32, fer = ed.flipsEdgeRemoval;
  std::vector<std::pair<int32_t, int32_t>> missingEdges;
  std::vector<int32_t> missingFaces;
  std::vector<std::pair<int32_t, int32_t>> failedEdges;
  std::vector<int32_t> failedFaces;
  bool first = true, firstFacets = true;
  int64_t steinerUsed = 0;
  size_t prevMissing = 0;
  int growing = 0;
  uint64_t workLimit = 0;
  bool outOfWork = false;
  // Input triangles whose cavity recovery failed: their inner subface edges are recovered one by one
  // (flips, then Steiner points) like the segments. Other triangles only need their segments: the cavity
  // retetrahedralization (FacetRecovery.h) triangulates their interior.
  std::vector<char> fallback(static_cast<size_t>(bc.numInputTriangles()), 0);
  auto requiredEdge = [&](int32_t a, int32_t b)
  {
    const std::array<int32_t, 2>* ef = bc.edgeFaces(a, b);
    if (!ef)
      return false;
    const int32_t f0 = (*ef)[0], f1 = (*ef)[1];
    if (f0 < 0 || f1 < 0 || bc.parent[f0] != bc.parent[f1])
      return true; // a (sub)segment
    return fallback[static_cast<size_t>(bc.parent[f0])] != 0;
  };
  FacetCavityStats cavityStats;
  BoundaryCensus census;
  // Missing required subface edges, in subface order (the order recovery tries them in); `only`: those
  // on these input segments.
  auto collectMissingEdges = [&](const std::unordered_set<uint64_t>* only)
  {
    missingEdges.clear();
    if (!census.upToDate(ed, bc))
      census.take(ed, bc);
    census.forEachSubfaceEdge(bc,
                              [&](int32_t, int32_t a, int32_t b, int32_t id, bool first)
                              {
                                if (first && (id < 0 || !census.edgePresent(id)) && requiredEdge(a, b) &&
                                    (!only || only->count(bc.segmentOf(a, b))))
                                  missingEdges.push_back({ a, b });
                              });
  };
  if (options.presplitSegments && !options.presplitSegments->empty() && options.allowSteiner)
  {
    // Presplit stage (see RecoveryOptions::presplitSegments). At most one presplit point per input triangle: beyond
    // that (segments of needle triangles, whose pieces would have to be as short as the needles are thin) the retry
    // would only end in a slow Steiner removal of thousands of points.
    const int64_t presplitBudget = std::min<int64_t>(budget, bc.numInputTriangles());
    const bool converged = presplit(rec, ed, bc, *options.presplitSegments, presplitBudget, collectMissingEdges,
                                    missingEdges, steinerUsed, rep);
    if (!converged)
    {
      rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (report)
        *report = rep;
      return Status::failure(ErrorKind::RecoveryFailed,
                             "Boundary recovery failed: splitting the listed segments did not make them edges within " +
                               std::to_string(presplitBudget) + " Steiner points (needle-thin triangles).");
    }
  }
  for (int round = 0; round < 100000; ++round)
  {
    if (pr->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Boundary recovery was cancelled.");
    collectMissingEdges(nullptr);
    if (first)
    {
      rep.missingEdgesInitially = static_cast<int64_t>(missingEdges.size());
      workLimit = ed.removalAttempts + kWorkBase + kWorkPerMissingEdge * missingEdges.size();
    }
    first = false;
    failedEdges.clear();
    size_t done = 0;
    for (auto [a, b] : missingEdges)
    {
      if (++done % 256 == 0)
      {
        pr->report(0.5 * static_cast<double>(done) / missingEdges.size(), "Recovering boundary edges");
        if (pr->cancelled())
          return Status::failure(ErrorKind::Cancelled, "Boundary recovery was cancelled.");
      }
      if (!bc.isEdge(a, b))
        continue; // split meanwhile
      if (ed.removalAttempts > workLimit)
        outOfWork = true;
      if (!outOfWork && rec.recoverEdgeByFlips(a, b))
        continue;
      failedEdges.push_back({ a, b });
    }
    bool changed = false;
    // Divergence guard: Steiner points that only make more edges go missing will not converge.
    if (round > 0 && missingEdges.size() > prevMissing)
      ++growing;
    else
      growing = 0;
    prevMissing = missingEdges.size();
    if (growing >= kMaxGrowingRounds)
      break;
    if (!failedEdges.empty())
    {
      if (!options.allowSteiner || steinerUsed >= budget)
        break;
      for (auto [a, b] : failedEdges)
      {
        if (!bc.isEdge(a, b) || ed.findEdge(a, b) >= 0 || steinerUsed >= budget)
          continue;
        const int64_t before = rec.steinerSegment + rec.steinerFacet;
        if ((options.segmentCones && rec.splitEdgeByCones(a, b, static_cast<size_t>(budget - steinerUsed))) ||
            rec.splitEdge(a, b))
        {
          steinerUsed += rec.steinerSegment + rec.steinerFacet - before;
          changed = true;
        }
      }
      if (changed)
        continue;
      break; // nothing could be split
    }
    // All edges present: facets.
    missingFaces.clear();
    if (!census.upToDate(ed, bc))
      census.take(ed, bc);
    for (int32_t f = 0; f < bc.capacity(); ++f)
      if (bc.alive(f) && census.faceCode(f) < 0)
        missingFaces.push_back(f);
    if (firstFacets)
      rep.missingFacetsInitially = static_cast<int64_t>(missingFaces.size());
    firstFacets = false;
    if (missingFaces.empty())
      break;
    failedFaces.clear();
    const Status cavities = recoverFacetCavities(ed, bc, missingFaces, fallback, cavityStats, *pr);
    if (!cavities.ok())
      return cavities;
    bool edgesNeeded = false;
    for (int32_t f : missingFaces)
    {
      if (!bc.alive(f) || !fallback[static_cast<size_t>(bc.parent[f])])
        continue;
      const int32_t* s = bc.subface(f);
      if (ed.findFace(s[0], s[1], s[2]) >= 0)
        continue;
      if (ed.findEdge(s[0], s[1]) < 0 || ed.findEdge(s[1], s[2]) < 0 || ed.findEdge(s[2], s[0]) < 0)
      {
        edgesNeeded = true; // recovered by the edge stage of the next round
        continue;
      }
      if (ed.removalAttempts > workLimit)
        outOfWork = true;
      if (outOfWork || !rec.recoverFacetByFlips(s[0], s[1], s[2]))
        failedFaces.push_back(f);
    }
    if (failedFaces.empty() || edgesNeeded)
      continue; // re-check edges (flips never remove constraint edges, so this ends quickly)
    if (!options.allowSteiner || steinerUsed >= budget)
      break;
    for (int32_t f : failedFaces)
    {
      if (!bc.alive(f) || steinerUsed >= budget)
        continue;
      const int32_t* s = bc.subface(f);
      if (ed.findFace(s[0], s[1], s[2]) >= 0)
        continue;
      // Prefer splitting the longest edge when the facet is skinny (keeps the pieces well shaped).
      if (rec.splitFacet(f))
      {
        ++steinerUsed;
        changed = true;
      }
    }
    if (!changed)
      break;
  }

  const std::vector<int64_t> ids = finalCensus(ed, bc, census, rep);
  rep.facetCavities = static_cast<int64_t>(cavityStats.successes);
  rep.facetCavityEnlargements = static_cast<int64_t>(cavityStats.enlargements);
  rep.steinerSegment = rec.steinerSegment;
  rep.splitSegments = bc.splitSegments();
  rep.steinerFacet = rec.steinerFacet;
  rep.flips23 = ed.flips23 - f23;
  rep.flips32 = ed.flips32 - f32;
  rep.flipsEdgeRemoval = ed.flipsEdgeRemoval - fer;
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (report)
    *report = rep;
  if (rep.unrecoveredEdges || rep.unrecoveredFacets)
  {
    return Status::failure(ErrorKind::RecoveryFailed,
                           "Boundary recovery failed: " + std::to_string(rep.unrecoveredEdges) + " edge(s) and " +
                             std::to_string(rep.unrecoveredFacets) + " facet(s) could not be recovered (" +
                             std::to_string(steinerUsed) + " Steiner points used" +
                             (options.allowSteiner ? "" : ", Steiner points disabled") +
                             (outOfWork                        ? ", flip work budget exhausted"
                                : growing >= kMaxGrowingRounds ? ", missing edges kept growing"
                                : steinerUsed >= budget        ? ", Steiner budget exhausted"
                                                               : "") +
                             "); first input triangles listed.",
                           ids);
  }
  return Status::success();
}

} // namespace volgrid
