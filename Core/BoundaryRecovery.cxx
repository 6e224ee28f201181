#include "BoundaryRecovery.h"

#include "Quality.h"

#include "BoundaryCensus.h"
#include "FacetRecovery.h"
#include "Predicates.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

namespace volgrid
{

using predicates::orient3d;

TriKey::TriKey(int32_t a, int32_t b, int32_t c)
{
  if (a > b)
    std::swap(a, b);
  if (b > c)
    std::swap(b, c);
  if (a > b)
    std::swap(a, b);
  v[0] = a;
  v[1] = b;
  v[2] = c;
}

// ------------------------------------------------------------------------------------------------
// BoundaryConstraints

void BoundaryConstraints::init(const int32_t* triangles, int32_t numTriangles)
{
  verts.clear();
  parent.clear();
  faces_.clear();
  edges_.clear();
  numAlive_ = 0;
  nonManifold_ = 0;
  segmentOf_.clear();
  splitSegments_.clear();
  numInput_ = numTriangles;
  // A closed surface has 3/2 edges per triangle (Steiner splits grow the maps when needed).
  faces_.reserve(static_cast<size_t>(numTriangles));
  edges_.reserve(static_cast<size_t>(numTriangles) * 3 / 2);
  for (int32_t t = 0; t < numTriangles; ++t)
    addSubface(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2], t);
}

int32_t BoundaryConstraints::addSubface(int32_t a, int32_t b, int32_t c, int32_t par)
{
  const int32_t f = static_cast<int32_t>(parent.size());
  verts.push_back(a);
  verts.push_back(b);
  verts.push_back(c);
  parent.push_back(par);
  faces_.insert(TriKey(a, b, c), f) = f;
  ++numAlive_;
  const int32_t e[3][2] = { { a, b }, { b, c }, { c, a } };
  for (auto& ed : e)
  {
    bool fresh = false;
    std::array<int32_t, 2>& fs = edges_.insert(edgeKey(ed[0], ed[1]), { { f, -1 } }, &fresh);
    if (fresh)
      continue;
    if (fs[0] < 0)
      fs[0] = f;
    else if (fs[1] < 0)
      fs[1] = f;
    else
      ++nonManifold_;
  }
  return f;
}

void BoundaryConstraints::removeSubface(int32_t f)
{
  if (parent[f] < 0)
    return;
  const int32_t* v = subface(f);
  faces_.erase(TriKey(v[0], v[1], v[2]));
  for (int i = 0; i < 3; ++i)
  {
    const uint64_t key = edgeKey(v[i], v[(i + 1) % 3]);
    std::array<int32_t, 2>* fs = edges_.find(key);
    if (!fs)
      continue;
    if ((*fs)[0] == f)
      (*fs)[0] = -1;
    if ((*fs)[1] == f)
      (*fs)[1] = -1;
    if ((*fs)[0] < 0 && (*fs)[1] < 0)
      edges_.erase(key);
  }
  parent[f] = -1;
  --numAlive_;
}

void BoundaryConstraints::addSegmentPoint(int32_t v, int32_t a, int32_t b)
{
  auto ia = segmentOf_.find(a), ib = segmentOf_.find(b);
  const uint64_t seg = ia != segmentOf_.end() ? ia->second : ib != segmentOf_.end() ? ib->second : edgeKey(a, b);
  segmentOf_[v] = seg;
  splitSegments_.insert(seg);
}

bool BoundaryConstraints::forbiddenEdge(int32_t u, int32_t v) const
{
  if (splitSegments_.empty() || isEdge(u, v))
    return false;
  if (splitSegments_.count(edgeKey(u, v)))
    return true;
  auto iu = segmentOf_.find(u), iv = segmentOf_.find(v);
  auto onSeg = [](uint64_t seg, int32_t w) {
    return static_cast<int32_t>(seg >> 32) == w || static_cast<int32_t>(seg & 0xffffffffu) == w;
  };
  if (iu != segmentOf_.end() && (onSeg(iu->second, v) || (iv != segmentOf_.end() && iv->second == iu->second)))
    return true;
  return iv != segmentOf_.end() && onSeg(iv->second, u);
}

uint64_t BoundaryConstraints::segmentOf(int32_t a, int32_t b) const
{
  auto ia = segmentOf_.find(a);
  if (ia != segmentOf_.end())
    return ia->second;
  auto ib = segmentOf_.find(b);
  return ib != segmentOf_.end() ? ib->second : edgeKey(a, b);
}

