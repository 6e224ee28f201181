#include "SegmentConeSplit.h"

#include "Predicates.h"

#include <algorithm>
#include <array>

namespace volgrid
{

using predicates::orient3d;

namespace
{

// Exact: the open segment AB crosses the open triangle f (not through its edges or vertices).
bool crossesFaceInterior(const TetMesh& m, const int32_t f[3], const double* A, const double* B)
{
  const double *U = m.point(f[0]), *V = m.point(f[1]), *W = m.point(f[2]);
  if (orient3d(U, V, W, A) * orient3d(U, V, W, B) >= 0)
    return false;
  const int l1 = orient3d(A, B, U, V), l2 = orient3d(A, B, V, W), l3 = orient3d(A, B, W, U);
  return (l1 > 0 && l2 > 0 && l3 > 0) || (l1 < 0 && l2 < 0 && l3 < 0);
}

// Where segment AB meets the plane of triangle f (rounded).
void planeCrossing(const TetMesh& m, const int32_t f[3], const double* A, const double* B, double* out)
{
  const double *U = m.point(f[0]), *V = m.point(f[1]), *W = m.point(f[2]);
  long double e1[3], e2[3], n[3];
  for (int k = 0; k < 3; ++k)
  {
    e1[k] = static_cast<long double>(V[k]) - U[k];
    e2[k] = static_cast<long double>(W[k]) - U[k];
  }
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  long double num = 0, den = 0;
  for (int k = 0; k < 3; ++k)
  {
    num += n[k] * (static_cast<long double>(U[k]) - A[k]);
    den += n[k] * (static_cast<long double>(B[k]) - A[k]);
  }
  const long double t = std::clamp(num / den, 0.0L, 1.0L);
  for (int k = 0; k < 3; ++k)
    out[k] = static_cast<double>(A[k] + t * (static_cast<long double>(B[k]) - A[k]));
}

// Tets a cone may take in beyond the chain to see all its faces.
constexpr int kMaxGrowth = 64;

struct Link
{
  int32_t tet; // chain tet
  int entry;   // face index through which the segment enters it (-1 for the first tet)
  int exit;    // face index through which it leaves (-1 for the last tet)
};

// The chain of tets the open segment ab crosses, from a to b. False when it passes through an edge or
// vertex, leaves the mesh, or crosses a constraint face.
bool traceChain(MeshEditor& ed, const BoundaryConstraints& bc, int32_t a, int32_t b, std::vector<Link>& chain)
{
  const TetMesh& m = ed.mesh;
  const double *A = m.point(a), *B = m.point(b);
  chain.clear();
  std::vector<int32_t> star;
  ed.star(a, star);
  int32_t f[3];
  int32_t t = -1;
  int exitFace = -1;
  for (int32_t s : star)
  {
    const int i = m.localIndex(s, a);
    m.faceVertices(s, i, f);
    if (f[0] == b || f[1] == b || f[2] == b)
      return false; // ab is an edge already
    if (crossesFaceInterior(m, f, A, B))
    {
      t = s;
      exitFace = i;
      break;
    }
  }
  if (t < 0)
    return false;
  int entry = -1;
  for (int guard = 0; guard < 100000; ++guard)
  {
    if (exitFace < 0)
    {
      const int32_t* v = m.vertices(t);
      if (v[0] == b || v[1] == b || v[2] == b || v[3] == b)
      {
        chain.push_back({ t, entry, -1 });
        return true;
      }
      for (int i = 0; i < 4 && exitFace < 0; ++i)
      {
        if (i == entry)
          continue;
        m.faceVertices(t, i, f);
        if (crossesFaceInterior(m, f, A, B))
          exitFace = i;
      }
      if (exitFace < 0)
        return false; // through an edge or a vertex
    }
    m.faceVertices(t, exitFace, f);
    if (bc.findSubface(f[0], f[1], f[2]) >= 0)
      return false;
    const int32_t next = m.neighbor(t, exitFace);
    if (next < 0)
      return false;
    chain.push_back({ t, entry, exitFace });
    entry = m.mirrorFace(t, exitFace);
    t = next;
    exitFace = -1;
  }
  return false;
}

// A cavity made star-shaped from an apex by growth: it starts as the seed tets, takes in the tet beyond
// any face the apex does not see strictly (never across a constraint face or into `frozen`), and is
// replaced by the cone from the apex over its faces; faces through the apex (when it is a vertex) give
// no tet. With a fan, the cavity face fan->face of fan->tet is split in three at fan->point instead (the
// cone tets then hold the fan's triangles).
class ConeCavity
{
public:
  ConeCavity(MeshEditor& ed, const BoundaryConstraints& bc)
    : ed_(ed)
    , m_(ed.mesh)
    , bc_(bc)
  {
  }

