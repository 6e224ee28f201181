// The independent result check (Core/BoundaryCheck.h) against a plain hash-table reference (the check's
// former implementation): the same counts on a real mesh and on meshes broken on purpose (tets removed,
// repeated, turned over, with bad ids; input triangles dropped, added, repeated); the same report on any
// thread count, and the shared faces it hands to the size ratios are the mesh's.
#include "BoundaryCheck.h"
#include "Enclosures.h"
#include "Mesh/RandomDelaunay.h"
#include "Mesher.h"
#include "Predicates.h"
#include "VertexKeys.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

using namespace volgrid;

namespace
{

struct Counts
{
  int64_t inverted = 0, badIds = 0, overShared = 0, sameOrientation = 0, boundary = 0, notInput = 0, missing = 0,
          interior = 0, added = 0;
  bool operator==(const Counts& o) const
  {
    return inverted == o.inverted && badIds == o.badIds && overShared == o.overShared &&
      sameOrientation == o.sameOrientation && boundary == o.boundary && notInput == o.notInput &&
      missing == o.missing && interior == o.interior && added == o.added;
  }
};

bool sameCyclic(const int32_t* f, const int32_t* s)
{
  for (int r = 0; r < 3; ++r)
    if (f[0] == s[r] && f[1] == s[(r + 1) % 3] && f[2] == s[(r + 2) % 3])
      return true;
  return false;
}

Counts reference(const std::vector<double>& points, int32_t numInputPoints, const std::vector<int32_t>& tets,
                 const std::vector<int32_t>& triangles)
{
  Counts c;
  const int64_t np = static_cast<int64_t>(points.size() / 3), nt = static_cast<int64_t>(tets.size() / 4);
  struct Use
  {
    int32_t v[3];
    int count;
  };
  std::unordered_map<TriKey, Use, TriKeyHash> faces;
  for (int64_t t = 0; t < nt; ++t)
  {
    const int32_t* v = tets.data() + 4 * t;
    bool bad = false;
    for (int i = 0; i < 4; ++i)
    {
      bad = bad || v[i] < 0 || v[i] >= np;
      for (int j = i + 1; j < 4; ++j)
        bad = bad || v[i] == v[j];
    }
    if (bad)
    {
      ++c.badIds;
      continue;
    }
    c.inverted += predicates::orient3d(&points[3 * v[0]], &points[3 * v[1]], &points[3 * v[2]], &points[3 * v[3]]) <= 0;
    for (int i = 0; i < 4; ++i)
    {
      const int* fv = TetMesh::kFaceVertex[i];
      const int32_t f[3] = { v[fv[0]], v[fv[1]], v[fv[2]] };
      auto it = faces.find(TriKey(f[0], f[1], f[2]));
      if (it == faces.end())
        faces.emplace(TriKey(f[0], f[1], f[2]), Use{ { f[0], f[1], f[2] }, 1 });
      else
      {
        ++it->second.count;
        c.sameOrientation += it->second.count == 2 && sameCyclic(f, it->second.v);
        c.overShared += it->second.count == 3;
      }
    }
  }
  std::unordered_map<TriKey, int32_t, TriKeyHash> input;
  for (size_t t = 0; t < triangles.size() / 3; ++t)
    input.emplace(TriKey(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]), static_cast<int32_t>(t));
  std::vector<uint8_t> onBoundary(static_cast<size_t>(np), 0);
  for (auto& [key, use] : faces)
    if (use.count == 1)
    {
      ++c.boundary;
      c.notInput += input.count(key) == 0;
      for (int k = 0; k < 3; ++k)
        onBoundary[key.v[k]] = 1;
    }
  for (int64_t v = numInputPoints; v < np; ++v)
    c.added += onBoundary[v];
  for (auto& [key, t] : input)
  {
    auto it = faces.find(key);
    c.missing += it == faces.end();
    c.interior += it != faces.end() && it->second.count == 2;
  }
  return c;
}

Counts counts(const BoundaryCheckReport& r)
{
  Counts c;
  c.inverted = r.invertedTets;
  c.badIds = r.badIds;
  c.overShared = r.overSharedFaces;
  c.sameOrientation = r.sameOrientationFaces;
  c.boundary = r.boundaryFaces;
  c.notInput = r.boundaryFacesNotInput;
  c.missing = r.inputTrianglesNotFaces;
  c.interior = r.inputTrianglesInterior;
  c.added = r.boundaryPointsAdded;
  return c;
}
} // namespace

