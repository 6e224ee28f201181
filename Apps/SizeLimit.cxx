#include "SizeLimit.h"

#include "AvailableMemory.h"
#include "CliSupport.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace volgrid
{
namespace cli
{
namespace
{
// "1.4e+10", or "more than 1e+308" when the estimate overflowed.
std::string count(double n)
{
  if (!std::isfinite(n))
    return "more than 1e+308";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2g", n);
  return buffer;
}
// "about 1.4e+10", but "more than 1e+308" as it is.
std::string about(const std::string& figure)
{
  return figure.compare(0, 9, "more than") == 0 ? figure : "about " + figure;
}
} // namespace

bool parseMaxTets(const char* command, const char* text, long long& maxTets)
{
  if (!parseLong(command, "--max-tets", text, maxTets))
    return false;
  if (maxTets <= 0)
  {
    std::fprintf(stderr, "volgrid %s: --max-tets must be a positive number of tets, got '%s'\n", command, text);
    return false;
  }
  return true;
}

std::string humanBytes(double bytes)
{
  const char* units[] = { "bytes", "KiB", "MiB", "GiB", "TiB" };
  int u = 0;
  while (u < 4 && bytes >= 1024.0)
    bytes /= 1024.0, ++u;
  if (!std::isfinite(bytes))
    return "more than 1e+308 bytes";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, bytes < 1e6 ? "%.3g %s" : "%.2g %s", bytes, units[u]);
  return buffer;
}

bool refuseIfTooLarge(const char* command, const SizeEstimate& e, long long maxTets, const std::string& cause)
{
  const double available = volgrid::availableMemoryBytes();
  const bool tooMany = maxTets > 0 ? e.tets > static_cast<double>(maxTets) : e.bytes > available;
  if (!tooMany)
    return false;
  std::string limit;
  char buffer[160];
  if (maxTets > 0)
    std::snprintf(buffer, sizeof buffer, "--max-tets %lld", maxTets);
  else
    std::snprintf(buffer, sizeof buffer, "%s of memory available (--max-tets N sets a limit in tets instead)",
                  humanBytes(available).c_str());
  limit = buffer;
  std::fprintf(stderr,
               "volgrid %s: %s would make %s tets on %s points, needing %s of memory; that exceeds the "
               "limit of %s. Refused before any work: %s.\n",
               command, cause.c_str(), about(count(e.tets)).c_str(), about(count(e.points)).c_str(),
               about(humanBytes(e.bytes)).c_str(), limit.c_str(),
               e.driver == SizeDriver::PointCount ? "use fewer points" : "choose a coarser size");
  return true;
}
} // namespace cli
} // namespace volgrid