int32_t BoundaryConstraints::findSubface(int32_t a, int32_t b, int32_t c) const
{
  const int32_t* f = faces_.find(TriKey(a, b, c));
  return f ? *f : -1;
}

const std::array<int32_t, 2>* BoundaryConstraints::edgeFaces(int32_t a, int32_t b) const
{
  return edges_.find(edgeKey(a, b));
}

// ------------------------------------------------------------------------------------------------
// MeshEditor

MeshEditor::MeshEditor(TetMesh& m)
  : mesh(m)
{
  rebuildVertexMap();
}

void MeshEditor::rebuildVertexMap()
{
  vertTet_.assign(static_cast<size_t>(mesh.numVertices()), -1);
  mesh.forEachTet([&](int32_t t) {
    const int32_t* v = mesh.vertices(t);
    for (int i = 0; i < 4; ++i)
      if (v[i] >= 0)
        vertTet_[v[i]] = t;
  });
}

int32_t MeshEditor::tetOf(int32_t v)
{
  if (v < 0)
    return -1;
  if (static_cast<size_t>(v) >= vertTet_.size())
    vertTet_.resize(static_cast<size_t>(mesh.numVertices()), -1);
  const int32_t t = vertTet_[v];
  if (t >= 0 && t < mesh.tetCapacity() && !mesh.isFree(t) && mesh.localIndex(t, v) >= 0)
    return t;
  // Stale entry (should not happen: every edit refreshes the vertices it touches): rescan.
  rebuildVertexMap();
  return vertTet_[v];
}

void MeshEditor::ensureStamp()
{
  if (tetStamp.size() < static_cast<size_t>(mesh.tetCapacity()))
    tetStamp.resize(static_cast<size_t>(mesh.tetCapacity()) + 1024, 0);
}

uint32_t MeshEditor::newStamp()
{
  ensureStamp();
  if (++stamp_ == 0)
  {
    std::fill(tetStamp.begin(), tetStamp.end(), 0);
    stamp_ = 1;
  }
  return stamp_;
}

void MeshEditor::star(int32_t v, std::vector<int32_t>& out)
{
  out.clear();
  const int32_t t0 = tetOf(v);
  if (t0 < 0)
    return;
  const uint32_t s = newStamp();
  out.push_back(t0);
  tetStamp[t0] = s;
  for (size_t k = 0; k < out.size(); ++k)
  {
    const int32_t t = out[k];
    const int li = mesh.localIndex(t, v);
    for (int i = 0; i < 4; ++i)
    {
      if (i == li)
        continue;
      const int32_t u = mesh.neighbor(t, i);
      if (u >= 0 && tetStamp[u] != s)
      {
        tetStamp[u] = s;
        out.push_back(u);
      }
    }
  }
}

int32_t MeshEditor::findEdge(int32_t a, int32_t b)
{
  star(a, tmpTets_);
  for (int32_t t : tmpTets_)
    if (mesh.localIndex(t, b) >= 0)
      return t;
  return -1;
}

int32_t MeshEditor::findFace(int32_t a, int32_t b, int32_t c, int* face)
{
  star(a, tmpTets_);
  for (int32_t t : tmpTets_)
  {
    if (mesh.localIndex(t, b) < 0 || mesh.localIndex(t, c) < 0)
      continue;
    if (face)
    {
      const int32_t* v = mesh.vertices(t);
      for (int i = 0; i < 4; ++i)
        if (v[i] != a && v[i] != b && v[i] != c)
          *face = i;
    }
    return t;
  }
  return -1;
}

static int permutationSign(int a, int b, int c, int d)
{
  const int p[4] = { a, b, c, d };
  int inv = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (p[i] > p[j])
        ++inv;
  return (inv & 1) ? -1 : 1;
}

bool MeshEditor::edgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring, std::vector<int32_t>& tets)
{
  ring.clear();
  tets.clear();
  const int ix = mesh.localIndex(t, x), iy = mesh.localIndex(t, y);
  if (ix < 0 || iy < 0)
    return false;
  int k = -1, l = -1;
  for (int i = 0; i < 4; ++i)
    if (i != ix && i != iy)
      (k < 0 ? k : l) = i;
  const int32_t* v = mesh.vertices(t);
  int32_t r0 = v[k], r1 = v[l];
  if (permutationSign(ix, iy, k, l) < 0)
    std::swap(r0, r1);
  int32_t cur = t, ra = r0, rb = r1;
  for (int guard = 0; guard < 4096; ++guard)
  {
    ring.push_back(ra);
    tets.push_back(cur);
    // Next tet: across the face of cur opposite ra (it contains x, y, rb).
    const int ia = mesh.localIndex(cur, ra);
    const int32_t nxt = mesh.neighbor(cur, ia);
    if (nxt < 0)
      return false;
    if (nxt == t)
      return true;
    const int32_t* w = mesh.vertices(nxt);
    int32_t rc = -1;
    for (int i = 0; i < 4; ++i)
      if (w[i] != x && w[i] != y && w[i] != rb)
        rc = w[i];
    if (rc < 0 || mesh.localIndex(nxt, x) < 0 || mesh.localIndex(nxt, y) < 0)
      return false;
    cur = nxt;
    ra = rb;
    rb = rc;
  }
  return false;
}

