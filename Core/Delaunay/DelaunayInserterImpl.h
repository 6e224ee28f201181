// Internal header of the Delaunay kernel (Delaunay.cxx, DelaunayInserter.cxx, DelaunayParallel.cxx,
// DelaunayCanonical.cxx): the inserter's state and its walk / cavity / insertion code, the tables
// shared by those files, and the kernel's internal entry points. Not part of Core's interface.
#pragma once

#include "Delaunay.h"
#include "PredicatesInline.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <cstring>
#include <vector>

namespace volgrid
{
namespace delaunay_detail
{
constexpr int kFV[4][3] = { { 1, 3, 2 }, { 0, 2, 3 }, { 0, 3, 1 }, { 0, 1, 2 } };
// Transient marks during one insertion, in the sign bit of neighbour codes (codes are >= 0 while ghost
// tets exist): bit 31 of tetNeighbors[4t] = t is in the cavity, of tetNeighbors[4t+1] = t was tested and
// is not in conflict. Those words are read or written anyway, unlike a separate flag array.
constexpr uint32_t kMarkBit = 0x80000000u;
constexpr int32_t kCodeMask = 0x7fffffff;

// The hot loop uses the inline filtered predicates (PredicatesInline.h): same results as Predicates.h.
constexpr double kInsphereFilter2 =
  (24.0 * predicates::detail::kInsphereBound) * (24.0 * predicates::detail::kInsphereBound) * (1.0 + 0x1p-20);

inline bool samePoint(const double* a, const double* b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Key of the undirected edge {a,b} (a or b may be kGhostVertex).
inline uint64_t edgeKey(int32_t a, int32_t b)
{
  const uint32_t x = static_cast<uint32_t>(a + 1), y = static_cast<uint32_t>(b + 1);
  return x < y ? (uint64_t(x) << 32) | y : (uint64_t(y) << 32) | x;
}

// For a new tet with the cavity face opposite `f`, the face g (g != f) contains the new point and the
// edge made of the two local indices other than f and g: kOther[f][g] = {x, y}.
struct EdgePair
{
  int8_t x, y;
};
constexpr EdgePair kOther[4][4] = {
  { { -1, -1 }, { 2, 3 }, { 1, 3 }, { 1, 2 } },
  { { 2, 3 }, { -1, -1 }, { 0, 3 }, { 0, 2 } },
  { { 1, 3 }, { 0, 3 }, { -1, -1 }, { 0, 1 } },
  { { 1, 2 }, { 0, 2 }, { 0, 1 }, { -1, -1 } },
};
// Same pair, directed: face g of the new tet read cyclically from the new point (at position f) is
// (new point, x, y). The new tet across that face lists the same edge as (y, x).
constexpr EdgePair kDirected[4][4] = {
  { { -1, -1 }, { 2, 3 }, { 3, 1 }, { 1, 2 } },
  { { 3, 2 }, { -1, -1 }, { 0, 3 }, { 2, 0 } },
  { { 1, 3 }, { 3, 0 }, { -1, -1 }, { 0, 1 } },
  { { 2, 1 }, { 0, 2 }, { 1, 0 }, { -1, -1 } },
};

// Rounds at least this large run on several threads (buildDelaunay with threads > 1), for inputs at
// least kParallelMinPoints large, cut into chunks of at least kParallelMinChunk points (one per worker).
// Workers are told apart by a one-byte owner id per tet (1..255; 0 = free): at most 255 workers.
constexpr size_t kParallelMinPoints = 200000;
constexpr size_t kParallelMinRound = 50000;
constexpr int32_t kParallelMinChunk = 8192;
constexpr int kMaxParallelWorkers = 255;
} // namespace delaunay_detail

using namespace delaunay_detail;

// ---------------------------------------------------------------------------------------------------
struct DelaunayInserter::Impl
{
  TetMesh& mesh;
  uint64_t rng;
  int32_t last = -1;
  uint64_t walkSteps = 0;
  uint64_t cavityTets = 0;
  const int32_t* sosId = nullptr; // optional: SoS id of each vertex (default: the vertex id)
  // Lattice mode (see latticeUnit): limits on the coordinate differences for exact double evaluation;
  // negative = off. Only buildDelaunay turns it on (later points need not be on the lattice).
  double latticeOrientLimit = -1, latticeInsphereLimit2 = -1; // the latter squared