  struct Fan
  {
    int32_t tet;
    int face;
    const double* point;
    int32_t id;
  };

  std::vector<int32_t> region;
  std::vector<std::array<int32_t, 4>> tets;

  // allowed(w): may the apex be joined to w?
  template<class Allowed>
  bool build(const std::vector<int32_t>& seed, const double* apex, int32_t apexId, int32_t frozen, const Fan* fan,
             const Allowed& allowed)
  {
    const uint32_t s = ed_.newStamp();
    region = seed;
    for (int32_t t : region)
      ed_.tetStamp[t] = s;
    int32_t f[3];
    for (int growth = 0; growth <= kMaxGrowth; ++growth)
    {
      tets.clear();
      keptEdges_.clear();
      keptVerts_.clear();
      int32_t grow = -1;
      for (size_t k = 0; k < region.size() && grow < 0; ++k)
      {
        const int32_t t = region[k];
        for (int fi = 0; fi < 4; ++fi)
        {
          const int32_t u = m_.neighbor(t, fi);
          m_.faceVertices(t, fi, f);
          if (u >= 0 && ed_.tetStamp[u] == s)
          {
            if (bc_.findSubface(f[0], f[1], f[2]) >= 0)
              return false; // a constraint face would vanish inside
            continue;
          }
          for (int e = 0; e < 3; ++e)
          {
            keptEdges_.push_back(edgeKey(f[e], f[(e + 1) % 3]));
            keptVerts_.push_back(f[e]);
          }
          if (fan && t == fan->tet && fi == fan->face)
          {
            for (int e = 0; e < 3; ++e)
            {
              const int32_t x = f[e], y = f[(e + 1) % 3];
              if (!allowed(x) || orient3d(m_.point(x), m_.point(y), fan->point, apex) <= 0)
                return false;
              tets.push_back({ x, y, fan->id, apexId });
            }
            continue;
          }
          if (f[0] == apexId || f[1] == apexId || f[2] == apexId)
            continue;
          if (!allowed(f[0]) || !allowed(f[1]) || !allowed(f[2]))
            return false;
          if (orient3d(m_.point(f[0]), m_.point(f[1]), m_.point(f[2]), apex) > 0)
          {
            tets.push_back({ f[0], f[1], f[2], apexId });
            continue;
          }
          if (u < 0 || u == frozen || bc_.findSubface(f[0], f[1], f[2]) >= 0)
            return false;
          grow = u;
          break;
        }
      }
      if (grow < 0)
        return keepsConstraints();
      ed_.tetStamp[grow] = s;
      region.push_back(grow);
    }
    return false;
  }

private:
  // Nothing may vanish inside the cavity: its vertices and constraint edges must be on its boundary.
  bool keepsConstraints()
  {
    std::sort(keptEdges_.begin(), keptEdges_.end());
    std::sort(keptVerts_.begin(), keptVerts_.end());
    static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (int32_t t : region)
    {
      const int32_t* v = m_.vertices(t);
      for (int i = 0; i < 4; ++i)
        if (!std::binary_search(keptVerts_.begin(), keptVerts_.end(), v[i]))
          return false;
      for (const auto& e : kEdge)
        if (bc_.isEdge(v[e[0]], v[e[1]]) &&
            !std::binary_search(keptEdges_.begin(), keptEdges_.end(), edgeKey(v[e[0]], v[e[1]])))
          return false;
    }
    return true;
  }

