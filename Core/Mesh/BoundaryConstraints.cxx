// BoundaryConstraints (BoundaryRecovery.h): the input triangles and their subfaces while boundary
// Steiner points exist, with the edge and face maps recovery looks them up in.
#include "BoundaryConstraints.h"

#include <algorithm>

namespace volgrid
{

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
  auto onSeg = [](uint64_t seg, int32_t w)
  { return static_cast<int32_t>(seg >> 32) == w || static_cast<int32_t>(seg & 0xffffffffu) == w; };
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

bool BoundaryConstraints::onSegment(int32_t w, uint64_t seg) const
{
  if (static_cast<int32_t>(seg >> 32) == w || static_cast<int32_t>(seg & 0xffffffffu) == w)
    return true;
  auto iw = segmentOf_.find(w);
  return iw != segmentOf_.end() && iw->second == seg;
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

} // namespace volgrid