TEST(BoundaryCheck, SameCountsAsAHashTableOnGoodAndBrokenMeshes)
{
  SurfaceMesh s;
  EnclosureOptions eo;
  eo.shape = EnclosureShape::Sphere;
  eo.targetEdgeLength = 0.3;
  ASSERT_TRUE(makeEnclosure(eo, s).ok());
  MesherResult m;
  ASSERT_TRUE(meshSurface(s, MesherOptions(), m).ok());
  const BoundaryCheckReport good =
    checkBoundaryConformity(m.points, m.numInputPoints, m.tets, s.triangles, m.stats.enclosedVolume);
  EXPECT_TRUE(good.ok()) << good.summary();
  EXPECT_TRUE(good.firstProblems.empty());
  EXPECT_TRUE(counts(good) == reference(m.points, m.numInputPoints, m.tets, s.triangles));
  std::mt19937 rng(3);
  const int32_t nt = static_cast<int32_t>(m.tets.size() / 4);
  for (int trial = 0; trial < 40; ++trial)
  {
    std::vector<int32_t> tets = m.tets, tris = s.triangles;
    std::uniform_int_distribution<int32_t> anyTet(0, nt - 1);
    for (int k = 0; k < 1 + trial % 4; ++k)
    {
      const int32_t t = anyTet(rng);
      switch ((trial + k) % 6)
      {
        case 0: // removed
          tets.erase(tets.begin() + 4 * t, tets.begin() + 4 * t + 4);
          break;
        case 1: // repeated, sometimes turned over
          tets.insert(tets.end(), m.tets.begin() + 4 * t, m.tets.begin() + 4 * t + 4);
          if (k % 2)
            std::swap(tets[tets.size() - 1], tets[tets.size() - 2]);
          break;
        case 2: // turned over
          std::swap(tets[4 * t], tets[4 * t + 1]);
          break;
        case 3: // bad ids
          tets[4 * t + 2] = (k % 2) ? -1 : tets[4 * t];
          break;
        case 4: // an input triangle dropped, one repeated
          tris.erase(tris.begin(), tris.begin() + 3);
          tris.insert(tris.end(), tris.begin(), tris.begin() + 3);
          break;
        default: // an input triangle that is no face
          tris.insert(tris.end(), { m.tets[4 * t], m.tets[4 * t + 1], 0 });
          break;
      }
    }
    const BoundaryCheckReport r =
      checkBoundaryConformity(m.points, m.numInputPoints, tets, tris, m.stats.enclosedVolume);
    EXPECT_TRUE(counts(r) == reference(m.points, m.numInputPoints, tets, tris))
      << "trial " << trial << ": " << r.summary();
    EXPECT_FALSE(r.ok()) << "trial " << trial;
    EXPECT_FALSE(r.firstProblems.empty()) << "trial " << trial;
  }
}

TEST(BoundaryCheck, SameReportOnAnyThreadCountAndTheSharedFacesOfTheMesh)
{
  // 40,000 random points: about 260,000 tets, four blocks of the check's tet loop and two ranges of its face
  // matching on two threads; tets turned over, repeated and removed, so that the problems listed in tet order
  // come from several blocks and ranges.
  TetMesh mesh;
  randomDelaunay(mesh, 40000, 11);
  std::vector<int32_t> tets = flatTets(mesh);
  const int64_t nt = static_cast<int64_t>(tets.size() / 4);
  ASSERT_GT(nt, 2 * 65536);
  int64_t interiorFaces = 0;
  mesh.forEachTet(
    [&](int32_t u)
    {
      for (int i = 0; i < 4; ++i)
        interiorFaces += mesh.neighbor(u, i) > u;
    });
  const std::vector<int32_t> noTriangles;
  std::vector<std::pair<int32_t, int32_t>> shared;
  const BoundaryCheckReport one = checkBoundaryConformity(mesh.points, 0, tets, noTriangles, 1.0, &shared, 1);
  EXPECT_TRUE(one.meshValid()) << one.summary();
  EXPECT_EQ(static_cast<int64_t>(shared.size()), interiorFaces);
  for (const auto& f : shared)
  {
    ASSERT_TRUE(f.first >= 0 && f.first < nt && f.second >= 0 && f.second < nt && f.first != f.second);
    int common = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        common += tets[4 * f.first + i] == tets[4 * f.second + j];
    ASSERT_EQ(common, 3) << f.first << " " << f.second;
  }
  for (int64_t t : { int64_t(5), int64_t(70000), nt - 3 })
    std::swap(tets[4 * t], tets[4 * t + 1]);
  tets.insert(tets.end(), tets.begin() + 4 * 100, tets.begin() + 4 * 101); // repeated: over-shared faces
  tets.erase(tets.begin() + 4 * 90000, tets.begin() + 4 * 90001);          // removed: a hole
  const BoundaryCheckReport broken = checkBoundaryConformity(mesh.points, 0, tets, noTriangles, 1.0, nullptr, 1);
  EXPECT_EQ(broken.invertedTets, 3);
  EXPECT_GT(broken.overSharedFaces, 0);
  EXPECT_GT(broken.boundaryFacesNotInput, one.boundaryFacesNotInput);
  for (int threads : { 2, 8 })
  {
    const BoundaryCheckReport r = checkBoundaryConformity(mesh.points, 0, tets, noTriangles, 1.0, nullptr, threads);
    EXPECT_TRUE(counts(r) == counts(broken)) << threads;
    EXPECT_EQ(r.tetVolume, broken.tetVolume) << threads; // the same bits: block sums in block order
    EXPECT_EQ(r.firstProblems, broken.firstProblems) << threads;
  }
}