bool MeshEditor::replace(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets,
  std::vector<int32_t>* created, bool allowOpen)
{
  for (int32_t t : oldTets)
    mesh.tetFlags[t] |= TetMesh::kMarkA;
  bfaces_.clear();
  int32_t f[3];
  for (int32_t t : oldTets)
    for (int i = 0; i < 4; ++i)
    {
      const int32_t code = mesh.neighborCode(t, i);
      if (code >= 0 && (mesh.tetFlags[code >> 2] & TetMesh::kMarkA))
        continue;
      mesh.faceVertices(t, i, f);
      bfaces_.push_back({ TriKey(f[0], f[1], f[2]), code });
    }
  for (int32_t t : oldTets)
    mesh.tetFlags[t] &= static_cast<uint8_t>(~TetMesh::kMarkA);
  nfaces_.clear();
  for (size_t n = 0; n < newTets.size(); ++n)
  {
    const auto& q = newTets[n];
    for (int i = 0; i < 4; ++i)
    {
      const int* fv = TetMesh::kFaceVertex[i];
      nfaces_.push_back({ TriKey(q[fv[0]], q[fv[1]], q[fv[2]]), static_cast<int32_t>(n), i });
    }
  }
  auto lessB = [](const BFace& a, const BFace& b) { return a.key < b.key; };
  auto lessN = [](const NFace& a, const NFace& b) { return a.key < b.key; };
  std::sort(bfaces_.begin(), bfaces_.end(), lessB);
  std::sort(nfaces_.begin(), nfaces_.end(), lessN);
  // Verify: every new face is either shared by exactly two new tets or matches exactly one old boundary
  // face, and every old boundary face is matched.
  size_t matched = 0;
  for (size_t i = 0; i + 1 < bfaces_.size(); ++i)
    if (bfaces_[i].key == bfaces_[i + 1].key)
      return false;
  for (size_t i = 0; i < nfaces_.size();)
  {
    size_t j = i + 1;
    while (j < nfaces_.size() && nfaces_[j].key == nfaces_[i].key)
      ++j;
    const size_t cnt = j - i;
    const bool inB = std::binary_search(bfaces_.begin(), bfaces_.end(), BFace{ nfaces_[i].key, 0 }, lessB);
    if (cnt == 1 && inB)
      ++matched;
    else if (!(cnt == 2 && !inB) && !(allowOpen && cnt == 1))
      return false;
    i = j;
  }
  if (matched != bfaces_.size() && !allowOpen)
    return false;
  if (allowOpen)
  {
    // Outer tets whose face is not matched lose that neighbour.
    for (const BFace& b : bfaces_)
    {
      if (b.code < 0)
        continue;
      auto it = std::lower_bound(nfaces_.begin(), nfaces_.end(), NFace{ b.key, 0, 0 }, lessN);
      if (it == nfaces_.end() || !(it->key == b.key))
        mesh.unlink(b.code >> 2, b.code & 3);
    }
  }

  // Commit.
  for (int32_t t : oldTets)
    mesh.freeTet(t);
  tmpTets_.resize(newTets.size());
  for (size_t n = 0; n < newTets.size(); ++n)
  {
    const auto& q = newTets[n];
    tmpTets_[n] = mesh.newTet(q[0], q[1], q[2], q[3]);
    for (int i = 0; i < 4; ++i)
    {
      if (static_cast<size_t>(q[i]) >= vertTet_.size())
        vertTet_.resize(static_cast<size_t>(mesh.numVertices()), -1);
      vertTet_[q[i]] = tmpTets_[n];
    }
  }
  for (size_t i = 0; i < nfaces_.size();)
  {
    size_t j = i + 1;
    while (j < nfaces_.size() && nfaces_[j].key == nfaces_[i].key)
      ++j;
    const int32_t ta = tmpTets_[nfaces_[i].tet];
    if (j - i == 2)
      mesh.link(ta, nfaces_[i].face, tmpTets_[nfaces_[i + 1].tet], nfaces_[i + 1].face);
    else
    {
      auto it = std::lower_bound(bfaces_.begin(), bfaces_.end(), BFace{ nfaces_[i].key, 0 }, lessB);
      if (it == bfaces_.end() || !(it->key == nfaces_[i].key) || it->code < 0)
        mesh.unlink(ta, nfaces_[i].face);
      else
        mesh.link(ta, nfaces_[i].face, it->code >> 2, it->code & 3);
    }
    i = j;
  }
  if (created)
    *created = tmpTets_;
  ++edits;
  return true;
}

