// Tests that read the shared corpus (../shared/data/real, absent on a user's clone) skip with a message
// naming the missing file instead of failing.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace volgrid_testing
{
// The absolute path of a corpus file, `relPath` below VOLGRID_SHARED_DATA_DIR ("a/b.off" or "/a/b.off").
inline std::string corpusPath(const std::string& relPath)
{
  const std::string dir = VOLGRID_SHARED_DATA_DIR;
  return relPath.empty() || relPath[0] == '/' ? dir + relPath : dir + "/" + relPath;
}

inline bool corpusFilePresent(const std::string& path)
{
  return static_cast<bool>(std::ifstream(path, std::ios::binary));
}
} // namespace volgrid_testing

// In a test body: skips the test when the corpus file `relPath` is missing.
#define VOLGRID_SKIP_WITHOUT_CORPUS_FILE(relPath)                                                                      \
  do                                                                                                                   \
  {                                                                                                                    \
    const std::string volgridCorpusFile_ = volgrid_testing::corpusPath(relPath);                                       \
    if (!volgrid_testing::corpusFilePresent(volgridCorpusFile_))                                                       \
      GTEST_SKIP() << "corpus file missing: " << volgridCorpusFile_ << " (no ../shared/data/real beside the clone)";   \
  } while (false)
