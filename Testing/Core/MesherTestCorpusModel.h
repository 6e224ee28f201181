// A corpus model meshed the way recovery tests need it: quality stage off (recovery and Steiner removal
// only), then checked for what recovery promises: no boundary Steiner point left, boundary == input,
// volume exact (BoundaryCheck.h).
#pragma once

#include "BoundaryCheck.h"
#include "Mesher.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace volgrid
{
namespace testshapes
{

// relPath: below VOLGRID_SHARED_DATA_DIR. False when the file is not there (the caller skips).
inline bool meshCorpusModelAndCheck(const std::string& relPath, MesherResult& r)
{
  const std::string path = std::string(VOLGRID_SHARED_DATA_DIR) + "/" + relPath;
  if (!std::ifstream(path))
    return false;
  SurfaceMesh s;
  EXPECT_TRUE(readSurface(path, s).ok()) << path;
  MesherOptions options;
  options.improvement.fieldPoints = false;
  options.improvement.optimize = false;
  const Status st = meshSurface(s, options, r);
  EXPECT_TRUE(st.ok()) << relPath << ": " << st.message;
  if (!st.ok())
    return true;
  EXPECT_EQ(r.stats.steinerBoundary, 0) << relPath;
  const BoundaryCheckReport br =
    checkBoundaryConformity(r.points, r.numInputPoints, r.tets, s.triangles, r.stats.enclosedVolume);
  EXPECT_TRUE(br.ok()) << relPath << ": " << br.summary();
  return true;
}

} // namespace testshapes
} // namespace volgrid
