// Canonical tet numbering of a Delaunay mesh.
//
// The tets of the (SoS-)Delaunay triangulation are unique, but the slots they end up in depend on the
// history of the construction, and with two threads on the interleaving of the threads. The product's
// rule is that the same input and options give the same mesh arrays whatever the thread count, so
// buildDelaunay renumbers the tets canonically, from their vertices only:
//   * each tet's vertex list is rotated by an even permutation (orientation kept) so that it starts with
//     its smallest output vertex id, followed by the smallest of the other three (the vertex at infinity
//     counts as the largest); faces move with their opposite vertices;
//   * tets are ordered by their last inserted vertex (counting sort; insertion follows the Hilbert
//     curve in BRIO rounds, and most tets have a vertex of the last round, so the tet order is
//     spatially coherent), then by the rotated list (insertion sort within a vertex's few tets);
//   * free slots are dropped; neighbour codes are rewritten for the new numbers and face positions.
// Memory: besides the new-to-old order (4 bytes per tet) and the rotations (1 byte), at most one new
// 16-byte row array exists at a time, so the peak stays within the kernel's budget (issue 2: 60 bytes
// per tet). (An in-place cycle-following permutation would need no row array but costs a dependent
// cache miss per row: several times slower.) Cost: a few linear passes over the tet arrays.
#include "DelaunayInserterImpl.h"

#include <thread>

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

// New order of tet w's positions (ord[j] = old position of new position j); w in output ids.
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
  uint8_t* F = mesh.tetFlags.data();
  auto toOutput = [toInput](int32_t v) { return (toInput && v >= 0) ? toInput[v] : v; };
  // Group key: the last inserted vertex (kGhostVertex = -1 never is). Most tets get a vertex of the
  // last BRIO round, so the groups follow that round's Hilbert order: neighbouring tets get nearby
  // numbers, which keeps the passes below cache-friendly.
  auto lastInserted = [](const int32_t* w) { return std::max(std::max(w[0], w[1]), std::max(w[2], w[3])); };
  // Rotated list of tet t in output ids, and the rotation.
  auto rotated = [&](int32_t t, int32_t row[4], int8_t ord[4]) {
    const int32_t* w = V + 4 * static_cast<size_t>(t);
    int32_t out[4];
    for (int i = 0; i < 4; ++i)
      out[i] = toOutput(w[i]);
    canonicalOrder(out, ord);
    for (int j = 0; j < 4; ++j)
      row[j] = out[ord[j]];
  };

  // Pass 1: counts per last inserted vertex. From here on the flag byte of a slot holds the tet's
  // rotation (newPos below, never 0 for a live tet) and 0 for a free slot: no separate array.
  std::vector<int32_t> start(static_cast<size_t>(nv) + 1, 0);
  for (int32_t t = 0; t < cap; ++t)
  {
    const bool live = !(F[t] & TetMesh::kFree);
    F[t] = live ? 0xff : 0; // 0xff: live, rotation not yet known
    if (live)
      ++start[lastInserted(V + 4 * static_cast<size_t>(t)) + 1];
  }
  for (int32_t v = 0; v < nv; ++v)
    start[v + 1] += start[v];
  const int32_t live = start[nv];

  // Pass 2: newToOld by groups (counting sort), then each group sorted by the rotated lists; the
  // rotation of every live tet (newPos: new position of old position f in bits 2f..2f+1).
  uint8_t* newPos = F;
  std::vector<int32_t> newToOld(static_cast<size_t>(live));
  {
    std::vector<int32_t> fill(start.begin(), start.end() - 1);
    for (int32_t t = 0; t < cap; ++t)
      if (F[t] != 0)
        newToOld[fill[lastInserted(V + 4 * static_cast<size_t>(t))]++] = t;
  }
  {
    struct Keyed
    {
      int32_t row[4];
      int32_t tet;
    };
    std::vector<Keyed> group;
    for (int32_t v = 0; v < nv; ++v)
    {
      const int32_t a = start[v], b = start[v + 1];
      group.resize(static_cast<size_t>(b - a));
      for (int32_t i = a; i < b; ++i)
      {
        Keyed& k = group[static_cast<size_t>(i - a)];
        int8_t ord[4];
        k.tet = newToOld[i];
        rotated(k.tet, k.row, ord);
        newPos[k.tet] = static_cast<uint8_t>((1 << (2 * ord[1])) | (2 << (2 * ord[2])) | (3 << (2 * ord[3])));
      }
      if (b - a > 1)
        std::sort(group.begin(), group.end(), [](const Keyed& x, const Keyed& y) { return rowLess(x.row, y.row); });
      for (int32_t i = a; i < b; ++i)
        newToOld[i] = group[static_cast<size_t>(i - a)].tet;
    }
  }
  std::vector<int32_t>().swap(start);
  // New number of every live slot.
  std::vector<int32_t> newId(static_cast<size_t>(cap), -1);
  for (int32_t i = 0; i < live; ++i)
    newId[newToOld[i]] = i;

  auto inHalves = [threads](int32_t n, const auto& work) {
    if (threads > 1 && n >= (1 << 20))
    {
      std::thread helper(work, n / 2, n);
      work(0, n / 2);
      helper.join();
    }
    else
      work(0, n);
  };
  // Pass 3: neighbour codes rewritten in place for the new numbers and face positions (a row's
  // rewrite reads only newId/newPos of its neighbours).
  inHalves(cap, [&](int32_t from, int32_t to) {
    for (int32_t t = from; t < to; ++t)
    {
      if (F[t] == 0)
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
  std::vector<int32_t>().swap(newId);

  // Pass 4: the rows gathered in the new order and rotated, one array at a time (the old one is freed
  // before the next is allocated: the transient memory stays at one 16-byte row per tet). Writes are
  // sequential; the reads follow the construction's slot order, which is spatially coherent too.
  auto gather = [&](std::vector<int32_t>& rows, bool vertices) {
    std::vector<int32_t> out(4 * static_cast<size_t>(live));
    const int32_t* in = rows.data();
    inHalves(live, [&](int32_t from, int32_t to) {
      for (int32_t i = from; i < to; ++i)
      {
        const int32_t t = newToOld[i];
        const uint8_t np = newPos[t];
        const int32_t* r = in + 4 * static_cast<size_t>(t);
        int32_t* o = out.data() + 4 * static_cast<size_t>(i);
        for (int f = 0; f < 4; ++f)
          o[(np >> (2 * f)) & 3] = vertices ? toOutput(r[f]) : r[f];
      }
    });
    rows.swap(out);
  };
  gather(mesh.tetNeighbors, false);
  gather(mesh.tetVertices, true);

  std::vector<int32_t> vertices, neighbors;
  vertices.swap(mesh.tetVertices);
  neighbors.swap(mesh.tetNeighbors);
  mesh.clear();
  mesh.tetVertices.swap(vertices);
  mesh.tetNeighbors.swap(neighbors);
  mesh.tetFlags.assign(static_cast<size_t>(live), 0);
  mesh.adjustGhostCount(ghosts);
}

} // namespace volgrid