  int orient(const double* a, const double* b, const double* c, const double* d) const
  {
    if (latticeOrientLimit > 0)
    {
      const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
      const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
      const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
      const double m = std::max({ std::fabs(ux), std::fabs(uy), std::fabs(uz), std::fabs(vx), std::fabs(vy),
                                  std::fabs(vz), std::fabs(wx), std::fabs(wy), std::fabs(wz) });
      if (m <= latticeOrientLimit)
      {
        const double det = (ux * (vy * wz - vz * wy) + uy * (vz * wx - vx * wz)) + uz * (vx * wy - vy * wx);
        return (det > 0) - (det < 0);
      }
    }
    return predicates::orient3dInline(a, b, c, d);
  }

  // Exact insphere sign (0 when cospherical); the SoS tie-break is the caller's. Fast path: the
  // determinant with the expression tree of PredicatesInline.h, whose forward error is at most
  // gamma_16 * P (P = sum of the absolute monomials, see Predicates.cxx). P is bounded from the lifted
  // values w_i = |p_i - e|^2 without computing it: P = sum_i w_i q_i, where q_i is the permanent of the
  // other three rows of |coordinates|, at most the product of their row sums (<= sqrt(3 w_j)), so
  // P <= 4 W * 3^(3/2) W^(3/2) <= 24 W^(5/2) with W = max w_i. The test |det| > gamma_16 * 24 W^(5/2) is
  // done squared (no square root) with a relative margin of 2^-20 for the rounding of both sides.
  // Restricting W to [2^-200, 2^200] rules out overflow and keeps gradual underflow below 2^-800 of
  // the bound. Uncertain cases go to the exact predicate.
  int insphere(const double* a, const double* b, const double* c, const double* d, const double* e) const
  {
    const predicates::detail::InsphereTerms<double> t = predicates::detail::insphereTerms<double>(a, b, c, d, e);
    const double det = -t.det; // > 0: e inside (the negation is exact)
    const double w0 = t.w[0], w1 = t.w[1], w2 = t.w[2], w3 = t.w[3];
    const double W = std::max(std::max(w0, w1), std::max(w2, w3));
    if (W <= latticeInsphereLimit2)
      return (det > 0) - (det < 0); // exact (lattice input, differences <= 2^9 units)
    const double W2 = W * W;
    if (det * det > kInsphereFilter2 * (W2 * W2 * W) && W >= 0x1p-200 && W <= 0x1p200)
      return (det > 0) - (det < 0);
    return predicates::insphere(a, b, c, d, e);
  }

  // Parallel construction (buildDelaunay with threads > 1): tets are owned by one thread at a time
  // (owner[t] = thread id + 1, acquired with compare-exchange before any read, released at the end of
  // the insertion); an insertion that meets a tet owned by the other thread is undone and reported as
  // aborted (the caller inserts it later, alone). New slots come from a pre-allocated pool.
  std::atomic<uint8_t>* owner = nullptr;
  uint8_t me = 0;
  std::vector<int32_t> held, spare;
  std::atomic<int32_t>* nextSlot = nullptr; // pool mode: next unused slot, pool ends at slotLimit
  int32_t slotLimit = 0;
  bool lockFailed = false, poolFull = false;
  int32_t poolEnd = INT32_MAX;   // smallest failed pool position (the pool's used part ends there)
  int32_t pendingGhostDelta = 0; // pool mode: ghost count changes not yet reported to the mesh

  bool acquire(int32_t t)
  {
    if (!owner)
      return true;
    uint8_t cur = owner[t].load(std::memory_order_relaxed);
    if (cur == me)
      return true;
    cur = 0;
    if (!owner[t].compare_exchange_strong(cur, me, std::memory_order_acquire, std::memory_order_relaxed))
      return false;
    held.push_back(t);
    return true;
  }
  void releaseAll()
  {
    for (int32_t t : held)
      owner[t].store(0, std::memory_order_release);
    held.clear();
  }

