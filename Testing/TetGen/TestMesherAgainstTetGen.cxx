// VolGrid's boundary-conforming mesher against TetGen -pY on the clean closed models of the shared
// corpus, alone and inside a sphere enclosure (both engines recovery only, every region kept for the
// enclosed case): wherever both succeed, both outputs are checked the same way (exact orientation,
// adjacency, boundary faces == input triangles, no boundary point added, volume == enclosed volume), and
// the tet counts and times are printed side by side. Where only one succeeds it is listed; VolGrid must
// mesh every case TetGen meshes.
#include "TetGenRunner.h"

#include "../Common/CorpusList.h"
#include "../Core/MesherTestObj.h"

#include "BoundaryCheck.h"
#include "Enclosures.h"
#include "Mesher.h"
#include "SurfaceMesh.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

namespace
{
// Guards the test time (2 cores) against a much larger model added to the corpus later; every current
// clean model is below it (the largest, igea.ply, has 268,686 triangles).
constexpr int32_t kMaxTriangles = 300000;
} // namespace

TEST(MesherVsTetGen, CleanCorpusSideBySide)
{
  const std::string dataDir = VOLGRID_SHARED_DATA_DIR;
  const std::vector<std::string> files = volgrid_testing::cleanClosedCorpusFiles(dataDir);
  if (files.empty())
    GTEST_SKIP() << "no corpus at " << dataDir;
  int compared = 0, onlyVolGrid = 0, onlyTetGen = 0, neither = 0, skipped = 0;
  std::vector<std::string> tetgenFailures;
  std::printf("%-56s %10s %10s %9s %9s %s\n", "model", "VolGrid", "TetGen-pY", "VG s", "TG s", "notes");
  for (const std::string& file : files)
  {
    volgrid::SurfaceMesh model;
    const std::string path = dataDir + "/" + file;
    bool read = false;
    if (volgrid_testing::endsWith(file, ".obj"))
      read = volgrid::testshapes::readObj(path, model);
    else
      read = volgrid::readSurface(path, model).ok();
    if (!read || model.numberOfTriangles() > kMaxTriangles)
    {
      ++skipped;
      continue;
    }
    volgrid::mergeCoincidentPoints(model);
    for (int variant = 0; variant < 2; ++variant)
    {
      // The model alone, then inside a sphere enclosure (the aircraft-in-sphere case). TetGen -pY fills
      // every region, so VolGrid keeps all regions there too (the body's inside as well).
      volgrid::SurfaceMesh surface = model;
      std::string name = file;
      // Recovery and exterior removal only, as -pY (no refinement, no quality stage).
      volgrid::MesherOptions options;
      options.improvement.fieldPoints = false;
      options.improvement.optimize = false;
      if (variant == 1)
      {
        volgrid::EnclosureOptions eo =
          volgrid::enclosureAround(volgrid::boundingBox(surface, true), volgrid::EnclosureShape::Sphere, 3.0);
        volgrid::SurfaceMesh sphere;
        ASSERT_TRUE(volgrid::makeEnclosure(eo, sphere).ok()) << file;
        surface.append(sphere);
        name += " +sphere";
        options.regionRule = volgrid::RegionRule::KeepAll;
      }
      volgrid::MesherResult ours;
      const auto start = std::chrono::steady_clock::now();
      const volgrid::Status status = volgrid::meshSurface(surface, options, ours);
      const double ourSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const volgrid_tetgen::TetGenMesh theirs = volgrid_tetgen::meshSurface(surface.points, surface.triangles, "pYQ");

      std::string notes;
      if (status.ok() && theirs.ok)
      {
        ++compared;
        const volgrid::BoundaryCheckReport a = volgrid::checkBoundaryConformity(
          ours.points, ours.numInputPoints, ours.tets, surface.triangles, ours.stats.enclosedVolume);
        const volgrid::BoundaryCheckReport b = volgrid::checkBoundaryConformity(
          theirs.points, surface.numberOfPoints(), theirs.tets, surface.triangles, ours.stats.enclosedVolume);
        EXPECT_TRUE(a.ok()) << name << " VolGrid: " << a.summary();
        // Both meshes fill the same domain exactly: their volumes agree to rounding.
        EXPECT_NEAR(a.tetVolume, b.tetVolume, 1e-9 * std::abs(ours.stats.enclosedVolume)) << name;
        if (!b.ok())
          notes = "TetGen output: " + b.summary();
      }
      else if (status.ok())
      {
        ++onlyVolGrid;
        tetgenFailures.push_back(name + " (" + theirs.error + ")");
        notes = "TetGen failed: " + theirs.error;
      }
      else if (theirs.ok)
      {
        ++onlyTetGen;
        notes = "VolGrid failed: " + status.message.substr(0, 80);
      }
      else
      {
        ++neither;
        notes = "both failed";
      }
      std::printf("%-56s %10lld %10lld %9.3f %9.3f %s\n", name.c_str(),
                  static_cast<long long>(status.ok() ? ours.stats.tets : -1),
                  static_cast<long long>(theirs.ok ? static_cast<long long>(theirs.tets.size() / 4) : -1), ourSeconds,
                  theirs.seconds, notes.c_str());
    }
  }
  std::printf("compared %d, only VolGrid meshed %d, only TetGen meshed %d, neither %d, files skipped %d "
              "(> %d triangles)\n",
              compared, onlyVolGrid, onlyTetGen, neither, skipped, kMaxTriangles);
  for (const std::string& f : tetgenFailures)
    std::printf("TetGen -pY failed on %s\n", f.c_str());
  EXPECT_GT(compared, 0);
  // What TetGen meshes, VolGrid meshes too.
  EXPECT_EQ(onlyTetGen, 0);
  EXPECT_EQ(neither, 0);
}
