#include "BoundaryCensus.h"

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace volgrid
{

namespace
{

constexpr int32_t kFound = static_cast<int32_t>(0x80000000u); // sign bit of an edge entry
constexpr int32_t kEnd = 0x7fffffff;

void sort3(int32_t& x, int32_t& y, int32_t& z)
{
  if (x > y)
    std::swap(x, y);
  if (y > z)
    std::swap(y, z);
  if (x > y)
    std::swap(x, y);
}

// Sets the found bit of the n edge entries at e that equal a, b or c.
inline void markEdges(int32_t* e, int32_t n, int32_t a, int32_t b, int32_t c)
{
#if defined(__SSE2__)
  // Four entries at a time (data_ is padded): rows are short, and a branch per entry mispredicts.
  static const int32_t lanes[8] = { -1, -1, -1, -1, 0, 0, 0, 0 };
  const __m128i A = _mm_set1_epi32(a), B = _mm_set1_epi32(b), C = _mm_set1_epi32(c);
  const __m128i value = _mm_set1_epi32(~kFound), found = _mm_set1_epi32(kFound);
  for (int32_t k = 0; k < n; k += 4)
  {
    __m128i* p = reinterpret_cast<__m128i*>(e + k);
    const __m128i E = _mm_loadu_si128(p);
    const __m128i V = _mm_and_si128(E, value);
    __m128i hit = _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi32(V, A), _mm_cmpeq_epi32(V, B)), _mm_cmpeq_epi32(V, C));
    hit = _mm_and_si128(hit, _mm_loadu_si128(reinterpret_cast<const __m128i*>(lanes + 4 - std::min(n - k, 4))));
    _mm_storeu_si128(p, _mm_or_si128(E, _mm_and_si128(hit, found)));
  }
#else
  for (int32_t k = 0; k < n; ++k)
  {
    const int32_t v = e[k] & ~kFound;
    e[k] |= (v == a) | (v == b) | (v == c) ? kFound : 0;
  }
#endif
}

} // namespace

void BoundaryCensus::take(const MeshEditor& editor, const BoundaryConstraints& bc, bool withEdges)
{
  index(bc.verts.data(), bc.capacity(), bc.parent.data(), editor.mesh.numVertices());
  sweep(editor.mesh, withEdges);
  edgesSwept_ = withEdges;
  mesh_ = &editor.mesh;
  bc_ = &bc;
  edits_ = editor.edits;
  tetCapacity_ = editor.mesh.tetCapacity();
  numTets_ = editor.mesh.numTets();
  bcCapacity_ = bc.capacity();
  bcAlive_ = bc.numAlive();
}

void BoundaryCensus::take(const TetMesh& mesh, const int32_t* triangles, int32_t count, bool withEdges)
{
  index(triangles, count, nullptr, mesh.numVertices());
  sweep(mesh, withEdges);
  edgesSwept_ = withEdges;
  mesh_ = nullptr; // never up to date
  bc_ = nullptr;
}

bool BoundaryCensus::upToDate(const MeshEditor& editor, const BoundaryConstraints& bc) const
{
  return edgesSwept_ && mesh_ == &editor.mesh && bc_ == &bc && edits_ == editor.edits &&
    tetCapacity_ == editor.mesh.tetCapacity() && numTets_ == editor.mesh.numTets() && bcCapacity_ == bc.capacity() &&
    bcAlive_ == bc.numAlive();
}

