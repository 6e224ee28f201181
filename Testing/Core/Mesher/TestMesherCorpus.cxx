// Corpus test: every clean closed model of the shared corpus (SOURCES.md: watertight YES, no defect
// other than polygon faces or inconsistent orientation), alone and inside a generated sphere enclosure.
// For each case that meshes: exact validity, boundary == input triangles, volume == enclosed volume
// (relative error < 1e-9), no Steiner point on the boundary. A case that does not mesh must fail with
// RecoveryFailed (reported, never a wrong mesh, never a crash). The coverage is printed and must not
// fall below the recorded baseline.
//
// Every clean model is run, the largest (igea.ply, 268,686 triangles) in about 2 s; kMaxTriangles only
// guards the runtime against a much larger file added to the corpus later (it would be listed as skipped).
#include "BoundaryCheck.h"
#include "Enclosures.h"
#include "Mesher.h"
#include "MesherTestObj.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace volgrid;

namespace
{

constexpr int64_t kMaxTriangles = 300000;
// Cases (models and enclosure variants) meshed and checked by this implementation when it was written.
constexpr int kBaselineChecked =
  176; // planar flips, ring chords, retry with presplit segments, crossing-face edge removal, slab facets, piecewise
       // facets, Steiner points past the flip budget, vertex cones, no edge along split segments, star flips, cavity
       // carving, segment cones, no size limit below 300k triangles

std::string dataDir()
{
  return VOLGRID_SHARED_DATA_DIR;
}

// Rows of SOURCES.md marked watertight YES whose defects are only polygon faces / orientation.
std::vector<std::string> cleanClosedFiles()
{
  std::vector<std::string> out;
  std::ifstream in(dataDir() + "/SOURCES.md");
  std::string line;
  while (std::getline(in, line))
  {
    if (line.size() < 2 || line[0] != '|')
      continue;
    std::vector<std::string> cols;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, '|'))
    {
      const size_t a = c.find_first_not_of(' '), b = c.find_last_not_of(' ');
      cols.push_back(a == std::string::npos ? "" : c.substr(a, b - a + 1));
    }
    if (cols.size() < 10 || cols[6] != "YES")
      continue;
    const std::string& defects = cols[9];
    std::string rest = defects;
    bool clean = defects == "none found";
    if (!clean)
    {
      clean = true;
      std::stringstream ds(defects);
      std::string item;
      while (std::getline(ds, item, ';'))
        if (item.find("non-triangle faces") == std::string::npos &&
            item.find("inconsistently oriented edges") == std::string::npos)
          clean = false;
    }
    if (clean)
      out.push_back(cols[1]);
  }
  return out;
}

bool endsWith(const std::string& s, const std::string& e)
{
  return s.size() >= e.size() && s.compare(s.size() - e.size(), e.size(), e) == 0;
}

struct CaseResult
{
  bool meshed = false;
  bool checked = false;
  std::string line;
};

// This test is about boundary recovery, exterior removal and Steiner point removal: the grid control and
// quality stage (MesherOptions::improvement, when present) is switched off to keep the corpus fast.
template<class T>
auto noImprovement(T& o, int) -> decltype(o.improvement.fieldPoints = false, o.improvement.optimize = false, void())
{
  o.improvement.fieldPoints = false;
  o.improvement.optimize = false;
}
template<class T>
void noImprovement(T&, long)
{
}

CaseResult runCase(const std::string& name, const SurfaceMesh& s)
{
  CaseResult cr;
  MesherResult r;
  MesherOptions options;
  noImprovement(options, 0);
  const auto t0 = std::chrono::steady_clock::now();
  Status st = meshSurface(s, options, r);
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  char buf[512];
  if (!st.ok())
  {
    EXPECT_EQ(st.kind, ErrorKind::RecoveryFailed) << name << ": " << st.message;
    std::snprintf(buf, sizeof buf, "%-52s FAILED %6.2fs  %s", name.c_str(), sec, st.message.substr(0, 110).c_str());
    cr.line = buf;
    return cr;
  }
  cr.meshed = true;
  BoundaryCheckReport br =
    checkBoundaryConformity(r.points, r.numInputPoints, r.tets, s.triangles, r.stats.enclosedVolume);
  EXPECT_TRUE(br.ok()) << name << ": " << br.summary();
  EXPECT_EQ(r.stats.steinerBoundary, 0) << name;
  cr.checked = br.ok() && r.stats.steinerBoundary == 0;
  std::snprintf(buf, sizeof buf,
                "%-52s %s tris %7lld tets %8lld missE %5lld missF %4lld steiner(int) %5lld volErr %.1e %6.2fs",
                name.c_str(), cr.checked ? "ok    " : "BAD   ", (long long)r.stats.inputTriangles,
                (long long)r.stats.tets, (long long)r.stats.missingEdges, (long long)r.stats.missingFacets,
                (long long)r.stats.steinerInterior, br.relativeVolumeError, sec);
  cr.line = buf;
  return cr;
}

} // namespace