  MeshEditor& ed_;
  TetMesh& m_;
  const BoundaryConstraints& bc_;
  std::vector<uint64_t> keptEdges_;
  std::vector<int32_t> keptVerts_;
};

} // namespace

ConeStep coneStepAlongSegment(MeshEditor& ed, const BoundaryConstraints& bc, int32_t a, int32_t b,
                              const std::function<bool(int32_t)>& onLine, int32_t* newPoint)
{
  TetMesh& m = ed.mesh;
  if (ed.findEdge(a, b) >= 0)
    return ConeStep::Recovered;
  std::vector<Link> chain;
  if (!traceChain(ed, bc, a, b, chain))
    return ConeStep::Failed;
  // Copies: adding the point E may move the coordinate array.
  const double A[3] = { m.point(a)[0], m.point(a)[1], m.point(a)[2] };
  const double B[3] = { m.point(b)[0], m.point(b)[1], m.point(b)[2] };
  const size_t K = chain.size();
  ConeCavity cav(ed, bc);
  std::vector<int32_t> seed;
  int32_t f[3];
  double E[3];
  auto setSeed = [&](size_t n)
  {
    seed.clear();
    for (size_t k = 0; k < n; ++k)
      seed.push_back(chain[k].tet);
  };

  // The whole rest at once: the cone from a or from b over the chain.
  setSeed(K);
  // New edges from a or b: never to another point of the line but the other end or a piece, nor along
  // another split segment (BoundaryConstraints::forbiddenEdge).
  auto fromA = [&](int32_t w) { return (!onLine(w) || w == b || bc.isEdge(a, w)) && !bc.forbiddenEdge(a, w); };
  auto fromB = [&](int32_t w) { return (!onLine(w) || w == a || bc.isEdge(b, w)) && !bc.forbiddenEdge(b, w); };
  if (cav.build(seed, A, a, -1, nullptr, fromA) || cav.build(seed, B, b, -1, nullptr, fromB))
    return ed.replace(cav.region, cav.tets, nullptr) ? ConeStep::Recovered : ConeStep::Failed;

  // Else a piece a-E, E where ab crosses the exit face of chain[j]: the cone from a over chain[0..j]
  // with that face split at E (and the tet beyond it coned from E), or the cone from E over
  // chain[0..j+1]. The longest j that works.
  auto fromE = [&](int32_t w) { return !onLine(w) || w == a || w == b; };
  // The tet beyond the exit face, coned from E (which lies in its entry face), added to the cavity.
  auto coneBeyond = [&](int32_t t, int entry, int32_t eId)
  {
    for (int fi = 0; fi < 4; ++fi)
    {
      if (fi == entry)
        continue;
      m.faceVertices(t, fi, f);
      if (!fromE(f[0]) || !fromE(f[1]) || !fromE(f[2]) || orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), E) <= 0)
        return false;
      cav.tets.push_back({ f[0], f[1], f[2], eId });
    }
    cav.region.push_back(t);
    return true;
  };
  auto tryPiece = [&](size_t j, int32_t eId)
  {
    m.faceVertices(chain[j].tet, chain[j].exit, f);
    planeCrossing(m, f, A, B, E);
    setSeed(j + 1);
    const ConeCavity::Fan fan = { chain[j].tet, chain[j].exit, E, eId };
    const int32_t beyond = chain[j + 1].tet;
    // (the fan joins E to the crossed face's vertices: none may be on the line)
    if (!onLine(f[0]) && !onLine(f[1]) && !onLine(f[2]) &&
        cav.build(seed, A, a, beyond, &fan,
                  [&](int32_t w) { return (!onLine(w) || bc.isEdge(a, w)) && !bc.forbiddenEdge(a, w); }) &&
        coneBeyond(beyond, chain[j + 1].entry, eId))
      return true;
    setSeed(j + 2);
    return cav.build(seed, E, eId, -1, nullptr, fromE);
  };
  size_t best = K;
  for (size_t j = 0; j + 1 < K && tryPiece(j, -1); ++j)
    best = j;
  if (best == K)
    return ConeStep::Failed;
  const int32_t v = m.addPoint(E); // coordinates set again below: tryPiece recomputes E
  if (!tryPiece(best, v))
  {
    m.points.resize(m.points.size() - 3);
    return ConeStep::Failed;
  }
  double* P = m.points.data() + 3 * static_cast<size_t>(v);
  P[0] = E[0];
  P[1] = E[1];
  P[2] = E[2];
  if (!ed.replace(cav.region, cav.tets, nullptr))
  {
    m.points.resize(m.points.size() - 3);
    return ConeStep::Failed;
  }
  *newPoint = v;
  return ConeStep::Advanced;
}

} // namespace volgrid
