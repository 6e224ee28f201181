#include "MeshNavigator.h"

#include "PredicatesInline.h"

namespace volgrid
{

MeshNavigator::MeshNavigator(TetMesh& m, StaleEntries rule)
  : mesh(m)
  , stale_(rule)
{
  rebuildVertexMap();
}

void MeshNavigator::rebuildVertexMap()
{
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

} // namespace volgrid