  // Reused buffers (no allocation in the insertion loop once they have grown).
  struct BoundaryFace
  {
    int32_t v[4];    // the new tet: the cavity tet's vertices with the new point at position `face`
    int32_t outside; // neighbour code of the tet across the face (outside the cavity)
    int8_t face;
    int8_t local[4]; // local numbers of the face's vertices (matrix matching)
  };
  // Matching of the new tets around the cavity boundary edges: the boundary vertices get local numbers
  // (vlocal[v+1], reset after each insertion from the list localVert), and directed edge (x,y) is stored
  // at edgeMat[x*kMaxLocal+y]. Cavities with more boundary vertices use the edge hash instead.
  // vlocal is -1 between insertions (one byte per vertex: every inserter of the parallel construction
  // has one); edgeMat has a fixed stride of kMaxLocal.
  static constexpr int kLocalShift = 7;
  static constexpr int32_t kMaxLocal = 1 << kLocalShift;
  std::vector<int8_t> vlocal;
  std::vector<int32_t> localVert = std::vector<int32_t>(kMaxLocal),
                       edgeMat = std::vector<int32_t>(kMaxLocal * kMaxLocal);
  std::vector<int32_t> cavity, outside;
  std::vector<BoundaryFace> boundary;
  struct HashSlot
  {
    uint64_t key;
    int32_t code;
    uint32_t stamp;
  };
  std::vector<HashSlot> table;
  uint32_t stamp = 0;

  // Bucket grid (PointLocation::BucketGrid).
  bool grid = false;
  double glo[3] = { 0, 0, 0 }, gscale[3] = { 0, 0, 0 };
  int gres = 1;
  std::vector<int32_t> bucketHead; // last vertex registered in the bucket
  std::vector<int32_t> vertexNext; // next vertex in the same bucket
  std::vector<int32_t> vertexTet;  // a tet (probably still) incident to the vertex

  Impl(TetMesh& m, uint64_t seed)
    : mesh(m)
    , rng(seed | 1)
  {
  }

  uint32_t random()
  {
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return static_cast<uint32_t>(rng);
  }

  int32_t liveTet(int32_t hint) const
  {
    if (hint >= 0 && hint < mesh.tetCapacity() && !mesh.isFree(hint))
      return hint;
    if (last >= 0 && last < mesh.tetCapacity() && !mesh.isFree(last))
      return last;
    for (int32_t t = 0; t < mesh.tetCapacity(); ++t)
      if (!mesh.isFree(t))
        return t;
    return -1;
  }

  int32_t walk(const double* p, int32_t t)
  {
    const int32_t* V = mesh.tetVertices.data();
    const int32_t* N = mesh.tetNeighbors.data();
    const double* P = mesh.points.data();
    int32_t prev = -1;
    uint32_t bits = 0;
    int bitsLeft = 0;
    for (;;)
    {
      ++walkSteps;
      if (owner && (!acquire(t) || (mesh.tetFlags[t] & TetMesh::kFree)))
        return -1; // owned by the other thread, or a slot it freed
      const int32_t* w = V + 4 * static_cast<size_t>(t);
      if ((w[0] | w[1] | w[2] | w[3]) < 0)
      {
        // Ghost: p strictly beyond its hull face -> located (the ghost is in conflict); else go inside.
        const int k = w[0] < 0 ? 0 : w[1] < 0 ? 1 : w[2] < 0 ? 2 : 3;
        if (prev < 0)
        {
          const int o = orient(P + 3 * static_cast<size_t>(w[kFV[k][0]]), P + 3 * static_cast<size_t>(w[kFV[k][1]]),
                               P + 3 * static_cast<size_t>(w[kFV[k][2]]), p);
          if (o > 0)
            return t;
        }
        else
          return t; // entered from a finite tet through a face that p strictly sees: in conflict
        prev = t;
        t = N[4 * static_cast<size_t>(t) + k] >> 2;
        continue;
      }
      if (bitsLeft == 0)
      {
        bits = random();
        bitsLeft = 16;
      }
      const int r = static_cast<int>(bits & 3);
      bits >>= 2;
      --bitsLeft;
      int32_t next = -1;
      for (int j = 0; j < 4; ++j)
      {
        const int i = (r + j) & 3;
        const int32_t u = N[4 * static_cast<size_t>(t) + i] >> 2;
        if (u == prev)
          continue;
        const int o = orient(P + 3 * static_cast<size_t>(w[kFV[i][0]]), P + 3 * static_cast<size_t>(w[kFV[i][1]]),
                             P + 3 * static_cast<size_t>(w[kFV[i][2]]), p);
        if (o < 0)
        {
          next = u;
          break;
        }
      }
      if (next < 0)
        return t;
      prev = t;
      t = next;
    }
  }

