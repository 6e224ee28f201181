// DelaunayInserter: the public face of the Bowyer-Watson insertion (DelaunayInserterImpl.h holds the
// code), and the first tet with its four ghosts.
#include "DelaunayInserterImpl.h"

namespace volgrid
{

DelaunayInserter::DelaunayInserter(TetMesh& mesh, uint64_t seed)
  : impl_(new Impl(mesh, seed))
{
}
DelaunayInserter::~DelaunayInserter() = default;

int32_t DelaunayInserter::locate(const double* p, int32_t hint)
{
  const int32_t start = impl_->liveTet(hint);
  return start < 0 ? -1 : impl_->walk(p, start);
}

DelaunayInserter::Result DelaunayInserter::insert(int32_t v, int32_t hint, const double* next)
{
  return impl_->insert(v, hint, next);
}

void DelaunayInserter::enableBucketGrid(const double lo[3], const double hi[3], size_t expectedVertices)
{
  Impl& m = *impl_;
  m.grid = true;
  // About 4 vertices per bucket at the end: the paper's depth-limited octree with leaf buckets.
  int res = 1;
  while (static_cast<size_t>(res) * res * res * 4 < expectedVertices && res < 512)
    ++res;
  m.gres = res;
  for (int a = 0; a < 3; ++a)
  {
    m.glo[a] = lo[a];
    const double ext = hi[a] - lo[a];
    m.gscale[a] = ext > 0 ? res / ext : 0.0;
  }
  m.bucketHead.assign(static_cast<size_t>(res) * res * res, -1);
  m.vertexNext.assign(std::max<size_t>(expectedVertices, static_cast<size_t>(m.mesh.numVertices())), -1);
  m.vertexTet.assign(m.vertexNext.size(), -1);
}

void DelaunayInserter::registerVertex(int32_t v, int32_t tet)
{
  impl_->gridRegister(v, tet);
}

void DelaunayInserter::setSoSIds(const int32_t* ids)
{
  impl_->sosId = ids;
}

int32_t DelaunayInserter::lastTet() const
{
  return impl_->last;
}
uint64_t DelaunayInserter::walkSteps() const
{
  return impl_->walkSteps;
}
uint64_t DelaunayInserter::cavityTets() const
{
  return impl_->cavityTets;
}

// ---------------------------------------------------------------------------------------------------
int32_t initDelaunayTet(TetMesh& mesh, int32_t a, int32_t b, int32_t c, int32_t d)
{
  const int o = predicates::orient3d(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d));
  assert(o != 0);
  if (o < 0)
    std::swap(a, b);
  const int32_t t = mesh.newTet(a, b, c, d);
  int32_t ghosts[4];
  for (int i = 0; i < 4; ++i)
  {
    int32_t f[3];
    mesh.faceVertices(t, i, f);
    // Reverse the face so that the vertex at infinity (outside) sees it positively.
    ghosts[i] = mesh.newTet(f[0], f[2], f[1], TetMesh::kGhostVertex);
    mesh.link(t, i, ghosts[i], 3);
  }
  // Ghost faces 0,1,2 contain the vertex at infinity and a hull edge: pair them by edge.
  for (int i = 0; i < 4; ++i)
    for (int g = 0; g < 3; ++g)
    {
      if (mesh.neighborCode(ghosts[i], g) >= 0)
        continue;
      const EdgePair e = kOther[3][g];
      const uint64_t key = edgeKey(mesh.vertex(ghosts[i], e.x), mesh.vertex(ghosts[i], e.y));
      for (int j = 0; j < 4; ++j)
        for (int h = 0; h < 3 && j != i; ++h)
        {
          const EdgePair e2 = kOther[3][h];
          if (edgeKey(mesh.vertex(ghosts[j], e2.x), mesh.vertex(ghosts[j], e2.y)) == key)
            mesh.link(ghosts[i], g, ghosts[j], h);
        }
    }
  return t;
}

} // namespace volgrid
