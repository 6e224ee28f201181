#include "EditJournal.h"

#include <cassert>

namespace volgrid
{

EditJournal::Mark EditJournal::mark(const TetMesh& mesh, const std::vector<int32_t>* labels) const
{
  Mark m;
  m.tets = tets_.size();
  m.points = points_.size();
  m.capacity = mesh.tetCapacity();
  m.vertices = mesh.numVertices();
  m.labels = labels ? labels->size() : 0;
  m.bookkeeping = mesh.bookkeeping();
  return m;
}

void EditJournal::saveTet(const TetMesh& mesh, const std::vector<int32_t>* labels, int32_t t)
{
  assert(t >= 0 && t < mesh.tetCapacity());
  TetRecord r;
  r.t = t;
  r.label = labels && static_cast<size_t>(t) < labels->size() ? (*labels)[t] : -1;
  const size_t base = 4 * static_cast<size_t>(t);
  for (int i = 0; i < 4; ++i)
  {
    r.vertices[i] = mesh.tetVertices[base + i];
    r.neighbors[i] = mesh.tetNeighbors[base + i];
  }
  r.flags = mesh.tetFlags[t];
  tets_.push_back(r);
}

void EditJournal::savePoint(const TetMesh& mesh, int32_t v)
{
  const double* p = mesh.point(v);
  points_.push_back({ v, { p[0], p[1], p[2] } });
}

void EditJournal::changedSince(const Mark& m, std::vector<int32_t>& slots, std::vector<int32_t>& points) const
{
  slots.clear();
  points.clear();
  for (size_t k = m.tets; k < tets_.size(); ++k)
    slots.push_back(tets_[k].t);
  for (size_t k = m.points; k < points_.size(); ++k)
    points.push_back(points_[k].v);
}

void EditJournal::rollback(const Mark& mark, TetMesh& mesh, std::vector<int32_t>* labels)
{
  assert(mark.tets <= tets_.size() && mark.points <= points_.size());
  assert(mark.capacity <= mesh.tetCapacity() && mark.vertices <= mesh.numVertices());
  for (size_t k = tets_.size(); k-- > mark.tets;)
  {
    const TetRecord& r = tets_[k];
    const size_t base = 4 * static_cast<size_t>(r.t);
    for (int i = 0; i < 4; ++i)
    {
      mesh.tetVertices[base + i] = r.vertices[i];
      mesh.tetNeighbors[base + i] = r.neighbors[i];
    }
    mesh.tetFlags[r.t] = r.flags;
    if (labels && static_cast<size_t>(r.t) < labels->size())
      (*labels)[r.t] = r.label;
  }
  tets_.resize(mark.tets);
  for (size_t k = points_.size(); k-- > mark.points;)
  {
    const PointRecord& r = points_[k];
    double* p = mesh.points.data() + 3 * static_cast<size_t>(r.v);
    p[0] = r.xyz[0];
    p[1] = r.xyz[1];
    p[2] = r.xyz[2];
  }
  points_.resize(mark.points);
  mesh.truncate(mark.capacity);
  mesh.points.resize(3 * static_cast<size_t>(mark.vertices));
  mesh.restoreBookkeeping(mark.bookkeeping);
  if (labels)
    labels->resize(mark.labels);
}

void EditJournal::clear()
{
  tets_.clear();
  points_.clear();
}

} // namespace volgrid
