// BoundaryCensus (one sweep over the tets) against the per-item searches it replaces
// (MeshEditor::findEdge / findFace), and the FlatHashMap behind BoundaryConstraints.
#include "BoundaryCensus.h"
#include "BoundaryRecovery.h"
#include "Delaunay.h"
#include "FlatHashMap.h"
#include "MesherTestShapes.h"
#include "RecoveryTestSetup.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

using namespace volgrid;

namespace
{

// Every answer of the census equals the star searches'; returns how many edges and faces were missing.
std::pair<int, int> expectCensusMatchesSearch(MeshEditor& ed, const BoundaryConstraints& bc)
{
  BoundaryCensus census;
  census.take(ed, bc);
  EXPECT_TRUE(census.upToDate(ed, bc));
  int missingEdges = 0, missingFaces = 0;
  for (int32_t f = 0; f < bc.capacity(); ++f)
  {
    if (!bc.alive(f))
      continue;
    const int32_t* s = bc.subface(f);
    for (int i = 0; i < 3; ++i)
    {
      const int32_t a = s[i], b = s[(i + 1) % 3];
      const int32_t id = census.edgeId(a, b);
      EXPECT_GE(id, 0);
      EXPECT_EQ(id, census.edgeId(b, a));
      const bool present = ed.findEdge(a, b) >= 0;
      EXPECT_EQ(census.edgePresent(id), present) << "edge " << a << "-" << b;
      missingEdges += !present;
    }
    const int32_t code = census.faceCode(f);
    EXPECT_EQ(code >= 0, ed.findFace(s[0], s[1], s[2]) >= 0) << "subface " << f;
    missingFaces += code < 0;
    if (code >= 0)
    {
      // The reported face has the subface's three vertices.
      int32_t fv[3];
      ed.mesh.faceVertices(code >> 2, code & 3, fv);
      EXPECT_EQ(TriKey(fv[0], fv[1], fv[2]), TriKey(s[0], s[1], s[2]));
    }
  }
  // A faces-only census finds the same faces and no edges.
  BoundaryCensus faces;
  faces.take(ed, bc, false);
  EXPECT_FALSE(faces.upToDate(ed, bc));
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f))
    {
      EXPECT_EQ(faces.faceCode(f), census.faceCode(f));
      EXPECT_FALSE(faces.edgePresent(faces.edgeId(bc.subface(f)[0], bc.subface(f)[1])));
    }
  // A census of the live subfaces given as a plain triangle list answers the same.
  std::vector<int32_t> tris, ids;
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f))
    {
      tris.insert(tris.end(), bc.subface(f), bc.subface(f) + 3);
      ids.push_back(f);
    }
  BoundaryCensus list;
  list.take(ed.mesh, tris.data(), static_cast<int32_t>(ids.size()));
  EXPECT_FALSE(list.upToDate(ed, bc));
  for (size_t k = 0; k < ids.size(); ++k)
  {
    EXPECT_EQ(list.faceCode(static_cast<int32_t>(k)) >= 0, census.faceCode(ids[k]) >= 0);
    const int32_t a = tris[3 * k], b = tris[3 * k + 1];
    EXPECT_EQ(list.edgePresent(list.edgeId(a, b)), census.edgePresent(census.edgeId(a, b)));
  }
  return { missingEdges, missingFaces };
}

} // namespace

TEST(BoundaryCensus, MatchesStarSearchBeforeAndAfterRecovery)
{
  // Skinny strips: the Delaunay tetrahedralization misses many boundary edges and faces; recovery then
  // adds Steiner points and splits subfaces.
  SurfaceMesh s = testshapes::stripBox(20, 1.0, 8.0, 0.25);
  RecoverySetup su(s, 20);
  MeshEditor ed(su.mesh);
  const auto before = expectCensusMatchesSearch(ed, su.bc);
  EXPECT_GT(before.first, 0);
  EXPECT_GT(before.second, 0);
  ASSERT_TRUE(recoverBoundary(ed, su.bc, su.kinds, RecoveryOptions(), nullptr, nullptr).ok());
  const auto after = expectCensusMatchesSearch(ed, su.bc);
  EXPECT_EQ(after.first, 0);
  EXPECT_EQ(after.second, 0);
}

TEST(BoundaryCensus, SchoenhardtAndSpheres)
{
  {
    RecoverySetup su(testshapes::schoenhardt(30), 20);
    MeshEditor ed(su.mesh);
    EXPECT_GT(expectCensusMatchesSearch(ed, su.bc).second, 0);
  }
  SurfaceMesh s;
  const double c[3] = { 0, 0, 0 };
  testshapes::addSphere(s, c, 1.0, 3);
  testshapes::addSphere(s, c, 3.0, 2, true);
  RecoverySetup su(s, 20);
  MeshEditor ed(su.mesh);
  expectCensusMatchesSearch(ed, su.bc);
}

TEST(BoundaryCensus, StaleAfterAnEditOrAConstraintChange)
{
  RecoverySetup su(testshapes::stripBox(6, 1.0, 4.0, 0.5), 20);
  MeshEditor ed(su.mesh);
  BoundaryCensus census;
  census.take(ed, su.bc);
  EXPECT_TRUE(census.upToDate(ed, su.bc));
  // A 2-3 flip somewhere.
  bool flipped = false;
  for (int32_t t = 0; t < su.mesh.tetCapacity() && !flipped; ++t)
    for (int i = 0; i < 4 && !flipped && !su.mesh.isFree(t); ++i)
      flipped = ed.flip23(t, i, &su.bc);
  ASSERT_TRUE(flipped);
  EXPECT_FALSE(census.upToDate(ed, su.bc));
  census.take(ed, su.bc);
  EXPECT_TRUE(census.upToDate(ed, su.bc));
  su.bc.removeSubface(0);
  EXPECT_FALSE(census.upToDate(ed, su.bc));
  census.take(ed, su.bc);
  EXPECT_EQ(census.faceCode(0), -1); // dead subfaces are not looked for
}

TEST(FlatHashMap, AgreesWithUnorderedMap)
{
  // Keys from a small range: long probe runs, many erasures that must shift entries back.
  struct Identity
  {
    uint64_t operator()(uint64_t k) const { return k; }
  };
  FlatHashMap<uint64_t, int, Identity> flat;
  std::unordered_map<uint64_t, int> ref;
  std::mt19937_64 rng(7);
  for (int step = 0; step < 200000; ++step)
  {
    const uint64_t k = rng() % 3000;
    switch (rng() % 3)
    {
      case 0:
      {
        bool fresh = false;
        int& v = flat.insert(k, step, &fresh);
        auto [it, refFresh] = ref.emplace(k, step);
        ASSERT_EQ(fresh, refFresh);
        ASSERT_EQ(v, it->second);
        v = it->second = step;
        break;
      }
      case 1:
        ASSERT_EQ(flat.erase(k), ref.erase(k) == 1);
        break;
      default:
      {
        const int* v = flat.find(k);
        auto it = ref.find(k);
        ASSERT_EQ(v != nullptr, it != ref.end());
        if (v)
        {
          ASSERT_EQ(*v, it->second);
        }
      }
    }
    ASSERT_EQ(flat.size(), ref.size());
  }
  for (auto& [k, v] : ref)
    ASSERT_TRUE(flat.find(k) && *flat.find(k) == v);
}
