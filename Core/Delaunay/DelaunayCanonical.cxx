// Canonical tet numbering of a Delaunay mesh.
//
// The tets of the (SoS-)Delaunay triangulation are unique, but the slots they end up in depend on the
// history of the construction, and with several threads on their interleaving. The product's
// rule is that the same input and options give the same mesh arrays whatever the thread count, so
// buildDelaunay renumbers the tets canonically, from their vertices and the insertion order only (both
// fixed by the input and the options: the spatial sort and its seed):
//   * each tet's vertex list is rotated by an even permutation (orientation kept) so that it starts with
//     its earliest inserted vertex, followed by the earliest of the other three (the vertex at infinity
//     counts as the last); faces move with their opposite vertices. Without spatial sorting, insertion
//     order is input order: the smallest vertex id comes first. (Insertion ranks rather than output ids:
//     an output id costs a random lookup per vertex, which made this pass several times slower.)
//   * tets are ordered by their last inserted vertex (counting sort; insertion follows the Hilbert
//     curve in BRIO rounds, and most tets have a vertex of the last round, so the tet order is
//     spatially coherent), then by the rotated list (insertion sort within a vertex's few tets);
//   * free slots are dropped; neighbour codes are rewritten for the new numbers and face positions.
// Memory: besides the new-to-old order (4 bytes per tet) and the rotations (1 byte), at most one new
// 16-byte row array exists at a time, so the peak stays within the kernel's budget (issue 2: 60 bytes
// per tet). (An in-place cycle-following permutation would need no row array but costs a dependent
// cache miss per row: several times slower.) Cost: a few linear passes over the tet arrays.
#include "DelaunayInserterImpl.h"
#include "ParallelFor.h"