TEST(MesherCorpus, CleanClosedModels)
{
  const std::vector<std::string> files = cleanClosedFiles();
  if (files.empty())
    GTEST_SKIP() << "no corpus at " << dataDir();
  int total = 0, meshed = 0, checked = 0, skipped = 0;
  struct Case
  {
    std::string name;
    SurfaceMesh surface;
    CaseResult result;
  };
  std::vector<Case> cases;
  std::vector<std::string> lines;
  // VOLGRID_CORPUS_ONLY=substring runs the matching files only (diagnosis; no baseline check then).
  const char* only = std::getenv("VOLGRID_CORPUS_ONLY");
  for (const std::string& f : files)
  {
    if (only && f.find(only) == std::string::npos)
      continue;
    const std::string path = dataDir() + "/" + f;
    SurfaceMesh s;
    bool ok = endsWith(f, ".obj") ? testshapes::readObj(path, s) : readSurface(path, s).ok();
    if (!ok)
    {
      ADD_FAILURE() << f << ": cannot be read";
      continue;
    }
    if (s.numberOfTriangles() > kMaxTriangles)
    {
      lines.push_back(f + ": skipped (" + std::to_string(s.numberOfTriangles()) + " triangles, runtime)");
      ++skipped;
      continue;
    }
    for (int variant = 0; variant < 2; ++variant)
    {
      SurfaceMesh c = s;
      std::string name = f;
      if (variant == 1)
      {
        // The aircraft-in-sphere situation: the model inside a sphere enclosure.
        mergeCoincidentPoints(c);
        EnclosureOptions eo = enclosureAround(boundingBox(c, true), EnclosureShape::Sphere, 3.0);
        SurfaceMesh e;
        if (!makeEnclosure(eo, e).ok())
          continue;
        c.append(e);
        name += " +sphere";
      }
      cases.push_back({ name, std::move(c), CaseResult() });
    }
  }
  // Two workers (the cases are independent; the mesher keeps no global state). Largest cases first so
  // that the two workers finish together.
  std::vector<size_t> order(cases.size());
  for (size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b)
                   { return cases[a].surface.numberOfTriangles() > cases[b].surface.numberOfTriangles(); });
  std::atomic<size_t> next{ 0 };
  auto worker = [&]()
  {
    for (size_t k = next++; k < order.size(); k = next++)
    {
      Case& c = cases[order[k]];
      c.result = runCase(c.name, c.surface);
      c.surface = SurfaceMesh();
    }
  };
  std::thread helper(worker);
  worker();
  helper.join();
  std::vector<std::string> failedNames;
  for (const Case& c : cases)
  {
    ++total;
    meshed += c.result.meshed;
    checked += c.result.checked;
    lines.push_back(c.result.line);
    if (!c.result.checked)
      failedNames.push_back(c.name);
  }
  for (auto& l : lines)
    std::printf("%s\n", l.c_str());
  std::printf("corpus: %d cases, %d meshed, %d checked (boundary == input, volume exact), %d files skipped\n", total,
              meshed, checked, skipped);
  std::printf("not meshed (%zu):", failedNames.size());
  for (auto& n : failedNames)
    std::printf(" [%s]", n.c_str());
  std::printf("\n");
  EXPECT_EQ(meshed, checked);
  // Baseline of this implementation (see the commit message); raise it as recovery improves.
  if (!only)
  {
    EXPECT_GE(checked, kBaselineChecked);
  }
}

// Steiner removal where a segment Steiner point was rounded to just outside a planar part of a CAD
// model: its star is a few flat tets between two triangulations of the plane, no point sees the cavity,
// and the cone from one of the cavity's vertices fills it (spool.off kept 4 boundary Steiner points
// without it).
TEST(MesherCorpus, FlatSteinerStarsRemovedByVertexCone)
{
  const std::string path = dataDir() + "/tetgen-tests/cgal/spool.off";
  SurfaceMesh s;
  if (!readSurface(path, s).ok())
    GTEST_SKIP() << "no corpus file " << path;
  MesherOptions options;
  noImprovement(options, 0);
  MesherResult r;
  Status st = meshSurface(s, options, r);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(r.stats.steinerBoundary, 0);
  BoundaryCheckReport br =
    checkBoundaryConformity(r.points, r.numInputPoints, r.tets, s.triangles, r.stats.enclosedVolume);
  EXPECT_TRUE(br.ok()) << br.summary();
}
