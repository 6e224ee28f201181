#include "OutputPaths.h"

#include "CliSupport.h"

#include "AtomicFile.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include <sys/stat.h>

namespace volgrid
{
namespace cli
{
namespace
{
std::string list(const std::vector<std::string>& extensions)
{
  std::string s;
  for (size_t i = 0; i < extensions.size(); ++i)
    s += (i == 0 ? "." : i + 1 == extensions.size() ? " or ." : ", .") + extensions[i];
  return s;
}
} // namespace

bool sameFile(const std::string& a, const std::string& b)
{
  struct stat sa
  {
  }, sb{};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int checkOutputPath(const char* command, const char* role, const std::string& out,
                    const std::vector<std::string>& extensions, const std::vector<std::string>& inputs)
{
  const std::string ext = lowerExtension(out);
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
  {
    std::fprintf(stderr, "volgrid %s: %s '%s' must end in %s (nothing was done)\n", command, role, out.c_str(),
                 list(extensions).c_str());
    return 2;
  }
  for (const std::string& in : inputs)
  {
    if (!in.empty() && (in == out || sameFile(in, out)))
    {
      std::fprintf(stderr, "volgrid %s: %s '%s' is the input file '%s'; refusing to overwrite it (nothing was done)\n",
                   command, role, out.c_str(), in.c_str());
      return 2;
    }
  }
  std::string error;
  if (!probeWritable(out, error))
  {
    std::fprintf(stderr, "volgrid %s: %s (nothing was done)\n", command, error.c_str());
    return 1;
  }
  return 0;
}
} // namespace cli
} // namespace volgrid
