// The undo log of local edits (Core/EditJournal.h): edits made through a TetEditor with a journal, and
// point moves saved by the caller, are undone exactly (every array slot for slot, the free list and the
// counters, the labels), also for nested marks.
#include "Delaunay.h"
#include "EditJournal.h"
#include "MeshChecker.h"
#include "MeshOptimization.h"
#include "RandomDelaunay.h"
#include "TetEditor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace volgrid;

namespace
{
void expectSame(const TetMesh& a, const TetMesh& b)
{
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.tetVertices, b.tetVertices);
  EXPECT_EQ(a.tetNeighbors, b.tetNeighbors);
  EXPECT_EQ(a.tetFlags, b.tetFlags);
  EXPECT_EQ(a.numTets(), b.numTets());
  EXPECT_EQ(a.numFreeTets(), b.numFreeTets());
  EXPECT_EQ(a.numGhostTets(), b.numGhostTets());
  EXPECT_EQ(a.freeListHead(), b.freeListHead());
}

// Inserts a point at the centroid of each of `count` tets and runs 2-3 flips; returns the edits made.
int edit(TetEditor& ed, int count, int32_t firstTet)
{
  TetMesh& m = ed.mesh;
  int edits = 0;
  for (int32_t t = firstTet; edits < count && t < m.tetCapacity(); ++t)
  {
    if (m.isFree(t))
      continue;
    double c[3] = { 0, 0, 0 };
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k)
        c[k] += 0.25 * m.point(m.vertex(t, i))[k];
    const int32_t v = m.addPoint(c);
    if (ed.insertPoint(v, t) == TetEditor::InsertStatus::Inserted)
      ++edits;
    else
      m.points.resize(m.points.size() - 3);
    for (int f = 0; f < 4 && !m.isFree(t); ++f)
      edits += tryFlip23(ed, t, f, nullptr) ? 1 : 0;
  }
  return edits;
}
} // namespace

TEST(EditJournal, RollbackRestoresTheMeshAndLabelsExactly)
{
  TetMesh mesh;
  randomDelaunay(mesh, 400);
  std::vector<int32_t> labels(static_cast<size_t>(mesh.tetCapacity()));
  for (size_t t = 0; t < labels.size(); ++t)
    labels[t] = static_cast<int32_t>(t % 3);
  TetEditor ed(mesh, nullptr, &labels);
  EditJournal journal;
  ed.journal = &journal;
  ed.rebuildVertexMap();
  // Some edits kept before the marks (free slots on the free list, which the undone edits reuse).
  ASSERT_GT(edit(ed, 20, 0), 0);
  const TetMesh start = mesh;
  const std::vector<int32_t> startLabels = labels;
  const EditJournal::Mark outer = journal.mark(mesh, &labels);
  ASSERT_GT(edit(ed, 30, 100), 0);
  journal.savePoint(mesh, 5);
  mesh.points[15] += 0.001; // a caller's move of vertex 5
  const TetMesh middle = mesh;
  const std::vector<int32_t> middleLabels = labels;
  const EditJournal::Mark inner = journal.mark(mesh, &labels);
  ASSERT_GT(edit(ed, 30, 300), 0);
  journal.rollback(inner, mesh, &labels);
  expectSame(mesh, middle);
  EXPECT_EQ(labels, middleLabels);
  journal.rollback(outer, mesh, &labels);
  expectSame(mesh, start);
  EXPECT_EQ(labels, startLabels);
  // The restored mesh is a valid one (adjacency, orientation) and the editor goes on from it.
  ed.rebuildVertexMap();
  MeshCheckOptions o;
  o.delaunay = false;
  EXPECT_TRUE(checkMesh(mesh, o).valid) << checkMesh(mesh, o).summary();
  EXPECT_GT(edit(ed, 10, 0), 0);
  EXPECT_TRUE(checkMesh(mesh, o).valid) << checkMesh(mesh, o).summary();
}