namespace volgrid
{
namespace
{
// kRest[i0]: the other three positions, in the cyclic order that makes (i0, kRest[i0]) an even
// permutation of (0,1,2,3) (the double transposition (0 i0)(other two)); rotating them keeps it even.
constexpr int8_t kRest[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 3, 0, 1 }, { 2, 1, 0 } };

// Unsigned view of a vertex: kGhostVertex (-1) becomes the largest value.
inline uint32_t rank(int32_t v)
{
  return static_cast<uint32_t>(v);
}

// New order of tet w's positions (ord[j] = old position of new position j); w in insertion ranks.
inline void canonicalOrder(const int32_t* w, int8_t ord[4])
{
  int i0 = 0;
  for (int i = 1; i < 4; ++i)
    if (rank(w[i]) < rank(w[i0]))
      i0 = i;
  const int8_t* r = kRest[i0];
  int k = 0;
  if (rank(w[r[1]]) < rank(w[r[k]]))
    k = 1;
  if (rank(w[r[2]]) < rank(w[r[k]]))
    k = 2;
  ord[0] = static_cast<int8_t>(i0);
  ord[1] = r[k];
  ord[2] = r[(k + 1) % 3];
  ord[3] = r[(k + 2) % 3];
}

// Rotated list as two unsigned 64-bit keys (lexicographic order = order of (hi, lo)).
inline bool rowLess(const int32_t* x, const int32_t* y)
{
  const uint64_t xh = (uint64_t(rank(x[0])) << 32) | rank(x[1]), yh = (uint64_t(rank(y[0])) << 32) | rank(y[1]);
  if (xh != yh)
    return xh < yh;
  return ((uint64_t(rank(x[2])) << 32) | rank(x[3])) < ((uint64_t(rank(y[2])) << 32) | rank(y[3]));
}

// Group key: the last inserted vertex (kGhostVertex = -1 never is). Most tets get a vertex of the
// last BRIO round, so the groups follow that round's Hilbert order: neighbouring tets get nearby
// numbers, which keeps the passes below cache-friendly.
inline int32_t lastInserted(const int32_t* w)
{
  return std::max(std::max(w[0], w[1]), std::max(w[2], w[3]));
}

// Passes over [0, n) on up to `threads` ranges of at least 2^16 items (ParallelFor.h).
template<typename Work>
void inRanges(int threads, int32_t n, const Work& work)
{
  parallelFor(threads, n, 1 << 16, [&](int, int64_t from, int64_t to) { work(int32_t(from), int32_t(to)); });
}

// Pass 1, in slot order: every live tet's vertex row rotated in place; from here on the flag byte of
// a slot holds the rotation of its tet (newPos: new position of old position f in bits 2f..2f+1,
// never 0 for a live tet) and 0 for a free slot (no separate array).
// Each of the `countThreads` ranges also counts its tets per last inserted vertex (returned, one count
// array per range, for the counting sort of pass 2).
std::vector<std::vector<int32_t>> rotateRows(int32_t* V, uint8_t* F, int32_t cap, int32_t nv, int countThreads)
{
  uint8_t* newPos = F;
  std::vector<std::vector<int32_t>> count(static_cast<size_t>(parallelRanges(countThreads, cap, 1 << 16)));
  parallelFor(countThreads, cap, 1 << 16,
              [&](int range, int64_t from, int64_t to)
              {
                std::vector<int32_t>& c = count[range];
                c.assign(static_cast<size_t>(nv), 0);
                for (int32_t t = from; t < to; ++t)
                {
                  if (F[t] & TetMesh::kFree)
                  {
                    F[t] = 0;
                    continue;
                  }
                  int32_t* w = V + 4 * static_cast<size_t>(t);
                  ++c[lastInserted(w)];
                  int8_t ord[4];
                  canonicalOrder(w, ord);
                  const int32_t row[4] = { w[ord[0]], w[ord[1]], w[ord[2]], w[ord[3]] };
                  std::memcpy(w, row, sizeof row);
                  newPos[t] = static_cast<uint8_t>((1 << (2 * ord[1])) | (2 << (2 * ord[2])) | (3 << (2 * ord[3])));
                }
              });
  return count;
}

// Pass 2a: newToOld by groups of the last inserted vertex (counting sort; consumes `count`); start[v]
// is where vertex v's group begins (start[nv] = the number of live tets).
// The ranges' counts become their fill positions: range 0 fills the front of each group, range 1 the
// next part, ... (the order inside a group does not matter, it is sorted next).
std::vector<int32_t> groupByLastInserted(const int32_t* V, const uint8_t* F, int32_t cap, int32_t nv, int countThreads,
                                         std::vector<std::vector<int32_t>>& count, std::vector<int32_t>& start)
{
  start.assign(static_cast<size_t>(nv) + 1, 0);
  for (int32_t v = 0; v < nv; ++v)
  {
    int32_t at = start[v];
    for (std::vector<int32_t>& c : count)
    {
      const int32_t k = c[v];
      c[v] = at;
      at += k;
    }
    start[v + 1] = at;
  }
  std::vector<int32_t> newToOld(static_cast<size_t>(start[nv]));
  parallelFor(countThreads, cap, 1 << 16,
              [&](int range, int64_t from, int64_t to)
              {
                std::vector<int32_t>& fill = count[range];
                for (int32_t t = from; t < to; ++t)
                  if (F[t] != 0)
                    newToOld[fill[lastInserted(V + 4 * static_cast<size_t>(t))]++] = t;
              });
  std::vector<std::vector<int32_t>>().swap(count);
  return newToOld;
}

// Pass 2b: each group of newToOld sorted by the rotated rows (insertion sort of its few tets).
// Groups are independent (disjoint ranges of newToOld): ranges of the vertex range may run at once. A
// group's tets sit in scattered slots: their rows are prefetched a few tets ahead.
void sortGroups(const int32_t* V, const std::vector<int32_t>& start, int32_t nv, std::vector<int32_t>& newToOld,
                int threads)
{
  inRanges(threads, nv,
           [&](int32_t vFrom, int32_t vTo)
           {
             constexpr int32_t kAhead = 16;
             const int32_t end = start[vTo];
             for (int32_t i = start[vFrom]; i < std::min(end, start[vFrom] + kAhead); ++i)
               __builtin_prefetch(V + 4 * static_cast<size_t>(newToOld[i]));
             for (int32_t v = vFrom; v < vTo; ++v)
             {
               const int32_t a = start[v], b = start[v + 1];
               for (int32_t i = a; i < b; ++i)
                 if (i + kAhead < end)
                   __builtin_prefetch(V + 4 * static_cast<size_t>(newToOld[i + kAhead]));
               for (int32_t i = a + 1; i < b; ++i)
               {
                 const int32_t t = newToOld[i];
                 const int32_t* row = V + 4 * static_cast<size_t>(t);
                 int32_t j = i - 1;
                 for (; j >= a && rowLess(row, V + 4 * static_cast<size_t>(newToOld[j])); --j)
                   newToOld[j + 1] = newToOld[j];
                 newToOld[j + 1] = t;
               }
             }
           });
}

// Pass 3: neighbour codes rewritten in place for the new numbers and face positions (a row's rewrite
// reads only newId/newPos of its neighbours).
void renumberNeighbours(int32_t* N, const uint8_t* newPos, int32_t cap, const std::vector<int32_t>& newToOld,
                        int threads)
{
  const int32_t live = static_cast<int32_t>(newToOld.size());
  std::vector<int32_t> newId(static_cast<size_t>(cap), -1); // new number of every live slot
  inRanges(threads, live,
           [&](int32_t from, int32_t to)
           {
             for (int32_t i = from; i < to; ++i)
               newId[newToOld[i]] = i;
           });
  inRanges(threads, cap,
           [&](int32_t from, int32_t to)
           {
             for (int32_t t = from; t < to; ++t)
             {
               if (t + 8 < to)
                 for (int f = 0; f < 4; ++f)
                 {
                   const int32_t c = N[4 * static_cast<size_t>(t + 8) + f];
                   if (c >= 0)
                     __builtin_prefetch(newId.data() + (c >> 2));
                 }
               if (newPos[t] == 0)
                 continue; // free slot
               int32_t* n = N + 4 * static_cast<size_t>(t);
               for (int f = 0; f < 4; ++f)
               {
                 const int32_t c = n[f];
                 if (c >= 0)
                   n[f] = (newId[c >> 2] << 2) | ((newPos[c >> 2] >> (2 * (c & 3))) & 3);
               }
             }
           });
}

// Pass 4, for one array: its rows gathered in the new order (neighbour rows rotated like the vertex rows
// were, vertex rows mapped to output ids). The old array is freed before the next is gathered: the
// transient memory stays at one 16-byte row per tet. Writes are sequential; the reads follow the
// construction's slot order, which is spatially coherent too.
void gatherRows(std::vector<int32_t>& rows, bool vertices, const std::vector<int32_t>& newToOld, const uint8_t* newPos,
                const int32_t* toInput, int threads)
{
  auto toOutput = [toInput](int32_t v) { return (toInput && v >= 0) ? toInput[v] : v; };
  const int32_t live = static_cast<int32_t>(newToOld.size());
  std::vector<int32_t> out(4 * static_cast<size_t>(live));
  const int32_t* in = rows.data();
  inRanges(threads, live,
           [&](int32_t from, int32_t to)
           {
             for (int32_t i = from; i < to; ++i)
             {
               if (i + 16 < to)
                 __builtin_prefetch(in + 4 * static_cast<size_t>(newToOld[i + 16]));
               const int32_t t = newToOld[i];
               const int32_t* r = in + 4 * static_cast<size_t>(t);
               int32_t* o = out.data() + 4 * static_cast<size_t>(i);
               if (vertices)
                 for (int f = 0; f < 4; ++f)
                   o[f] = toOutput(r[f]);
               else
                 for (int f = 0; f < 4; ++f)
                   o[(newPos[t] >> (2 * f)) & 3] = r[f];
             }
           });
  rows.swap(out);
}
} // namespace