  __attribute__((always_inline)) bool inConflict(int32_t u, const double* p, int32_t v)
  {
    const int32_t* w = mesh.tetVertices.data() + 4 * static_cast<size_t>(u);
    const double* P = mesh.points.data();
    if ((w[0] | w[1] | w[2] | w[3]) < 0)
    {
      const int k = w[0] < 0 ? 0 : w[1] < 0 ? 1 : w[2] < 0 ? 2 : 3;
      const int o = orient(P + 3 * static_cast<size_t>(w[kFV[k][0]]), P + 3 * static_cast<size_t>(w[kFV[k][1]]),
                           P + 3 * static_cast<size_t>(w[kFV[k][2]]), p);
      if (o != 0)
        return o > 0;
      // p on the plane of the hull face: same answer as the finite tet across it.
      u = (mesh.tetNeighbors[4 * static_cast<size_t>(u) + k] & kCodeMask) >> 2;
      if (!acquire(u))
      {
        lockFailed = true;
        return false;
      }
      w = mesh.tetVertices.data() + 4 * static_cast<size_t>(u);
    }
    const double* pa = P + 3 * static_cast<size_t>(w[0]);
    const double* pb = P + 3 * static_cast<size_t>(w[1]);
    const double* pc = P + 3 * static_cast<size_t>(w[2]);
    const double* pd = P + 3 * static_cast<size_t>(w[3]);
    const int s = insphere(pa, pb, pc, pd, p);
    if (s != 0)
      return s > 0;
    // Exactly cospherical: Simulation of Simplicity with the vertices' ids.
    if (sosId)
      return predicates::detail::insphereSoSTie(pa, pb, pc, pd, p, sosId[w[0]], sosId[w[1]], sosId[w[2]], sosId[w[3]],
                                                sosId[v]) > 0;
    return predicates::detail::insphereSoSTie(pa, pb, pc, pd, p, w[0], w[1], w[2], w[3], v) > 0;
  }

  int32_t gridStart(const double* p) const
  {
    int c[3];
    for (int a = 0; a < 3; ++a)
    {
      const double f = (p[a] - glo[a]) * gscale[a];
      c[a] = f <= 0 ? 0 : f >= gres - 1 ? gres - 1 : static_cast<int>(f);
    }
    const double* P = mesh.points.data();
    // Search rings of buckets around p's bucket; nearest vertex of the first non-empty ring. Give up
    // after a few rings (the walk from the last tet takes over): early on most buckets are empty.
    for (int ring = 0; ring <= std::min(2, gres); ++ring)
    {
      int32_t best = -1;
      double bestD = 0;
      for (int i = std::max(0, c[0] - ring); i <= std::min(gres - 1, c[0] + ring); ++i)
        for (int j = std::max(0, c[1] - ring); j <= std::min(gres - 1, c[1] + ring); ++j)
          for (int k = std::max(0, c[2] - ring); k <= std::min(gres - 1, c[2] + ring); ++k)
          {
            if (std::max({ std::abs(i - c[0]), std::abs(j - c[1]), std::abs(k - c[2]) }) != ring)
              continue;
            for (int32_t v = bucketHead[(static_cast<size_t>(i) * gres + j) * gres + k]; v >= 0; v = vertexNext[v])
            {
              const double* q = P + 3 * static_cast<size_t>(v);
              const double d =
                (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]);
              if (best < 0 || d < bestD)
              {
                best = v;
                bestD = d;
              }
            }
          }
      if (best >= 0)
      {
        const int32_t t = vertexTet[best];
        if (t >= 0 && t < mesh.tetCapacity() && !mesh.isFree(t))
          return t;
        return -1;
      }
    }
    return -1;
  }

  void gridRegister(int32_t v, int32_t t)
  {
    if (!grid)
      return;
    if (static_cast<size_t>(v) >= vertexNext.size())
    {
      vertexNext.resize(static_cast<size_t>(v) + 1 + static_cast<size_t>(v) / 4, -1);
      vertexTet.resize(vertexNext.size(), -1);
    }
    const double* p = mesh.point(v);
    int c[3];
    for (int a = 0; a < 3; ++a)
    {
      const double f = (p[a] - glo[a]) * gscale[a];
      c[a] = f <= 0 ? 0 : f >= gres - 1 ? gres - 1 : static_cast<int>(f);
    }
    const size_t b = (static_cast<size_t>(c[0]) * gres + c[1]) * gres + c[2];
    vertexNext[v] = bucketHead[b];
    bucketHead[b] = v;
    vertexTet[v] = t;
  }