// changedSince() tells what the edits since a mark touched: every slot of the mark's capacity whose content
// differs is listed (slots appended since are the caller's to add), and the moved vertices are listed.
TEST(EditJournal, ChangedSinceListsEveryChangedSlotAndMovedPoint)
{
  TetMesh mesh;
  randomDelaunay(mesh, 400);
  TetEditor ed(mesh, nullptr, nullptr);
  EditJournal journal;
  ed.journal = &journal;
  ASSERT_GT(edit(ed, 20, 0), 0); // free slots for the edits below to reuse
  const TetMesh start = mesh;
  const EditJournal::Mark mark = journal.mark(mesh, nullptr);
  ASSERT_GT(edit(ed, 30, 100), 0);
  journal.savePoint(mesh, 7);
  mesh.points[21] += 0.001;
  std::vector<int32_t> slots, points;
  journal.changedSince(mark, slots, points);
  EXPECT_EQ(points, std::vector<int32_t>{ 7 });
  std::sort(slots.begin(), slots.end());
  int32_t changed = 0;
  for (int32_t t = 0; t < start.tetCapacity(); ++t)
  {
    const bool same = std::equal(mesh.vertices(t), mesh.vertices(t) + 4, start.vertices(t)) &&
      mesh.tetFlags[t] == start.tetFlags[t] &&
      std::equal(mesh.tetNeighbors.begin() + 4 * t, mesh.tetNeighbors.begin() + 4 * t + 4,
                 start.tetNeighbors.begin() + 4 * t);
    if (!same)
    {
      ++changed;
      EXPECT_TRUE(std::binary_search(slots.begin(), slots.end(), t)) << "slot " << t;
    }
  }
  EXPECT_GT(changed, 30);
}

// After an undo, MeshNavigator::refreshVertexMap() with the slots the undo restored gives every vertex the
// entry a full rebuild would (the quality stage relies on it instead of a sweep per undone attempt: the
// entries decide where stars start, and so the mesh), also when kept edits before it were never refreshed.
TEST(EditJournal, RefreshAfterAnUndoGivesTheMapOfARebuild)
{
  TetMesh mesh;
  randomDelaunay(mesh, 400);
  TetEditor ed(mesh, nullptr, nullptr);
  TetEditor rebuilt(mesh, nullptr, nullptr, TetEditor::VertexMap::None);
  EditJournal journal;
  ed.journal = &journal;
  ASSERT_GT(edit(ed, 20, 0), 0); // kept, not refreshed
  for (int32_t firstTet : { 100, 300, 50 })
  {
    const EditJournal::Mark mark = journal.mark(mesh, nullptr);
    ASSERT_GT(edit(ed, 25, firstTet), 0);
    std::vector<int32_t> slots, points;
    journal.changedSince(mark, slots, points);
    journal.rollback(mark, mesh, nullptr);
    ed.refreshVertexMap(slots);
    rebuilt.rebuildVertexMap();
    int32_t differing = 0;
    for (int32_t v = 0; v < mesh.numVertices() + 40; ++v)
      differing += ed.mappedTet(v) != rebuilt.mappedTet(v);
    EXPECT_EQ(differing, 0) << "after the undo of the edits from tet " << firstTet;
    ASSERT_GT(edit(ed, 10, firstTet + 20), 0); // kept edits again before the next undo
  }
}

// With refreshThreads > 1 and enough written entries, refreshVertexMap() walks the stars on the threads
// without the shared stamps: the map must still be the one a full rebuild gives.
TEST(EditJournal, RefreshOnThreadsGivesTheMapOfARebuild)
{
  TetMesh mesh;
  randomDelaunay(mesh, 20000);
  TetEditor ed(mesh, nullptr, nullptr);
  ed.refreshThreads = 4;
  TetEditor rebuilt(mesh, nullptr, nullptr, TetEditor::VertexMap::None);
  ASSERT_GT(edit(ed, 6000, 0), 5000); // more written entries than one thread's share of the refresh
  ed.refreshVertexMap({});
  rebuilt.rebuildVertexMap();
  int32_t differing = 0;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    differing += ed.mappedTet(v) != rebuilt.mappedTet(v);
  EXPECT_EQ(differing, 0);
}
