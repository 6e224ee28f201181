// Flips around boundary Steiner points that Steiner removal could not remove (Core/Recovery/StarFlips.h).
#include "BoundaryRecovery.h"
#include "MeshChecker.h"
#include "MesherTestCorpusModel.h"
#include "StarFlips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace volgrid;

namespace
{

MeshCheckOptions structural()
{
  MeshCheckOptions o;
  o.delaunay = false;
  o.euler = false;
  return o;
}

// Three tets around edge (3, 4) (a 2-3 flip of two tets sharing face (0, 1, 2)), all in region 5.
void threeTetsAroundEdge(TetMesh& m, MeshEditor& ed, const BoundaryConstraints* bc)
{
  const double p[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.3, 0.3, 1 }, { 0.3, 0.3, -1 } };
  for (auto& q : p)
    m.addPoint(q);
  const int32_t a = m.newTet(0, 1, 2, 3), b = m.newTet(0, 2, 1, 4);
  m.link(a, 3, b, 3);
  ed.rebuildVertexMap();
  ASSERT_TRUE(ed.flip23(a, 3, bc));
  ASSERT_EQ(m.numTets(), 3);
}

} // namespace

TEST(StarFlips, EdgeRemovalKeepsRegionLabels)
{
  TetMesh m;
  MeshEditor ed(m);
  BoundaryConstraints bc;
  bc.init(nullptr, 0);
  threeTetsAroundEdge(m, ed, &bc);
  std::vector<int32_t> region(static_cast<size_t>(m.tetCapacity()), 5);
  ASSERT_TRUE(removeEdgeKeepingRegion(ed, bc, 3, 4, &region));
  EXPECT_EQ(m.numTets(), 2);
  EXPECT_LT(ed.findEdge(3, 4), 0);
  EXPECT_TRUE(checkMesh(m, structural()).valid);
  for (int32_t t = 0; t < m.tetCapacity(); ++t)
    EXPECT_EQ(region[static_cast<size_t>(t)], m.isFree(t) ? -1 : 5) << "slot " << t;
  EXPECT_FALSE(removeEdgeKeepingRegion(ed, bc, 3, 4, &region)); // no longer an edge
}

TEST(StarFlips, CandidatesAreInteriorEdges)
{
  TetMesh m;
  MeshEditor ed(m);
  BoundaryConstraints bc;
  const int32_t tri[3] = { 0, 1, 3 };
  bc.init(tri, 1);
  threeTetsAroundEdge(m, ed, nullptr);
  std::vector<std::pair<int32_t, int32_t>> edges;
  starFlipCandidates(ed, bc, 4, edges);
  ASSERT_FALSE(edges.empty());
  // Edges through the point first; never a boundary edge (01, 13, 30).
  EXPECT_TRUE(edges.front().first == 4 || edges.front().second == 4);
  for (auto& e : edges)
    EXPECT_FALSE(bc.isEdge(e.first, e.second)) << e.first << "-" << e.second;
  EXPECT_TRUE(std::any_of(edges.begin(), edges.end(),
                          [](const std::pair<int32_t, int32_t>& e)
                          { return edgeKey(e.first, e.second) == edgeKey(1, 2); }));
}

// triceratops.off leaves two segment Steiner points in flat stars on its planar parts that only go
// once interior edges next to them are flipped away.
TEST(StarFlips, TriceratopsBoundarySteinerPointsRemoved)
{
  MesherResult r;
  if (!testshapes::meshCorpusModelAndCheck("tetgen-tests/cgal/triceratops.off", r))
    GTEST_SKIP() << "no corpus file tetgen-tests/cgal/triceratops.off";
}