bool MeshEditor::flip23(int32_t t, int face, const BoundaryConstraints* bc, std::vector<int32_t>* created)
{
  const int32_t u = mesh.neighbor(t, face);
  if (u < 0)
    return false;
  int32_t f[3];
  mesh.faceVertices(t, face, f);
  if (bc && bc->findSubface(f[0], f[1], f[2]) >= 0)
    return false;
  const int32_t p = mesh.vertex(t, face);
  const int32_t q = mesh.vertex(u, mesh.mirrorFace(t, face));
  if (bc && bc->forbiddenEdge(p, q))
    return false;
  const double *P = mesh.point(p), *Q = mesh.point(q), *A = mesh.point(f[0]), *B = mesh.point(f[1]),
               *C = mesh.point(f[2]);
  if (orient3d(Q, B, C, P) <= 0 || orient3d(A, Q, C, P) <= 0 || orient3d(A, B, Q, P) <= 0)
    return false;
  tmpNew_.clear();
  tmpNew_.push_back({ { q, f[1], f[2], p } });
  tmpNew_.push_back({ { f[0], q, f[2], p } });
  tmpNew_.push_back({ { f[0], f[1], q, p } });
  lastRemoved.clear();
  lastRemoved.push_back({ { mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2), mesh.vertex(t, 3) } });
  lastRemoved.push_back({ { mesh.vertex(u, 0), mesh.vertex(u, 1), mesh.vertex(u, 2), mesh.vertex(u, 3) } });
  std::vector<int32_t> old = { t, u };
  if (!replace(old, tmpNew_, created))
    return false;
  lastRemovedIds = old;
  ++flips23;
  return true;
}


bool MeshEditor::removeEdge(int32_t t, int32_t x, int32_t y, const BoundaryConstraints* bc, std::vector<int32_t>* created,
  std::array<int32_t, 2> chord)
{
  if (bc && bc->isEdge(x, y))
    return false;
  ++removalAttempts;
  std::vector<int32_t>& ring = tmpRing_;
  std::vector<int32_t> tets;
  if (!edgeRing(t, x, y, ring, tets))
    return false;
  const int n = static_cast<int>(ring.size());
  if (n < 3 || n > 48)
    return false;
  const double* X = mesh.point(x);
  const double* Y = mesh.point(y);
  const double kInvalid = -std::numeric_limits<double>::infinity();
  std::vector<double> best(static_cast<size_t>(n * n), kInvalid);
  std::vector<int> choice(static_cast<size_t>(n * n), -1);
  auto chordOk = [&](int i, int j) { return j == i + 1 || (i == 0 && j == n - 1) || !bc->forbiddenEdge(ring[i], ring[j]); };
  // A required chord (positions ci < cj in the ring): no chord of the triangulation may cross it.
  int ci = -1, cj = -1;
  if (chord[0] >= 0)
  {
    for (int i = 0; i < n; ++i)
    {
      if (ring[i] == chord[0] || ring[i] == chord[1])
        (ci < 0 ? ci : cj) = i;
    }
    if (cj < 0)
      return false;
  }
  auto crossesChord = [&](int i, int j) { // i < j
    if (ci < 0)
      return false;
    const bool inI = i < ci && ci < j, inJ = i < cj && cj < j;
    const bool atI = i == ci || j == ci, atJ = i == cj || j == cj;
    return !atI && !atJ && inI != inJ;
  };
  auto triQ = [&](int i, int k, int j) -> double {
    if (bc && (!chordOk(i, k) || !chordOk(k, j) || !chordOk(i, j)))
      return kInvalid;
    if (crossesChord(i, k) || crossesChord(k, j) || crossesChord(i, j))
      return kInvalid;
    const double *A = mesh.point(ring[i]), *B = mesh.point(ring[k]), *C = mesh.point(ring[j]);
    if (orient3d(A, B, C, Y) <= 0 || orient3d(A, C, B, X) <= 0)
      return kInvalid;
    return std::min(quality::tetShapeMeasure(A, B, C, Y), quality::tetShapeMeasure(A, C, B, X));
  };
  for (int len = 1; len < n; ++len)
    for (int i = 0; i + len < n; ++i)
    {
      const int j = i + len;
      if (len == 1)
      {
        best[i * n + j] = std::numeric_limits<double>::infinity();
        continue;
      }
      double bq = kInvalid;
      int bk = -1;
      for (int k = i + 1; k < j; ++k)
      {
        const double sub = std::min(best[i * n + k], best[k * n + j]);
        if (!(sub > bq))
          continue;
        const double q = std::min(sub, triQ(i, k, j));
        if (q > bq)
        {
          bq = q;
          bk = k;
        }
      }
      best[i * n + j] = bq;
      choice[i * n + j] = bk;
    }
  if (!(best[n - 1] > kInvalid))
    return false;
  tmpNew_.clear();
  std::vector<std::pair<int, int>> stack = { { 0, n - 1 } };
  while (!stack.empty())
  {
    auto [i, j] = stack.back();
    stack.pop_back();
    if (j - i < 2)
      continue;
    const int k = choice[i * n + j];
    tmpNew_.push_back({ { ring[i], ring[k], ring[j], y } });
    tmpNew_.push_back({ { ring[i], ring[j], ring[k], x } });
    stack.push_back({ i, k });
    stack.push_back({ k, j });
  }
  lastRemoved.clear();
  for (int32_t u : tets)
    lastRemoved.push_back({ { mesh.vertex(u, 0), mesh.vertex(u, 1), mesh.vertex(u, 2), mesh.vertex(u, 3) } });
  if (!replace(tets, tmpNew_, created))
    return false;
  lastRemovedIds = tets;
  if (n == 3)
    ++flips32;
  else
    ++flipsEdgeRemoval;
  return true;
}

