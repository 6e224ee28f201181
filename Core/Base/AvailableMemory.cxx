#include "AvailableMemory.h"

#include <sys/resource.h>

#include <algorithm>
#include <exception>
#include <fstream>
#include <limits>
#include <string>

namespace volgrid
{
namespace
{
constexpr double kUnlimited = std::numeric_limits<double>::infinity();

double memAvailable()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:")
      return kib * 1024.0;
  return kUnlimited;
}

double readNumber(const char* path)
{
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max")
    return kUnlimited;
  try
  {
    return std::stod(text);
  }
  catch (const std::exception&)
  {
    return kUnlimited;
  }
}

double cgroupHeadroom()
{
  const double v2 = readNumber("/sys/fs/cgroup/memory.max");
  if (v2 < kUnlimited)
    return std::max(0.0, v2 - readNumber("/sys/fs/cgroup/memory.current"));
  const double v1 = readNumber("/sys/fs/cgroup/memory/memory.limit_in_bytes");
  if (v1 < 1e18)
    return std::max(0.0, v1 - readNumber("/sys/fs/cgroup/memory/memory.usage_in_bytes"));
  return kUnlimited;
}

double rlimitBytes(int resource)
{
  rlimit r{};
  if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY)
    return kUnlimited;
  return static_cast<double>(r.rlim_cur);
}
} // namespace

double availableMemoryBytes()
{
  return std::min({ memAvailable(), cgroupHeadroom(), rlimitBytes(RLIMIT_AS), rlimitBytes(RLIMIT_DATA) });
}

} // namespace volgrid
