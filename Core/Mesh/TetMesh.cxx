#include "TetMesh.h"

#include <algorithm>

namespace volgrid
{

void TetMesh::reserve(size_t vertices, size_t tets)
{
  if (points.capacity() < 3 * vertices)
    points.reserve(3 * vertices);
  if (tetFlags.capacity() < tets)
  {
    tetVertices.reserve(4 * tets);
    tetNeighbors.reserve(4 * tets);
    tetFlags.reserve(tets);
  }
}

void TetMesh::clear()
{
  points.clear();
  tetVertices.clear();
  tetNeighbors.clear();
  tetFlags.clear();
  freeHead_ = -1;
  numFree_ = 0;
  numGhost_ = 0;
}

int32_t TetMesh::addPoint(const double* xyz)
{
  const int32_t v = numVertices();
  points.insert(points.end(), xyz, xyz + 3);
  return v;
}

int32_t TetMesh::newTet(int32_t v0, int32_t v1, int32_t v2, int32_t v3)
{
  int32_t t;
  if (freeHead_ >= 0)
  {
    t = freeHead_;
    freeHead_ = tetNeighbors[4 * static_cast<size_t>(t)];
    --numFree_;
    tetFlags[t] = 0;
  }
  else
  {
    t = tetCapacity();
    // Grow by 1.5x instead of the standard library's doubling: the arrays are the mesh's bulk.
    if (tetFlags.size() == tetFlags.capacity())
    {
      const size_t cap = tetFlags.capacity() + tetFlags.capacity() / 2 + 16;
      tetVertices.reserve(4 * cap);
      tetNeighbors.reserve(4 * cap);
      tetFlags.reserve(cap);
    }
    tetVertices.resize(tetVertices.size() + 4);
    tetNeighbors.resize(tetNeighbors.size() + 4);
    tetFlags.push_back(0);
  }
  int32_t* v = tetVertices.data() + 4 * static_cast<size_t>(t);
  v[0] = v0;
  v[1] = v1;
  v[2] = v2;
  v[3] = v3;
  int32_t* n = tetNeighbors.data() + 4 * static_cast<size_t>(t);
  n[0] = n[1] = n[2] = n[3] = kNoNeighbor;
  if ((v0 | v1 | v2 | v3) < 0)
    ++numGhost_;
  return t;
}

int32_t TetMesh::appendTets(int32_t count)
{
  assert(count >= 0);
  const int32_t first = tetCapacity();
  const size_t need = tetFlags.size() + static_cast<size_t>(count);
  if (need > tetFlags.capacity())
  {
    const size_t cap = std::max(need, tetFlags.capacity() + tetFlags.capacity() / 2 + 16);
    tetVertices.reserve(4 * cap);
    tetNeighbors.reserve(4 * cap);
    tetFlags.reserve(cap);
  }
  tetVertices.resize(4 * need);
  tetNeighbors.resize(4 * need);
  tetFlags.resize(need, 0);
  return first;
}

void TetMesh::truncate(int32_t capacity)
{
  assert(capacity >= 0 && capacity <= tetCapacity());
  tetVertices.resize(4 * static_cast<size_t>(capacity));
  tetNeighbors.resize(4 * static_cast<size_t>(capacity));
  tetFlags.resize(static_cast<size_t>(capacity));
}

void TetMesh::setTetVertices(int32_t t, int32_t v0, int32_t v1, int32_t v2, int32_t v3)
{
  assert(!isFree(t));
  int32_t* v = tetVertices.data() + 4 * static_cast<size_t>(t);
  numGhost_ -= (v[0] | v[1] | v[2] | v[3]) < 0 ? 1 : 0;
  v[0] = v0;
  v[1] = v1;
  v[2] = v2;
  v[3] = v3;
  numGhost_ += (v0 | v1 | v2 | v3) < 0 ? 1 : 0;
}

void TetMesh::freeTet(int32_t t)
{
  assert(!isFree(t));
  if (isGhost(t))
    --numGhost_;
  tetFlags[t] = kFree;
  tetNeighbors[4 * static_cast<size_t>(t)] = freeHead_;
  freeHead_ = t;
  ++numFree_;
}

std::vector<int32_t> TetMesh::takeFreeSlots()
{
  std::vector<int32_t> slots;
  slots.reserve(static_cast<size_t>(numFree_));
  const int32_t n = tetCapacity();
  for (int32_t t = 0; t < n; ++t)
    if (tetFlags[t] & kFree)
      slots.push_back(t);
  freeHead_ = -1;
  numFree_ = 0;
  return slots;
}

void TetMesh::returnSlot(int32_t t)
{
  assert(t >= 0 && t < tetCapacity());
  tetFlags[t] = kFree;
  tetNeighbors[4 * static_cast<size_t>(t)] = freeHead_;
  freeHead_ = t;
  ++numFree_;
}

int32_t TetMesh::removeGhostTets()
{
  int32_t removed = 0;
  const int32_t n = tetCapacity();
  for (int32_t t = 0; t < n; ++t)
  {
    if (!isGhost(t))
      continue;
    for (int i = 0; i < 4; ++i)
    {
      const int32_t c = neighborCode(t, i);
      if (c >= 0 && !isGhost(c >> 2))
        tetNeighbors[static_cast<size_t>(c)] = kNoNeighbor; // index 4u+j == code (u<<2)|j
    }
    freeTet(t);
    ++removed;
  }
  return removed;
}

void TetMesh::compact(std::vector<int32_t>* oldToNewOut)
{
  const int32_t n = tetCapacity();
  std::vector<int32_t> oldToNew(static_cast<size_t>(n), -1);
  int32_t next = 0;
  for (int32_t t = 0; t < n; ++t)
    if (!isFree(t))
      oldToNew[t] = next++;
  for (int32_t t = 0; t < n; ++t)
  {
    const int32_t nt = oldToNew[t];
    if (nt < 0)
      continue;
    for (int i = 0; i < 4; ++i)
    {
      const int32_t c = tetNeighbors[4 * static_cast<size_t>(t) + i];
      tetVertices[4 * static_cast<size_t>(nt) + i] = tetVertices[4 * static_cast<size_t>(t) + i];
      tetNeighbors[4 * static_cast<size_t>(nt) + i] = c < 0 ? kNoNeighbor : encode(oldToNew[c >> 2], c & 3);
    }
    tetFlags[nt] = tetFlags[t];
  }
  tetVertices.resize(4 * static_cast<size_t>(next));
  tetNeighbors.resize(4 * static_cast<size_t>(next));
  tetFlags.resize(static_cast<size_t>(next));
  tetVertices.shrink_to_fit();
  tetNeighbors.shrink_to_fit();
  tetFlags.shrink_to_fit();
  freeHead_ = -1;
  numFree_ = 0;
  if (oldToNewOut)
    oldToNewOut->swap(oldToNew);
}

size_t TetMesh::memoryBytes() const
{
  return points.capacity() * sizeof(double) + tetVertices.capacity() * sizeof(int32_t) +
    tetNeighbors.capacity() * sizeof(int32_t) + tetFlags.capacity();
}

} // namespace volgrid