bool MeshEditor::removeEdgeDeep(int32_t t, int32_t x, int32_t y, const BoundaryConstraints* bc,
  std::vector<int32_t>* created, int depth, std::array<int32_t, 2> chord)
{
  if (removeEdge(t, x, y, bc, created, chord))
    return true;
  if (depth <= 0 || (bc && bc->isEdge(x, y)))
    return false;
  std::vector<int32_t> ring, tets;
  if (!edgeRing(t, x, y, ring, tets) || ring.size() <= 3 || ring.size() > 16)
    return false;
  for (size_t i = 0; i < ring.size(); ++i)
    for (int32_t e : { x, y })
    {
      const int32_t r = ring[i];
      if (bc && bc->isEdge(e, r))
        continue;
      const int32_t tt = findEdge(e, r);
      if (tt < 0)
        continue;
      std::vector<int32_t> sub;
      if (!removeEdgeDeep(tt, e, r, bc, &sub, depth - 1))
        continue;
      std::vector<std::array<int32_t, 4>> orig = lastRemoved;
      std::vector<int32_t> current = sub;
      const int32_t t2 = findEdge(x, y);
      std::vector<int32_t> fin;
      if (t2 >= 0 && removeEdge(t2, x, y, bc, &fin, chord))
      {
        // Compose: what the two flips removed from the original mesh, and what now covers it.
        for (size_t k = 0; k < lastRemovedIds.size(); ++k)
        {
          auto it = std::find(current.begin(), current.end(), lastRemovedIds[k]);
          if (it != current.end())
            current.erase(it);
          else
            orig.push_back(lastRemoved[k]);
        }
        // Ids recycled by the second flip may coincide with ids left in `current`: those are new tets.
        for (int32_t c : fin)
        {
          auto it = std::find(current.begin(), current.end(), c);
          if (it == current.end())
            current.push_back(c);
        }
        lastRemoved = orig;
        if (created)
          *created = current;
        return true;
      }
      // Undo the ring reduction.
      replace(sub, orig, nullptr);
    }
  return false;
}

int32_t MeshEditor::locate(const double* p, int32_t start)
{
  int32_t t = start;
  if (t < 0 || mesh.isFree(t))
    return -1;
  int32_t f[3];
  uint32_t rot = 0;
  const int64_t limit = 4 * static_cast<int64_t>(mesh.numTets()) + 100;
  for (int64_t step = 0; step < limit; ++step)
  {
    int next = -1;
    const int r = static_cast<int>(rot++ & 3);
    for (int k = 0; k < 4; ++k)
    {
      const int i = (k + r) & 3;
      mesh.faceVertices(t, i, f);
      if (orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p) < 0)
      {
        next = i;
        break;
      }
    }
    if (next < 0)
      return t;
    t = mesh.neighbor(t, next);
    if (t < 0)
      return -1;
  }
  return -1;
}