void canonicalizeTets(TetMesh& mesh, const int32_t* toInput, int threads)
{
  const int32_t cap = mesh.tetCapacity();
  const int32_t nv = mesh.numVertices();
  const int32_t ghosts = mesh.numGhostTets();
  // The points are not needed here and the caller replaces them (buildDelaunay's output points are the
  // input array): release them first, which lowers the peak.
  std::vector<double>().swap(mesh.points);
  int32_t* V = mesh.tetVertices.data();
  int32_t* N = mesh.tetNeighbors.data();
  uint8_t* F = mesh.tetFlags.data(); // after pass 1: each live tet's rotation (newPos), 0 for a free slot
  // The counting passes keep a count per vertex per range (4 bytes per vertex each): at most two ranges,
  // as measured, more raised the peak (1M random points, 8 ranges: +23 MB) for little time.
  constexpr int kCountRanges = 2;
  const int countThreads = std::min(resolveThreads(threads), kCountRanges);

  std::vector<std::vector<int32_t>> count = rotateRows(V, F, cap, nv, countThreads);
  std::vector<int32_t> start;
  std::vector<int32_t> newToOld = groupByLastInserted(V, F, cap, nv, countThreads, count, start);
  sortGroups(V, start, nv, newToOld, threads);
  std::vector<int32_t>().swap(start);
  renumberNeighbours(N, F, cap, newToOld, threads);
  gatherRows(mesh.tetNeighbors, false, newToOld, F, toInput, threads);
  gatherRows(mesh.tetVertices, true, newToOld, F, toInput, threads);

  const size_t live = newToOld.size();
  std::vector<int32_t> vertices, neighbors;
  vertices.swap(mesh.tetVertices);
  neighbors.swap(mesh.tetNeighbors);
  mesh.clear();
  mesh.tetVertices.swap(vertices);
  mesh.tetNeighbors.swap(neighbors);
  mesh.tetFlags.assign(live, 0);
  mesh.adjustGhostCount(ghosts);
}

} // namespace volgrid