  // Hash of the cavity boundary edges: returns the code stored by the twin face, or stores `code`.
  int32_t matchEdge(uint64_t key, int32_t code, uint32_t mask)
  {
    uint32_t h = static_cast<uint32_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
    for (;;)
    {
      HashSlot& s = table[h];
      if (s.stamp != stamp)
      {
        s.key = key;
        s.code = code;
        s.stamp = stamp;
        return -1;
      }
      if (s.key == key)
        return s.code;
      h = (h + 1) & mask;
    }
  }

  // What the cavity search hands to the rest of the insertion (growCavity counts in locals and stores
  // them here on the way out: counting through the reference cost 0.3% more instructions in insert).
  struct CavityState
  {
    int32_t nloc = 0;       // boundary vertices numbered so far (localVert)
    bool overflow = false;  // more than kMaxLocal of them: the edge hash matches the new tets
    int32_t ghostDelta = 0; // ghost tets created minus ghost tets removed
  };

  // Inserts vertex v: locate, cavity, slots for the new tets, the new tets written and linked, leftover
  // slots freed. next (optional): the point inserted next, near which the next walk starts.
  Result insert(int32_t v, int32_t hint, const double* next)
  {
    Result res;
    const double* p = mesh.point(v);
    const int32_t t = locate(p, hint);
    if (t < 0)
    {
      releaseAll();
      res.aborted = true;
      return res;
    }
    const int32_t twin = duplicateIn(t, p);
    if (twin >= 0)
    {
      res.tet = t;
      res.duplicateOf = twin;
      last = t;
      if (owner)
        releaseAll();
      return res;
    }
    CavityState cs;
    if (!growCavity(v, p, t, cs))
      return abortInsertion(res, cs.nloc);
    const size_t nb = boundary.size();
    const size_t nc = cavity.size();
    if (!claimSlots(nb))
      return abortInsertion(res, cs.nloc);
    clearLocalNumbers(cs.nloc);
    const bool useMatrix = !cs.overflow;
    const uint32_t mask = useMatrix ? 0 : prepareEdgeHash(nb);
    cs.ghostDelta += writeNewTets(nb, useMatrix, mask);
    if (useMatrix)
      linkThroughMatrix(nb);
    releaseLeftoverSlots(nb, nc);
    if (nextSlot)
      pendingGhostDelta += cs.ghostDelta;
    else
      mesh.adjustGhostCount(cs.ghostDelta);
    last = next ? nearestNewTet(next, nb) : cavity[nb - 1];
    res.tet = last;
    gridRegister(v, last);
    if (owner)
      releaseAll();
    return res;
  }

  // The tet where p is (or a ghost whose hull face p strictly sees), walking from the grid's nearest
  // vertex, else from the hint or the last tet; -1 when another thread holds the way.
  __attribute__((always_inline)) int32_t locate(const double* p, int32_t hint)
  {
    int32_t start = -1;
    if (grid)
      start = gridStart(p);
    if (start < 0)
      start = owner ? (hint >= 0 ? hint : last) : liveTet(hint);
    return walk(p, start);
  }

  // The vertex of finite tet t at exactly p's position, or -1.
  __attribute__((always_inline)) int32_t duplicateIn(int32_t t, const double* p) const
  {
    const int32_t* w = mesh.tetVertices.data() + 4 * static_cast<size_t>(t);
    if ((w[0] | w[1] | w[2] | w[3]) >= 0)
      for (int k = 0; k < 4; ++k)
        if (samePoint(mesh.point(w[k]), p))
          return w[k];
    return -1;
  }

  // Sets the mark bit of word `word` of tet u's neighbour row.
  static void markWord(int32_t* N, int32_t u, int word)
  {
    N[4 * static_cast<size_t>(u) + word] =
      static_cast<int32_t>(static_cast<uint32_t>(N[4 * static_cast<size_t>(u) + word]) | kMarkBit);
  }

