#include "bench_common.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace volgrid_bench
{
namespace
{

// splitmix64: tiny, fully specified, so the points do not depend on the standard library's distributions.
class Rng
{
public:
  explicit Rng(uint64_t seed)
    : state_(seed)
  {
  }
  uint64_t next()
  {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; } // [0, 1)

private:
  uint64_t state_;
};

void sphere(Rng& rng, double radius, int64_t count, std::vector<double>& xyz)
{
  const double twoPi = 6.283185307179586476925286766559;
  for (int64_t i = 0; i < count; ++i)
  {
    const double z = 2.0 * rng.uniform() - 1.0;
    const double phi = twoPi * rng.uniform();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    xyz.push_back(radius * r * std::cos(phi));
    xyz.push_back(radius * r * std::sin(phi));
    xyz.push_back(radius * z);
  }
}

} // namespace

bool generatePoints(const std::string& input, int64_t n, uint64_t seed, std::vector<double>& xyz, std::string& error)
{
  xyz.clear();
  if (n < 4)
  {
    error = "n must be at least 4";
    return false;
  }
  Rng rng(seed);
  if (input == "random")
  {
    xyz.resize(3 * static_cast<size_t>(n));
    for (double& c : xyz)
      c = rng.uniform();
    return true;
  }
  if (input == "grid" || input == "jittered-grid")
  {
    int64_t s = static_cast<int64_t>(std::llround(std::cbrt(static_cast<double>(n))));
    if (s < 2 || s * s * s != n)
    {
      error = "grid inputs need n = s^3 with s >= 2 (e.g. 1000000 for 100^3), got " + std::to_string(n);
      return false;
    }
    // Every grid cell is an axis-aligned box, whose 8 corners are exactly cospherical in floating point.
    const double h = 1.0 / static_cast<double>(s - 1);
    const double jitter = input == "jittered-grid" ? 1e-6 * h : 0.0;
    xyz.reserve(3 * static_cast<size_t>(n));
    for (int64_t k = 0; k < s; ++k)
      for (int64_t j = 0; j < s; ++j)
        for (int64_t i = 0; i < s; ++i)
        {
          const int64_t ijk[3] = { i, j, k };
          for (int64_t c : ijk)
          {
            double x = static_cast<double>(c) / static_cast<double>(s - 1);
            if (jitter != 0.0)
              x += (2.0 * rng.uniform() - 1.0) * jitter;
            xyz.push_back(x);
          }
        }
    return true;
  }
  if (input == "spheres")
  {
    xyz.reserve(3 * static_cast<size_t>(n));
    sphere(rng, 1.0, n / 2, xyz);
    sphere(rng, 10.0, n - n / 2, xyz);
    return true;
  }
  error = "unknown input '" + input + "' (random, grid, jittered-grid, spheres)";
  return false;
}

long readStatusKb(const char* field)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const size_t len = std::strlen(field);
  while (std::getline(in, line))
  {
    if (line.compare(0, len, field) == 0 && line.size() > len && line[len] == ':')
      return std::strtol(line.c_str() + len + 1, nullptr, 10);
  }
  return -1;
}

static int64_t nowNs()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
    .count();
}

void Meter::start()
{
  baselineKb_ = readStatusKb("VmRSS");
  // Reset the peak (VmHWM) to the current RSS so that the peak covers the triangulation only
  // (Linux >= 4.0; when refused, VmHWM still includes input generation, which is below the baseline's
  // order anyway).
  if (FILE* f = std::fopen("/proc/self/clear_refs", "w"))
  {
    peakReset_ = std::fputs("5", f) >= 0;
    peakReset_ = (std::fclose(f) == 0) && peakReset_;
  }
  t0_ = nowNs();
}

void Meter::stop()
{
  seconds_ = static_cast<double>(nowNs() - t0_) * 1e-9;
  peakKb_ = readStatusKb("VmHWM");
  if (peakKb_ < baselineKb_)
    peakKb_ = baselineKb_;
}

} // namespace volgrid_bench
