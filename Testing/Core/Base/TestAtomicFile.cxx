// AtomicFile: a failed write never touches the earlier file and leaves no temporary behind; a good write
// replaces it whole.
#include "AtomicFile.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
using namespace volgrid;

std::string scratchDir(const std::string& name)
{
  const std::string dir = ::testing::TempDir() + "volgrid_atomic_" + name;
  ::mkdir(dir.c_str(), 0755);
  return dir;
}

std::string contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int temporariesIn(const std::string& dir)
{
  int n = 0;
  if (DIR* d = ::opendir(dir.c_str()))
  {
    while (dirent* e = ::readdir(d))
      n += std::string(e->d_name).find(".volgrid-") != std::string::npos;
    ::closedir(d);
  }
  return n;
}
} // namespace

TEST(AtomicFile, ReplacesTheTargetWhole)
{
  const std::string dir = scratchDir("replace");
  const std::string target = dir + "/out.vtu";
  std::ofstream(target) << "old";
  std::string error;
  ASSERT_TRUE(writeFileAtomically(target, "new content", error)) << error;
  EXPECT_EQ(contents(target), "new content");
  EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(AtomicFile, MissingDirectoryNamesThePathAndTheReason)
{
  std::string error;
  const std::string target = scratchDir("missing") + "/no/such/out.vtu";
  EXPECT_FALSE(writeFileAtomically(target, "x", error));
  EXPECT_NE(error.find(target), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
  EXPECT_FALSE(probeWritable(target, error));
}

TEST(AtomicFile, RefusesDevicesAndDirectories)
{
  std::string error;
  EXPECT_FALSE(writeFileAtomically("/dev/full", "x", error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  struct stat st
  {
  };
  ASSERT_EQ(::stat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  const std::string dir = scratchDir("isdir");
  EXPECT_FALSE(writeFileAtomically(dir, "x", error));
  EXPECT_NE(error.find("directory"), std::string::npos) << error;
}

TEST(AtomicFile, FileSizeLimitKeepsTheEarlierFile)
{
  const std::string dir = scratchDir("limit");
  const std::string target = dir + "/out.vtu";
  std::ofstream(target) << "earlier";
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  void (*previous)(int) = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string error;
  const bool written = writeFileAtomically(target, std::string(100000, 'x'), error);
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  EXPECT_FALSE(written);
  EXPECT_NE(error.find("File too large"), std::string::npos) << error;
  EXPECT_EQ(contents(target), "earlier");
  EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(AtomicFile, CommitChecksTheExpectedSize)
{
  const std::string dir = scratchDir("size");
  const std::string target = dir + "/out.stl";
  std::ofstream(target) << "earlier";
  std::string error;
  {
    AtomicFile file;
    ASSERT_TRUE(file.open(target, error)) << error;
    ASSERT_TRUE(file.write("abc", 3, error)) << error;
    EXPECT_FALSE(file.commit(error, 84)); // a writer that stopped short
    EXPECT_NE(error.find("only 3 of 84 bytes"), std::string::npos) << error;
  }
  EXPECT_EQ(contents(target), "earlier");
  EXPECT_EQ(temporariesIn(dir), 0);
}
