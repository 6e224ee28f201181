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
// Cost: a few linear passes over the tet arrays (about 5% of the construction for random points).
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
  const int32_t* V = mesh.tetVertices.data();
  const int32_t* N = mesh.tetNeighbors.data();
  const uint8_t* F = mesh.tetFlags.data();
  auto toOutput = [toInput](int32_t v) { return (toInput && v >= 0) ? toInput[v] : v; };
  // Group key: the last inserted vertex (kGhostVertex = -1 never is). Most tets get a vertex of the
  // last BRIO round, so the groups follow that round's Hilbert order: neighbouring tets get nearby
  // numbers, which keeps the passes below cache-friendly.
  auto lastInserted = [](const int32_t* w) { return std::max(std::max(w[0], w[1]), std::max(w[2], w[3])); };

  // Pass 1: counts per last inserted vertex.
  std::vector<int32_t> start(static_cast<size_t>(nv) + 1, 0);
  for (int32_t t = 0; t < cap; ++t)
    if (!(F[t] & TetMesh::kFree))
      ++start[lastInserted(V + 4 * static_cast<size_t>(t)) + 1];
  for (int32_t v = 0; v < nv; ++v)
    start[v + 1] += start[v];
  const int32_t live = start[nv];

  // Pass 2: rotation of every live tet (newPos: new position of old position f in bits 2f..2f+1), its
  // rotated list written in its group; then each group sorted by the rotated lists.
  std::vector<uint8_t> newPos(static_cast<size_t>(cap));
  std::vector<int32_t> slotTet(static_cast<size_t>(live));
  std::vector<int32_t> V2(4 * static_cast<size_t>(live));
  {
    std::vector<int32_t> fill(start.begin(), start.end() - 1);
    for (int32_t t = 0; t < cap; ++t)
    {
      if (F[t] & TetMesh::kFree)
        continue;
      const int32_t* w = V + 4 * static_cast<size_t>(t);
      int32_t out[4];
      for (int i = 0; i < 4; ++i)
        out[i] = toOutput(w[i]);
      int8_t ord[4];
      canonicalOrder(out, ord);
      newPos[t] = static_cast<uint8_t>((1 << (2 * ord[1])) | (2 << (2 * ord[2])) | (3 << (2 * ord[3])));
      const int32_t pos = fill[lastInserted(w)]++;
      slotTet[pos] = t;
      int32_t* row = V2.data() + 4 * static_cast<size_t>(pos);
      for (int j = 0; j < 4; ++j)
        row[j] = out[ord[j]];
    }
  }
  for (int32_t v = 0; v < nv; ++v)
  {
    const int32_t a = start[v], b = start[v + 1];
    for (int32_t i = a + 1; i < b; ++i)
    {
      int32_t* rows = V2.data();
      if (!rowLess(rows + 4 * static_cast<size_t>(i), rows + 4 * static_cast<size_t>(i) - 4))
        continue;
      int32_t key[4];
      std::memcpy(key, rows + 4 * static_cast<size_t>(i), sizeof key);
      const int32_t t = slotTet[i];
      int32_t j = i - 1;
      for (; j >= a && rowLess(key, rows + 4 * static_cast<size_t>(j)); --j)
      {
        std::memcpy(rows + 4 * static_cast<size_t>(j + 1), rows + 4 * static_cast<size_t>(j), sizeof key);
        slotTet[j + 1] = slotTet[j];
      }
      std::memcpy(rows + 4 * static_cast<size_t>(j + 1), key, sizeof key);
      slotTet[j + 1] = t;
    }
  }
  std::vector<int32_t> newId(static_cast<size_t>(cap));
  for (int32_t i = 0; i < live; ++i)
    newId[slotTet[i]] = i;

  // Pass 3: neighbour codes for the new numbers and face positions.
  std::vector<int32_t> N2(4 * static_cast<size_t>(live));
  auto write = [&](int32_t from, int32_t to) {
    for (int32_t i = from; i < to; ++i)
    {
      const int32_t t = slotTet[i];
      const uint8_t np = newPos[t];
      const int32_t* n = N + 4 * static_cast<size_t>(t);
      int32_t* n2 = N2.data() + 4 * static_cast<size_t>(i);
      for (int f = 0; f < 4; ++f)
      {
        const int32_t c = n[f];
        const int p = (np >> (2 * f)) & 3;
        if (c < 0)
        {
          n2[p] = c;
          continue;
        }
        const int32_t u = c >> 2;
        n2[p] = (newId[u] << 2) | ((newPos[u] >> (2 * (c & 3))) & 3);
      }
    }
  };
  if (threads > 1 && live >= (1 << 20))
  {
    std::thread helper(write, live / 2, live);
    write(0, live / 2);
    helper.join();
  }
  else
    write(0, live);

  std::vector<double> points;
  points.swap(mesh.points);
  mesh.clear();
  mesh.points.swap(points);
  mesh.tetVertices.swap(V2);
  mesh.tetNeighbors.swap(N2);
  mesh.tetFlags.assign(static_cast<size_t>(live), 0);
  mesh.adjustGhostCount(ghosts);
}

} // namespace volgrid
