// Shared pieces of the Delaunay benchmark: deterministic point generators, the memory/time meter and the
// per-engine entry points. Each engine lives in its own .cxx (bench_<engine>.cxx) so that TetGen's REAL
// macro and CGAL's heavy templates stay isolated.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid_bench
{

// ---- inputs ----
// Generates `n` points (xyz interleaved) for `input`, the same points for every engine:
//   random         uniform in the unit cube
//   grid           the s^3 regular grid in the unit cube, s = cbrt(n) (n must be a cube, e.g. 1000000)
//   jittered-grid  the same grid, every coordinate moved by uniform [-1e-6, 1e-6] * spacing
//   spheres        n/2 points uniform on the sphere of radius 1 and n - n/2 on radius 10 (same centre)
// Returns false and sets `error` for an unknown input or a bad n.
bool generatePoints(const std::string& input, int64_t n, uint64_t seed, std::vector<double>& xyz, std::string& error);

// ---- memory and time ----
// Linux /proc/self/status fields in kB (-1 when unavailable).
long readStatusKb(const char* field);

// The engine calls start() right before the triangulation call and stop() right after it; everything
// the engine prepares before start() (its own copy of the input) is part of the baseline.
class Meter
{
public:
  void start();
  void stop();
  double seconds() const { return seconds_; }
  double baselineMb() const { return baselineKb_ / 1024.0; }
  double peakMb() const { return peakKb_ / 1024.0; }
  double peakBeyondBaselineBytes() const { return (peakKb_ - baselineKb_) * 1024.0; }
  bool peakWasReset() const { return peakReset_; }

private:
  long baselineKb_ = 0;
  long peakKb_ = 0;
  bool peakReset_ = false;
  double seconds_ = 0.0;
  int64_t t0_ = 0;
};

// ---- engines ----
struct EngineResult
{
  bool ok = false;
  int64_t tets = 0;    // finite tetrahedra
  int64_t points = -1; // vertices the engine reports using (when it says), else -1
  int threads = 1;
  std::string error;
  std::string note; // e.g. engine-specific details
};

// VolGrid kernel settings (the other engines use their defaults).
struct VolGridSettings
{
  std::string location = "walk"; // walk | bucket-grid (volgrid::PointLocation)
  bool spatialSort = true;       // false: insert in input order
};

// Each returns false (with result.error) when the engine is not compiled in or fails.
bool runVolGrid(const std::vector<double>& xyz, const VolGridSettings& settings, Meter& meter, EngineResult& result);
bool runTetGen(const std::vector<double>& xyz, Meter& meter, EngineResult& result);
bool runCGAL(const std::vector<double>& xyz, Meter& meter, EngineResult& result);
bool runVtkDelaunay3D(const std::vector<double>& xyz, Meter& meter, EngineResult& result);

} // namespace volgrid_bench