  // Requests the rows of tet c's neighbours: they are usually cache misses.
  static void prefetchAround(const int32_t* V, const int32_t* N, int32_t c)
  {
    for (int f = 0; f < 4; ++f)
    {
      const size_t u = static_cast<size_t>((N[4 * static_cast<size_t>(c) + f] & kCodeMask) >> 2);
      __builtin_prefetch(V + 4 * u);
      __builtin_prefetch(N + 4 * u);
    }
  }

  // Cavity: the tets in conflict with p (vertex v), grown breadth-first over `cavity` from t (which
  // contains p, hence is in conflict); the faces to the tets outside go to `boundary`. false: another
  // thread holds a tet on the way (the caller aborts).
  __attribute__((always_inline)) bool growCavity(int32_t v, const double* p, int32_t t, CavityState& cs)
  {
    const int32_t* V = mesh.tetVertices.data();
    int32_t* N = mesh.tetNeighbors.data();
    cavity.clear();
    outside.clear();
    boundary.clear();
    markWord(N, t, 0);
    cavity.push_back(t);
    int32_t nloc = 0, ghostDelta = 0; // locals, stored to cs on the way out
    bool overflow = false;
    const size_t needV = static_cast<size_t>(mesh.numVertices()) + 1;
    if (vlocal.size() < needV)
      vlocal.resize(needV + needV / 4, -1);
    int8_t* VL = vlocal.data();
    int32_t* LV = localVert.data();
    // While one tet is processed, the neighbours of the next queued tet are requested.
    prefetchAround(V, N, t);
    for (size_t qi = 0; qi < cavity.size(); ++qi)
    {
      const int32_t c = cavity[qi];
      if (qi + 1 < cavity.size())
        prefetchAround(V, N, cavity[qi + 1]);
      const int32_t* wc = V + 4 * static_cast<size_t>(c);
      if ((wc[0] | wc[1] | wc[2] | wc[3]) < 0)
        --ghostDelta;
      for (int f = 0; f < 4; ++f)
      {
        const int32_t code = N[4 * static_cast<size_t>(c) + f] & kCodeMask;
        const int32_t u = code >> 2;
        if (owner && !acquire(u))
        {
          cs = CavityState{ nloc, overflow, ghostDelta };
          return false;
        }
        const int32_t* nu = N + 4 * static_cast<size_t>(u);
        if (nu[0] < 0)
          continue; // in the cavity
        if (nu[1] >= 0)
        {
          const bool conflict = inConflict(u, p, v);
          if (lockFailed)
          {
            cs = CavityState{ nloc, overflow, ghostDelta };
            return false;
          }
          if (conflict)
          {
            markWord(N, u, 0);
            cavity.push_back(u);
            continue;
          }
          markWord(N, u, 1);
          outside.push_back(u);
        }
        addBoundaryFace(wc, f, code, v, VL, LV, nloc, overflow);
      }
    }
    cavityTets += cavity.size();
    for (int32_t u : outside)
      N[4 * static_cast<size_t>(u) + 1] &= kCodeMask;
    cs = CavityState{ nloc, overflow, ghostDelta };
    return true;
  }

  // Records the new tet on face f of cavity tet wc (outside neighbour `code`), numbering the face's
  // vertices locally (VL: vertex -> local number, LV: local number -> vertex) for the matching.
  __attribute__((always_inline)) void addBoundaryFace(const int32_t* wc, int f, int32_t code, int32_t v, int8_t* VL,
                                                      int32_t* LV, int32_t& nloc, bool& overflow)
  {
    boundary.emplace_back();
    BoundaryFace& bf = boundary.back();
    bf.v[0] = wc[0];
    bf.v[1] = wc[1];
    bf.v[2] = wc[2];
    bf.v[3] = wc[3];
    bf.v[f] = v;
    bf.outside = code;
    bf.face = static_cast<int8_t>(f);
    for (int k = 0; k < 4; ++k)
    {
      if (k == f)
        continue;
      int8_t& li = VL[wc[k] + 1];
      if (li < 0)
      {
        if (nloc == kMaxLocal)
        {
          overflow = true;
          continue;
        }
        li = static_cast<int8_t>(nloc);
        LV[nloc++] = wc[k];
      }
      bf.local[k] = li;
    }
  }

