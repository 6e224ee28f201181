#include "MeshNavigator.h"

#include "ParallelFor.h"
#include "PredicatesInline.h"

#include <algorithm>

namespace volgrid
{

MeshNavigator::MeshNavigator(TetMesh& m, StaleEntries rule, VertexMap map)
  : mesh(m)
  , stale_(rule)
  , map_(map)
{
  if (map_ == VertexMap::Kept)
    rebuildVertexMap();
}

void MeshNavigator::rebuildVertexMap()
{
  for (int32_t v : written_)
    writtenFlag_[static_cast<size_t>(v)] = 0;
  written_.clear();
  vertTet_.assign(static_cast<size_t>(mesh.numVertices()), -1);
  mesh.forEachTet(
    [&](int32_t t)
    {
      const int32_t* v = mesh.vertices(t);
      for (int i = 0; i < 4; ++i)
        if (v[i] >= 0)
          vertTet_[static_cast<size_t>(v[i])] = t;
    });
}

bool MeshNavigator::refreshVertexMap(const std::vector<int32_t>& hint, Progress* progress)
{
  if (map_ == VertexMap::None)
    return true;
  const size_t nv = static_cast<size_t>(mesh.numVertices());
  vertTet_.resize(nv, -1); // as a rebuild: no entry past the last point
  auto holds = [&](int32_t t, int32_t v)
  { return t >= 0 && t < mesh.tetCapacity() && !mesh.isFree(t) && mesh.localIndex(t, v) >= 0; };
  for (int32_t v : written_)
    if (static_cast<size_t>(v) < nv && !holds(vertTet_[static_cast<size_t>(v)], v))
      vertTet_[static_cast<size_t>(v)] = -1;
  for (int32_t t : hint)
  {
    if (t < 0 || t >= mesh.tetCapacity() || mesh.isFree(t))
      continue;
    for (int i = 0; i < 4; ++i)
    {
      const size_t w = static_cast<size_t>(mesh.vertex(t, i));
      if (w < nv && w < writtenFlag_.size() && writtenFlag_[w] && vertTet_[w] < 0)
        vertTet_[w] = t;
    }
  }
  for (int32_t v : written_)
    writtenFlag_[static_cast<size_t>(v)] = 0;
  // Each entry from its own star. After the first quality pass on a 5M-tet mesh these are the stars of
  // about 500,000 vertices (0.4 s on one thread): on several threads they are walked without the shared
  // stamps (read only, in any order; the same entries).
  const size_t block = progress ? kRefreshesPerQuestion : std::max<size_t>(written_.size(), 1);
  for (size_t first = 0; first < written_.size(); first += block)
  {
    if (first > 0 && progress->cancelled())
    {
      written_.erase(written_.begin(), written_.begin() + static_cast<std::ptrdiff_t>(first));
      return false;
    }
    refreshStars(first, std::min(written_.size(), first + block));
  }
  written_.clear();
  return true;
}

void MeshNavigator::refreshStars(size_t begin, size_t end)
{
  const size_t nv = static_cast<size_t>(mesh.numVertices());
  const int ranges = parallelRanges(refreshThreads, static_cast<int64_t>(end - begin), kMinRefreshesPerThread);
  if (ranges <= 1)
    for (size_t k = begin; k < end; ++k)
    {
      const int32_t v = written_[k];
      if (static_cast<size_t>(v) >= nv || vertTet_[static_cast<size_t>(v)] < 0)
        continue;
      star(v, findScratch_); // the scratch of findEdge/findFace, which this does not call
      vertTet_[static_cast<size_t>(v)] = *std::max_element(findScratch_.begin(), findScratch_.end());
    }
  else
    parallelFor(ranges, static_cast<int64_t>(end - begin), kMinRefreshesPerThread,
                [&](int, int64_t from, int64_t to)
                {
                  std::vector<int32_t> starTets;
                  for (int64_t k = from; k < to; ++k)
                  {
                    const size_t v = static_cast<size_t>(written_[begin + static_cast<size_t>(k)]);
                    if (v < nv && vertTet_[v] >= 0)
                      vertTet_[v] = highestSlotOfStar(static_cast<int32_t>(v), vertTet_[v], starTets);
                  }
                });
}

int32_t MeshNavigator::highestSlotOfStar(int32_t v, int32_t t0, std::vector<int32_t>& starTets) const
{
  // Breadth first over the faces holding v, as star() but without the shared stamps: the tets found are
  // kept in a small open-addressing table (a star has a few dozen tets; a larger one falls back to a
  // search of those found).
  constexpr uint32_t kTable = 64; // a power of two
  int32_t table[kTable];
  std::fill_n(table, kTable, -1);
  auto seen = [&](int32_t u)
  {
    if (starTets.size() >= kTable / 2)
      return std::find(starTets.begin(), starTets.end(), u) != starTets.end();
    for (uint32_t h = (static_cast<uint32_t>(u) * 2654435761u) >> 26;; h = (h + 1) & (kTable - 1))
    {
      if (table[h] == u)
        return true;
      if (table[h] < 0)
      {
        table[h] = u;
        return false;
      }
    }
  };
  starTets.clear();
  seen(t0);
  starTets.push_back(t0);
  int32_t highest = t0;
  for (size_t k = 0; k < starTets.size(); ++k)
  {
    const int32_t t = starTets[k];
    const int li = mesh.localIndex(t, v);
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = mesh.neighbor(t, i);
      if (i == li || u < 0 || seen(u))
        continue;
      starTets.push_back(u);
      highest = std::max(highest, u);
    }
  }
  return highest;
}