void BoundaryCensus::index(const int32_t* verts, int32_t count, const int32_t* parent, int32_t numVertices)
{
  auto alive = [&](int32_t f) { return !parent || parent[f] >= 0; };
  int32_t nrows = numVertices;
  for (int32_t f = 0; f < count; ++f)
    if (alive(f))
      for (int k = 0; k < 3; ++k)
        nrows = std::max(nrows, verts[3 * static_cast<size_t>(f) + k] + 1);
  const size_t n = static_cast<size_t>(nrows);
  // Counting sort of the edges (each listed by both its subfaces) by smallest vertex; degenerate subfaces
  // (a repeated vertex) are left out.
  std::vector<int32_t> edgeStart(n + 1, 0), faceCount(n, 0);
  auto sortedSubface = [&](int32_t f, int32_t& x, int32_t& y, int32_t& z)
  {
    x = verts[3 * static_cast<size_t>(f)];
    y = verts[3 * static_cast<size_t>(f) + 1];
    z = verts[3 * static_cast<size_t>(f) + 2];
    sort3(x, y, z);
    return x >= 0 && x != y && y != z;
  };
  int32_t x, y, z;
  for (int32_t f = 0; f < count; ++f)
    if (alive(f) && sortedSubface(f, x, y, z))
    {
      edgeStart[x + 1] += 2;
      edgeStart[y + 1] += 1;
      faceCount[x] += 1;
    }
  for (size_t v = 0; v < n; ++v)
    edgeStart[v + 1] += edgeStart[v];
  std::vector<int32_t> other(static_cast<size_t>(edgeStart[n]));
  {
    std::vector<int32_t> cursor(edgeStart.begin(), edgeStart.end() - 1);
    for (int32_t f = 0; f < count; ++f)
      if (alive(f) && sortedSubface(f, x, y, z))
      {
        other[cursor[x]++] = y;
        other[cursor[x]++] = z;
        other[cursor[y]++] = z;
      }
  }
  // Each row: distinct edge ends, then room for the subface quadruples.
  rows_.assign(n, Row{ 0, 0, 0 });
  data_.clear();
  data_.reserve(other.size() / 2 + 4 * static_cast<size_t>(count) + 4);
  for (size_t v = 0; v < n; ++v)
  {
    Row& r = rows_[v];
    r.begin = static_cast<int32_t>(data_.size());
    std::sort(other.begin() + edgeStart[v], other.begin() + edgeStart[v + 1]);
    for (int32_t e = edgeStart[v]; e < edgeStart[v + 1]; ++e)
      if (e == edgeStart[v] || other[e] != other[e - 1])
        data_.push_back(other[e]);
    r.faces = static_cast<int32_t>(data_.size());
    data_.resize(data_.size() + 4 * static_cast<size_t>(faceCount[v]), kEnd);
    r.end = static_cast<int32_t>(data_.size());
    faceCount[v] = r.faces; // from now on: the next free quadruple of the row
  }
  data_.resize(data_.size() + 3, kEnd); // padding: the sweep reads edge entries four at a time
  facePos_.assign(static_cast<size_t>(count), -1);
  for (int32_t f = 0; f < count; ++f)
    if (alive(f) && sortedSubface(f, x, y, z))
    {
      int32_t* q = data_.data() + faceCount[x];
      q[0] = y;
      q[1] = z;
      q[2] = f;
      q[3] = -1;
      facePos_[static_cast<size_t>(f)] = faceCount[x];
      faceCount[x] += 4;
    }
}

// Right after index(): no edge found yet, every face code -1.
void BoundaryCensus::sweep(const TetMesh& m, bool withEdges)
{
  const int32_t nrows = static_cast<int32_t>(rows_.size());
  const int32_t cap = m.tetCapacity();
  const int32_t* tv = m.tetVertices.data();
  const uint8_t* flags = m.tetFlags.data();
  const Row* rows = rows_.data();
  int32_t* d = data_.data();
  for (int32_t t = 0; t < cap; ++t)
  {
    const int32_t* w = tv + 4 * static_cast<size_t>(t);
    if ((flags[t] & TetMesh::kFree) || (w[0] | w[1] | w[2] | w[3]) < 0)
      continue; // free slot or ghost
    // The vertices sorted (a sorting network), with their local indices. A row of vertex x lists only
    // larger vertices, so the edges of the tet are in the rows of s0, s1, s2 and its faces in those of
    // s0 and s1.
    int32_t s[4] = { w[0], w[1], w[2], w[3] };
    int li[4] = { 0, 1, 2, 3 };
    auto order = [&](int i, int j)
    {
      const bool swap = s[i] > s[j];
      const int32_t lo = swap ? s[j] : s[i], hi = swap ? s[i] : s[j];
      const int a = swap ? li[j] : li[i], b = swap ? li[i] : li[j];
      s[i] = lo;
      s[j] = hi;
      li[i] = a;
      li[j] = b;
    };
    order(0, 1);
    order(2, 3);
    order(0, 2);
    order(1, 3);
    order(1, 2);
    if (s[2] >= nrows)
      continue; // vertices added after index() constrain nothing
    if (withEdges)
      for (int i = 0; i < 3; ++i)
        markEdges(d + rows[s[i]].begin, rows[s[i]].faces - rows[s[i]].begin, s[1], s[2], s[3]);
    // Faces {s0,y,z}: (s1,s2) is the face opposite s3, (s1,s3) opposite s2, (s2,s3) opposite s1. Faces
    // {s1,y,z}: only (s2,s3), opposite s0. Branch-free bodies: the hits are rare and unpredictable.
    {
      const Row& r = rows[s[0]];
      for (int32_t q = r.faces; q < r.end; q += 4)
      {
        const int32_t y = d[q], z = d[q + 1];
        const int y1 = y == s[1], y2 = y == s[2], z2 = z == s[2], z3 = z == s[3];
        const int opp = 3 * (y1 & z2) + 2 * (y1 & z3) + (y2 & z3);
        d[q + 3] = opp ? TetMesh::encode(t, li[opp]) : d[q + 3];
      }
    }
    {
      const Row& r = rows[s[1]];
      const int32_t code = TetMesh::encode(t, li[0]);
      for (int32_t q = r.faces; q < r.end; q += 4)
        d[q + 3] = (d[q] == s[2]) & (d[q + 1] == s[3]) ? code : d[q + 3];
    }
  }
}

int32_t BoundaryCensus::edgeId(int32_t a, int32_t b) const
{
  if (a > b)
    std::swap(a, b);
  if (a < 0 || a == b || a >= static_cast<int32_t>(rows_.size()))
    return -1;
  for (int32_t e = rows_[a].begin; e < rows_[a].faces; ++e)
    if ((data_[e] & ~kFound) == b)
      return e;
  return -1;
}

} // namespace volgrid