  // Slots for the nb new tets, appended to `cavity` after its own: in pool mode this inserter's spare
  // slots, then fresh ones from the shared pool; else the mesh's free slots, then appended ones.
  // false: the pool is used up (the slots taken go back to `spare`; the caller aborts).
  __attribute__((always_inline)) bool claimSlots(size_t nb)
  {
    const size_t nc = cavity.size();
    if (!nextSlot)
    {
      for (size_t i = nc; i < nb && mesh.freeListHead() >= 0; ++i)
        cavity.push_back(mesh.newTet(0, 0, 0, 0));
      if (cavity.size() < nb)
      {
        const int32_t first = mesh.appendTets(static_cast<int32_t>(nb - cavity.size()));
        for (int32_t s = first; cavity.size() < nb; ++s)
          cavity.push_back(s);
      }
      return true;
    }
    while (cavity.size() < nb && !spare.empty())
    {
      cavity.push_back(spare.back());
      spare.pop_back();
    }
    if (cavity.size() >= nb)
      return true;
    const int32_t k = static_cast<int32_t>(nb - cavity.size());
    const int32_t first = nextSlot->fetch_add(k);
    if (first + k > slotLimit)
    {
      poolFull = true;
      poolEnd = std::min(poolEnd, first); // slots from here on were never handed out
      for (size_t i = nc; i < cavity.size(); ++i)
        spare.push_back(cavity[i]);
      cavity.resize(nc);
      return false;
    }
    for (int32_t s = first; s < first + k; ++s)
    {
      if (owner)
      {
        owner[s].store(me, std::memory_order_relaxed);
        held.push_back(s);
      }
      cavity.push_back(s);
    }
    return true;
  }

  // Back to -1 between insertions: the local numbers of the nloc boundary vertices.
  void clearLocalNumbers(int32_t nloc)
  {
    int8_t* VL = vlocal.data(); // locals: the byte stores could alias the vectors' pointers
    const int32_t* LV = localVert.data();
    for (int32_t k = 0; k < nloc; ++k)
      VL[LV[k] + 1] = -1;
  }

  // The edge hash sized for nb boundary faces, emptied by a new stamp; returns its index mask.
  uint32_t prepareEdgeHash(size_t nb)
  {
    uint32_t size = 64;
    while (size < 4 * nb)
      size <<= 1;
    if (table.size() < size)
      table.assign(size, HashSlot{ 0, 0, 0 }), stamp = 0;
    if (++stamp == 0)
    {
      for (HashSlot& hs : table)
        hs.stamp = 0;
      stamp = 1;
    }
    return size - 1;
  }

  // The nb new tets written into their slots (cavity[i] for boundary[i]) and linked to the tets outside;
  // their faces around the new point are stored in the edge matrix (linked by linkThroughMatrix) or
  // matched at once in the edge hash (mask). Returns the number of new ghost tets.
  int32_t writeNewTets(size_t nb, bool useMatrix, uint32_t mask)
  {
    uint8_t* F = mesh.tetFlags.data();
    int32_t* V = mesh.tetVertices.data();
    int32_t* N = mesh.tetNeighbors.data();
    int32_t* M = edgeMat.data();
    int32_t ghosts = 0;
    for (size_t i = 0; i < nb; ++i)
    {
      const BoundaryFace& bf = boundary[i];
      const int32_t s = cavity[i];
      int32_t* ws = V + 4 * static_cast<size_t>(s);
      ws[0] = bf.v[0];
      ws[1] = bf.v[1];
      ws[2] = bf.v[2];
      ws[3] = bf.v[3];
      if ((bf.v[0] | bf.v[1] | bf.v[2] | bf.v[3]) < 0)
        ++ghosts;
      F[s] = 0;
      int32_t* ns = N + 4 * static_cast<size_t>(s);
      ns[bf.face] = bf.outside;
      N[bf.outside] = (s << 2) | bf.face;
      for (int g = 0; g < 4; ++g)
      {
        if (g == bf.face)
          continue;
        if (useMatrix)
        {
          const EdgePair e = kDirected[bf.face][g];
          M[(bf.local[e.x] << kLocalShift) | bf.local[e.y]] = (s << 2) | g;
          continue;
        }
        const EdgePair e = kOther[bf.face][g];
        const int32_t twin = matchEdge(edgeKey(bf.v[e.x], bf.v[e.y]), (s << 2) | g, mask);
        if (twin >= 0)
        {
          ns[g] = twin;
          N[twin] = (s << 2) | g;
        }
      }
    }
    return ghosts;
  }