int32_t MeshNavigator::tetOf(int32_t v)
{
  if (stale_ == StaleEntries::Trust)
    return mappedTet(v);
  if (v < 0)
    return -1;
  const int32_t t = mappedTet(v);
  if (t >= 0 && t < mesh.tetCapacity() && !mesh.isFree(t) && mesh.localIndex(t, v) >= 0)
    return t;
  // Stale entry (should not happen: every edit refreshes the vertices it touches): rescan.
  rebuildVertexMap();
  return mappedTet(v);
}

void MeshNavigator::ensureStamp()
{
  tetStamp.ensure(mesh.tetCapacity());
}

uint32_t MeshNavigator::newStamp()
{
  return tetStamp.next(mesh.tetCapacity());
}

void MeshNavigator::star(int32_t v, std::vector<int32_t>& out)
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

int32_t MeshNavigator::findEdge(int32_t a, int32_t b)
{
  star(a, findScratch_);
  for (int32_t t : findScratch_)
    if (mesh.localIndex(t, b) >= 0)
      return t;
  return -1;
}

int32_t MeshNavigator::findFace(int32_t a, int32_t b, int32_t c, int* face)
{
  star(a, findScratch_);
  for (int32_t t : findScratch_)
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

int32_t MeshNavigator::walk(const double* p, int32_t start, WalkOrder order) const
{
  if (start < 0 || start >= mesh.tetCapacity() || mesh.isFree(start))
    return -1;
  int32_t t = start;
  uint32_t rng = 0x9E3779B9u ^ static_cast<uint32_t>(start);
  const int64_t maxSteps = 4 * static_cast<int64_t>(mesh.numTets()) + (order == WalkOrder::Rotating ? 100 : 64);
  for (int64_t step = 0; step < maxSteps; ++step)
  {
    int first = static_cast<int>(step & 3);
    if (order == WalkOrder::Random)
    {
      rng = rng * 1664525u + 1013904223u;
      first = static_cast<int>((rng >> 16) & 3);
    }
    int exitFace = -1;
    for (int k = 0; k < 4; ++k)
    {
      const int i = (first + k) & 3;
      int32_t f[3];
      mesh.faceVertices(t, i, f);
      if (predicates::orient3dInline(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p) < 0)
      {
        exitFace = i;
        break;
      }
    }
    if (exitFace < 0)
      return t;
    const int32_t u = mesh.neighbor(t, exitFace);
    if (u < 0)
      return -1;
    t = u;
  }
  return -1;
}

void MeshNavigator::labelTets(const std::vector<int32_t>& ids, int32_t label)
{
  if (!labels)
    return;
  if (labels->size() < static_cast<size_t>(mesh.tetCapacity()))
    labels->resize(static_cast<size_t>(mesh.tetCapacity()), -1);
  for (int32_t t : ids)
    (*labels)[static_cast<size_t>(t)] = label;
}

namespace
{
void sortTriple(int32_t* k)
{
  if (k[0] > k[1])
    std::swap(k[0], k[1]);
  if (k[1] > k[2])
    std::swap(k[1], k[2]);
  if (k[0] > k[1])
    std::swap(k[0], k[1]);
}

template<class Face>
bool sameKey(const Face& a, const Face& b)
{
  return a.key[0] == b.key[0] && a.key[1] == b.key[1] && a.key[2] == b.key[2];
}

// The run of faces with the key of faces[k]: [k, end), old outer faces (owner -1) sorted first.
template<class Face>
size_t keyRunEnd(const std::vector<Face>& faces, size_t k)
{
  size_t j = k + 1;
  while (j < faces.size() && sameKey(faces[j], faces[k]))
    ++j;
  return j;
}
} // namespace

bool MeshNavigator::replaceTets(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets,
                                std::vector<int32_t>* created, bool allowOpen)
{
  // The old tets' outer faces and every face of the new tets, sorted by key (outer first within a key).
  std::vector<FaceEntry>& faces = replaceFaces_;
  faces.clear();
  const uint32_t s = newStamp();
  for (int32_t t : oldTets)
    tetStamp[t] = s;
  for (int32_t t : oldTets)
    for (int i = 0; i < 4; ++i)
    {
      const int32_t c = mesh.neighborCode(t, i);
      if (c >= 0 && tetStamp[c >> 2] == s)
        continue;
      FaceEntry e;
      mesh.faceVertices(t, i, e.key);
      sortTriple(e.key);
      e.code = c;
      e.owner = -1;
      e.face = i;
      faces.push_back(e);
    }
  for (size_t n = 0; n < newTets.size(); ++n)
    for (int i = 0; i < 4; ++i)
    {
      FaceEntry e;
      for (int k = 0; k < 3; ++k)
        e.key[k] = newTets[n][TetMesh::kFaceVertex[i][k]];
      sortTriple(e.key);
      e.code = TetMesh::kNoNeighbor;
      e.owner = static_cast<int32_t>(n);
      e.face = i;
      faces.push_back(e);
    }
  std::sort(faces.begin(), faces.end(),
            [](const FaceEntry& a, const FaceEntry& b)
            {
              if (a.key[0] != b.key[0])
                return a.key[0] < b.key[0];
              if (a.key[1] != b.key[1])
                return a.key[1] < b.key[1];
              if (a.key[2] != b.key[2])
                return a.key[2] < b.key[2];
              return a.owner < b.owner;
            });
  // A key is (outer, new) or (new, new); with allowOpen also a lone new face or a lone outer face.
  for (size_t k = 0; k < faces.size();)
  {
    const size_t j = keyRunEnd(faces, k);
    const bool paired = j - k == 2 && faces[k + 1].owner >= 0;
    if (!paired && !(allowOpen && j - k == 1))
      return false;
    k = j;
  }
  commitReplacement(oldTets, newTets);
  if (created)
    *created = replaceIds_;
  return true;
}

int32_t MeshNavigator::placeNewTet(const std::array<int32_t, 4>& q)
{
  if (!slotPool)
  {
    journalTet(mesh.freeListHead());
    return mesh.newTet(q[0], q[1], q[2], q[3]);
  }
  // Written in place: newTet() would touch the mesh's free list and counters, which other threads share.
  const int32_t t = slotPool->take();
  std::copy(q.begin(), q.end(), mesh.tetVertices.begin() + 4 * static_cast<ptrdiff_t>(t));
  std::fill_n(mesh.tetNeighbors.begin() + 4 * static_cast<ptrdiff_t>(t), 4, TetMesh::kNoNeighbor);
  return t;
}

void MeshNavigator::commitReplacement(const std::vector<int32_t>& oldTets,
                                      const std::vector<std::array<int32_t, 4>>& newTets)
{
  const uint8_t userBits = oldTets.empty() ? 0 : userBitsOf(oldTets[0]);
  const int32_t label = oldTets.empty() ? -1 : labelOf(oldTets[0]);
  for (int32_t t : oldTets)
  {
    journalTet(t);
    if (slotPool)
      slotPool->give(mesh, t);
    else
      mesh.freeTet(t);
  }
  std::vector<int32_t>& ids = replaceIds_;
  ids.resize(newTets.size());
  for (size_t n = 0; n < newTets.size(); ++n)
  {
    const auto& q = newTets[n];
    const int32_t t = placeNewTet(q);
    mesh.tetFlags[t] = userBits;
    ids[n] = t;
    for (int i = 0; i < 4; ++i)
      if (q[i] >= 0)
        mapVertex(q[i], t);
  }
  labelTets(ids, label);
  // Glue each key's run (checked by replaceTets): two new faces, a new and an outer face, or one alone.
  const std::vector<FaceEntry>& faces = replaceFaces_;
  for (size_t k = 0; k < faces.size();)
  {
    const size_t j = keyRunEnd(faces, k);
    const FaceEntry& a = faces[k];
    if (j - k == 1)
    {
      if (a.owner >= 0)
        mesh.unlink(ids[a.owner], a.face);
      else if (a.code >= 0)
      {
        journalTet(a.code >> 2);
        mesh.unlink(a.code >> 2, a.code & 3);
      }
    }
    else if (a.owner >= 0)
      mesh.link(ids[a.owner], a.face, ids[faces[k + 1].owner], faces[k + 1].face);
    else if (a.code < 0)
      mesh.unlink(ids[faces[k + 1].owner], faces[k + 1].face);
    else
    {
      journalTet(a.code >> 2);
      mesh.link(ids[faces[k + 1].owner], faces[k + 1].face, a.code >> 2, a.code & 3);
    }
    k = j;
  }
  ensureStamp();
}

void MeshNavigator::replaceByCone(const std::vector<int32_t>& cavity, const Cone& cone, std::vector<int32_t>* created)
{
  // Cone tet k has the new vertex at position i = apexAt[k], so its face i is the old boundary face (glued
  // to the old outer neighbour) and its three other faces contain the new vertex and one boundary edge:
  // they are matched pairwise by the edge's vertex pair.
  const uint8_t userBits = userBitsOf(cavity[0]);
  const int32_t label = labelOf(cavity[0]);
  // The outer neighbours' faces are written below, one cone tet after the other: their loads start now.
  for (const int32_t c : cone.outerCode)
    if (c >= 0)
      __builtin_prefetch(&mesh.tetNeighbors[4 * static_cast<size_t>(c >> 2)], 1);
  for (int32_t t : cavity)
  {
    journalTet(t);
    if (slotPool)
      slotPool->give(mesh, t);
    else
      mesh.freeTet(t);
  }
  const size_t n = cone.tets.size();
  std::vector<int32_t>& ids = replaceIds_;
  ids.resize(n);
  for (size_t k = 0; k < n; ++k)
  {
    const auto& q = cone.tets[k];
    const int32_t t = placeNewTet(q);
    mesh.tetFlags[t] = userBits;
    ids[k] = t;
    const int i = cone.apexAt[k];
    const int32_t c = cone.outerCode[k];
    if (c >= 0)
    {
      journalTet(c >> 2);
      mesh.link(t, i, c >> 2, c & 3);
    }
    for (int j = 0; j < 4; ++j)
    {
      mapVertex(q[j], t);
      if (j == i)
        continue;
      // Face j contains the apex (at position i) and the two vertices other than positions i and j.
      int32_t a = -1, b = -1;
      for (int m = 0; m < 4; ++m)
        if (m != i && m != j)
          (a < 0 ? a : b) = q[m];
      const uint64_t key = edgeKey(a, b);
      // The first of the edge's two side faces waits in the table; the second links to it and takes it out,
      // so the table is empty again at the end (no clearing per insertion, unlike the sort it replaced).
      const int32_t code = TetMesh::encode(t, j);
      if (const int32_t* other = openSideFaces_.find(key))
      {
        mesh.link(t, j, *other >> 2, *other & 3);
        openSideFaces_.erase(key);
      }
      else
        openSideFaces_.insert(key, code);
    }
  }
  if (!openSideFaces_.empty()) // a cone whose boundary is not closed (never from a star-shaped cavity)
    openSideFaces_.clear();
  labelTets(ids, label);
  ensureStamp();
  if (created)
    *created = ids;
}

} // namespace volgrid