bool MeshEditor::insertVertex(int32_t v, int32_t start, const BoundaryConstraints* bc)
{
  const double* p = mesh.point(v);
  const int32_t t0 = locate(p, start);
  if (t0 < 0)
    return false;
  if (vertTet_.size() < static_cast<size_t>(mesh.numVertices()))
    vertTet_.resize(static_cast<size_t>(mesh.numVertices()), -1);
  int32_t f[3];
  // Roots: tets whose closure contains p.
  std::vector<int32_t> roots = { t0 };
  const uint32_t sRoot = newStamp();
  tetStamp[t0] = sRoot;
  for (size_t k = 0; k < roots.size(); ++k)
  {
    const int32_t t = roots[k];
    for (int i = 0; i < 4; ++i)
    {
      mesh.faceVertices(t, i, f);
      const int o = orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p);
      if (o < 0)
        return false; // not in the closure: locate() is inconsistent
      if (o > 0)
        continue;
      if (f[0] == v || f[1] == v || f[2] == v)
        return false;
      // p on this face: the tet beyond must be split too.
      const int32_t u = mesh.neighbor(t, i);
      if (u < 0 || (bc && bc->findSubface(f[0], f[1], f[2]) >= 0))
        return false;
      if (tetStamp[u] != sRoot)
      {
        tetStamp[u] = sRoot;
        roots.push_back(u);
      }
    }
  }
  // A vertex at p already?
  for (int32_t t : roots)
    for (int i = 0; i < 4; ++i)
    {
      const double* q = mesh.point(mesh.vertex(t, i));
      if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2])
        return false;
    }
  // Bowyer-Watson growth (insphere is only a heuristic for the cavity's size here; validity is exact
  // below).
  const uint32_t sCav = newStamp();
  std::vector<int32_t>& cav = cavity_;
  cav = roots;
  for (int32_t t : cav)
    tetStamp[t] = sCav;
  // Bowyer-Watson growth; when it would delete a recovered boundary edge (every tet around the edge in
  // the cavity) the cavity falls back to the tets whose closure contains p (1-4, 2-6 or n-2n split, the
  // paper's "connect the intersection point to the polyhedron").
  const size_t maxCavity = 4096;
  for (size_t k = 0; k < cav.size() && cav.size() < maxCavity; ++k)
  {
    const int32_t t = cav[k];
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = mesh.neighbor(t, i);
      if (u < 0 || tetStamp[u] == sCav)
        continue;
      mesh.faceVertices(t, i, f);
      if (bc && bc->findSubface(f[0], f[1], f[2]) >= 0)
        continue;
      const int32_t* w = mesh.vertices(u);
      if (predicates::insphere(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]), p) > 0)
      {
        tetStamp[u] = sCav;
        cav.push_back(u);
      }
    }
  }
  if (bc && cav.size() > roots.size())
  {
    bool kills = false;
    std::vector<int32_t> ring, rtets;
    static const int kE[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (size_t k = 0; k < cav.size() && !kills; ++k)
    {
      const int32_t* w = mesh.vertices(cav[k]);
      for (auto& e : kE)
      {
        if (!bc->isEdge(w[e[0]], w[e[1]]))
          continue;
        if (!edgeRing(cav[k], w[e[0]], w[e[1]], ring, rtets))
          continue;
        bool all = true;
        for (int32_t u : rtets)
          all = all && tetStamp[u] == sCav;
        if (all)
        {
          kills = true;
          break;
        }
      }
    }
    if (kills)
    {
      for (int32_t t : cav)
        tetStamp[t] = 0;
      cav = roots;
      for (int32_t t : cav)
        tetStamp[t] = sCav;
    }
  }
  auto isRoot = [&](int32_t t) { return std::find(roots.begin(), roots.end(), t) != roots.end(); };
  // Make it star-shaped from p: drop tets with a boundary face p does not see strictly.
  for (int round = 0; round < 1000; ++round)
  {
    bool changed = false;
    for (size_t k = 0; k < cav.size(); ++k)
    {
      const int32_t t = cav[k];
      if (tetStamp[t] != sCav)
        continue;
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = mesh.neighbor(t, i);
        if (u >= 0 && tetStamp[u] == sCav)
          continue;
        mesh.faceVertices(t, i, f);
        if (orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p) > 0)
          continue;
        if (isRoot(t))
          return false;
        tetStamp[t] = 0;
        changed = true;
        break;
      }
    }
    // Keep only what is connected to the roots.
    const uint32_t sConn = newStamp();
    std::vector<int32_t>& q = queue_;
    q.clear();
    for (int32_t r : roots)
    {
      q.push_back(r);
      tetStamp[r] = sConn;
    }
    for (size_t k = 0; k < q.size(); ++k)
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = mesh.neighbor(q[k], i);
        if (u >= 0 && tetStamp[u] == sCav)
        {
          tetStamp[u] = sConn;
          q.push_back(u);
        }
      }
    const size_t before = cav.size();
    cav.clear();
    for (int32_t t : q)
      cav.push_back(t);
    // Re-stamp as the cavity stamp for the next round.
    for (int32_t t : cav)
      tetStamp[t] = sCav;
    if (!changed && cav.size() == before)
      break;
    if (!changed)
      break;
  }
  // Final validation and new tets.
  tmpNew_.clear();
  for (int32_t t : cav)
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = mesh.neighbor(t, i);
      if (u >= 0 && tetStamp[u] == sCav)
        continue;
      mesh.faceVertices(t, i, f);
      if (orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p) <= 0)
        return false;
      tmpNew_.push_back({ { f[0], f[1], f[2], v } });
    }
  std::vector<int32_t> old = cav;
  return replace(old, tmpNew_, nullptr);
}

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
    auto push = [&](int32_t u) {
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
    auto push = [&](int32_t u) {
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

  bool recoverEdgeByFlips(int32_t a, int32_t b)
  {
    std::vector<Crossing> faces, edges, f2, e2;
    std::vector<int32_t> created;
    int sideways = 0;
    for (int iter = 0; iter < 500; ++iter)
    {
      if (ed_.findEdge(a, b) >= 0)
        return true;
      if (!traceSegment(a, b, faces, edges))
        return false;
      const size_t m0 = faces.size() + edges.size();
      if (m0 == 0)
        return false;
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
            !ed_.flipInPlane(t, c.a, c.b, chord[0], chord[1], &bc_, &created, &kinds_)) &&
          ((t = ed_.findEdge(c.a, c.b)) < 0 || !ed_.removeEdgeDeep(t, c.a, c.b, &bc_, &created, 2)))
          continue;
        if (ed_.findEdge(a, b) >= 0)
          return true;
        // Like Sloan's 2D algorithm, a flip that keeps the count may still be needed (coplanar
        // crossings); a few such sideways steps are allowed.
        if (traceSegment(a, b, f2, e2) &&
          (f2.size() + e2.size() < m0 || (f2.size() + e2.size() == m0 && sideways < 64)))
        {
          if (f2.size() + e2.size() == m0)
            ++sideways;
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
    std::vector<Crossing> faces, edges, f2, e2;
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
        if (ed_.findEdge(a, b) >= 0)
          return true;
        if (traceSegment(a, b, f2, e2) && (f2.size() + e2.size() < m0 || (f2.size() + e2.size() == m0 && sideways < 64)))
        {
          if (f2.size() + e2.size() == m0)
            ++sideways;
          return true;
        }
        undo(created);
      }
    }
    return false;
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
      auto better = [&]() {
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
      auto consider = [&](int32_t q) {
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
    return true;
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
};

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
  const int64_t budget = options.maxSteinerPoints >= 0 ? options.maxSteinerPoints
                                                       : 4 * static_cast<int64_t>(bc.numInputTriangles()) + 1000;
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
  auto requiredEdge = [&](int32_t a, int32_t b) {
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
  auto collectMissingEdges = [&](const std::unordered_set<uint64_t>* only) {
    missingEdges.clear();
    if (!census.upToDate(ed, bc))
      census.take(ed, bc);
    std::vector<uint8_t> seen(static_cast<size_t>(census.edgeIdLimit()), 0);
    for (int32_t f = 0; f < bc.capacity(); ++f)
    {
      if (!bc.alive(f))
        continue;
      const int32_t* s = bc.subface(f);
      for (int i = 0; i < 3; ++i)
      {
        const int32_t a = s[i], b = s[(i + 1) % 3];
        const int32_t id = census.edgeId(a, b); // -1: degenerate, never present
        if (id >= 0 && seen[static_cast<size_t>(id)])
          continue;
        if (id >= 0)
          seen[static_cast<size_t>(id)] = 1;
        if ((id < 0 || !census.edgePresent(id)) && requiredEdge(a, b) &&
          (!only || only->count(bc.segmentOf(a, b))))
          missingEdges.push_back({ a, b });
      }
    }
  };
  if (options.presplitSegments && !options.presplitSegments->empty() && options.allowSteiner)
  {
    // Presplit stage (see RecoveryOptions::presplitSegments); insertVertex without constraints is the
    // Bowyer-Watson insertion, so the mesh stays Delaunay.
    // At most one presplit point per input triangle: beyond that (segments of needle triangles, whose
    // pieces would have to be as short as the needles are thin) the retry would only end in a slow
    // Steiner removal of thousands of points.
    const int64_t presplitBudget = std::min<int64_t>(budget, bc.numInputTriangles());
    bool converged = false;
    for (int round = 0; round < 64 && steinerUsed < presplitBudget; ++round)
    {
      collectMissingEdges(options.presplitSegments);
      if (missingEdges.empty())
      {
        converged = true;
        break;
      }
      bool split = false;
      for (auto [a, b] : missingEdges)
        if (bc.isEdge(a, b) && ed.findEdge(a, b) < 0 && steinerUsed < presplitBudget && rec.splitEdge(a, b, true))
        {
          ++steinerUsed;
          ++rep.presplitPoints;
          split = true;
        }
      if (!split)
        break;
    }
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
        if (rec.splitEdge(a, b))
        {
          ++steinerUsed;
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
    done = 0;
    // Cavity retetrahedralization of each input triangle with missing subfaces (all segments present).
    {
      std::unordered_map<int32_t, std::vector<int32_t>> byParent;
      for (int32_t f : missingFaces)
        if (!fallback[static_cast<size_t>(bc.parent[f])])
          byParent.emplace(bc.parent[f], std::vector<int32_t>());
      if (!byParent.empty())
      {
        for (int32_t f = 0; f < bc.capacity(); ++f)
          if (bc.alive(f))
          {
            auto it = byParent.find(bc.parent[f]);
            if (it != byParent.end())
              it->second.push_back(f);
          }
        for (auto& [par, subs] : byParent)
        {
          if (++done % 256 == 0)
          {
            pr->report(0.5 + 0.5 * static_cast<double>(done) / byParent.size(), "Recovering boundary facets");
            if (pr->cancelled())
              return Status::failure(ErrorKind::Cancelled, "Boundary recovery was cancelled.");
          }
          if (!recoverFacetByCavity(ed, bc, par, subs, &cavityStats) &&
            !recoverFacetByPieces(ed, bc, par, subs, &cavityStats) &&
            !recoverFacetBySlab(ed, bc, par, subs, &cavityStats))
            fallback[static_cast<size_t>(par)] = 1;
        }
      }
    }
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

  // Final census.
  std::vector<int64_t> badEdges, badFaces;
  {
    if (!census.upToDate(ed, bc))
      census.take(ed, bc);
    std::vector<uint8_t> seen(static_cast<size_t>(census.edgeIdLimit()), 0);
    for (int32_t f = 0; f < bc.capacity(); ++f)
    {
      if (!bc.alive(f))
        continue;
      const int32_t* s = bc.subface(f);
      bool faceOk = true;
      for (int i = 0; i < 3; ++i)
      {
        const int32_t a = s[i], b = s[(i + 1) % 3];
        const int32_t id = census.edgeId(a, b);
        const bool firstSeen = id < 0 || !seen[static_cast<size_t>(id)];
        if (id >= 0)
          seen[static_cast<size_t>(id)] = 1;
        if (firstSeen && (id < 0 || !census.edgePresent(id)))
        {
          ++rep.unrecoveredEdges;
          faceOk = false;
          if (badEdges.size() < 5)
            badEdges.push_back(bc.parent[f]);
        }
      }
      if (faceOk && census.faceCode(f) < 0)
      {
        ++rep.unrecoveredFacets;
        if (badFaces.size() < 5)
          badFaces.push_back(bc.parent[f]);
      }
    }
  }
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
    std::vector<int64_t> ids = badEdges;
    ids.insert(ids.end(), badFaces.begin(), badFaces.end());
    return Status::failure(ErrorKind::RecoveryFailed,
      "Boundary recovery failed: " + std::to_string(rep.unrecoveredEdges) + " edge(s) and " +
        std::to_string(rep.unrecoveredFacets) + " facet(s) could not be recovered (" +
        std::to_string(steinerUsed) + " Steiner points used" +
        (options.allowSteiner ? "" : ", Steiner points disabled") +
        (outOfWork ? ", flip work budget exhausted"
                   : growing >= kMaxGrowingRounds ? ", missing edges kept growing"
                                                  : steinerUsed >= budget ? ", Steiner budget exhausted" : "") +
        "); first input triangles listed.",
      ids);
  }
  return Status::success();
}

} // namespace volgrid