  // Each new tet's faces around the new point linked to the twin face stored in the edge matrix under
  // the reversed edge.
  void linkThroughMatrix(size_t nb)
  {
    int32_t* N = mesh.tetNeighbors.data();
    const int32_t* M = edgeMat.data();
    for (size_t i = 0; i < nb; ++i)
    {
      const BoundaryFace& bf = boundary[i];
      int32_t* ns = N + 4 * static_cast<size_t>(cavity[i]);
      for (int g = 0; g < 4; ++g)
      {
        if (g == bf.face)
          continue;
        const EdgePair e = kDirected[bf.face][g];
        ns[g] = M[(bf.local[e.y] << kLocalShift) | bf.local[e.x]];
      }
    }
  }

  // Cavity slots [nb, nc) left over (the cavity had more tets than boundary faces) are freed: to this
  // inserter's spare list in pool mode, else to the mesh.
  void releaseLeftoverSlots(size_t nb, size_t nc)
  {
    uint8_t* F = mesh.tetFlags.data();
    int32_t* V = mesh.tetVertices.data();
    for (size_t i = nb; i < nc; ++i)
    {
      const int32_t s = cavity[i];
      int32_t* ws = V + 4 * static_cast<size_t>(s);
      ws[0] = ws[1] = ws[2] = ws[3] = 0; // so that freeTet does not count it as a ghost
      if (nextSlot)
      {
        F[s] = TetMesh::kFree; // recycled by this inserter; freed in the mesh when the pool is closed
        spare.push_back(s);
      }
      else
        mesh.freeTet(s);
    }
  }

  // The new finite tet whose outer face is nearest to the next point, where the next walk starts
  // (heuristic, plain doubles: only the walk length depends on it); the last new tet if none is finite.
  int32_t nearestNewTet(const double* next, size_t nb) const
  {
    const double* P = mesh.points.data();
    int32_t at = cavity[nb - 1];
    double best = -1;
    for (size_t i = 0; i < nb; ++i)
    {
      const BoundaryFace& bf = boundary[i];
      if ((bf.v[0] | bf.v[1] | bf.v[2] | bf.v[3]) < 0)
        continue;
      const double* a = P + 3 * static_cast<size_t>(bf.v[kFV[bf.face][0]]);
      const double* b = P + 3 * static_cast<size_t>(bf.v[kFV[bf.face][1]]);
      const double* c = P + 3 * static_cast<size_t>(bf.v[kFV[bf.face][2]]);
      const double dx = a[0] + b[0] + c[0] - 3 * next[0];
      const double dy = a[1] + b[1] + c[1] - 3 * next[1];
      const double dz = a[2] + b[2] + c[2] - 3 * next[2];
      const double d = dx * dx + dy * dy + dz * dz;
      if (best < 0 || d < best)
      {
        best = d;
        at = cavity[i];
      }
    }
    return at;
  }

  // Undo the marks of a cavity search and give the tets back (parallel mode only).
  Result abortInsertion(Result res, int32_t nloc)
  {
    int32_t* N = mesh.tetNeighbors.data();
    for (int32_t c : cavity)
      N[4 * static_cast<size_t>(c)] &= kCodeMask;
    for (int32_t u : outside)
      N[4 * static_cast<size_t>(u) + 1] &= kCodeMask;
    clearLocalNumbers(nloc);
    lockFailed = false;
    releaseAll();
    res.aborted = true;
    return res;
  }
};

// `workers` threads insert the chunks (along the Hilbert curve) of each BRIO round from `round0` on
// (DelaunayParallel.cxx). firstTet: the four insertion positions of the first tet (already inserted).
Status insertParallel(TetMesh& mesh, DelaunayInserter& main, const std::vector<int32_t>& order,
                      const std::vector<size_t>& roundStarts, size_t round0, const int32_t* firstTet,
                      std::vector<int32_t>& inputToVertex, std::vector<int32_t>& rest, DelaunayReport& rep,
                      Progress* progress, uint64_t seed, int workers);

// Canonical tet numbering (DelaunayCanonical.cxx): see the file. Vertices are numbered in insertion
// order on entry; toInput (optional) maps them to the output numbering as the tets are written.
// threads > 1: the passes over all tets run on that many threads (same result). The mesh's points are
// released (the caller sets the output points).
void canonicalizeTets(TetMesh& mesh, const int32_t* toInput, int threads);

} // namespace volgrid
