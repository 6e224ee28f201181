// make bench: the boundary-conforming pipeline's stages on one surface, for comparison with TetGen -pY
// (scripts/bench_mesher.sh runs `tetgen -pYV` on the same surface and reads its stage timings).
// Grid control and optimisation are off: this measures Delaunay, recovery, exterior removal and
// boundary Steiner point removal, the stages TetGen -pY performs.
//
// usage: volgrid_bench_mesher (--input SURFACE | --sphere-in-sphere) [--write-poly PATH]
// Prints one JSON line.
#include "Enclosures.h"
#include "Mesher.h"
#include "SurfaceMesh.h"
#include "SurfaceReader.h"

#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

namespace
{
// The far-field case: an icosphere body r=1 with 20,480 triangles inside an icosphere r=10.
volgrid::Status sphereInSphere(volgrid::SurfaceMesh& surface)
{
  volgrid::EnclosureOptions body;
  body.shape = volgrid::EnclosureShape::Sphere;
  body.dimensions[0] = 1.0;
  body.targetEdgeLength = 0.0329; // frequency-32 icosphere: 20 x 32^2 = 20,480 triangles
  volgrid::EnclosureOptions farField = body;
  farField.dimensions[0] = 10.0;
  farField.targetEdgeLength = 1.2;
  volgrid::SurfaceMesh far;
  volgrid::Status s = volgrid::makeEnclosure(body, surface);
  if (s.ok())
    s = volgrid::makeEnclosure(farField, far);
  if (s.ok())
    surface.append(far);
  return s;
}

// The surface as a TetGen .poly file; `hole` (may be null) marks a region TetGen must leave empty, as
// VolGrid's even-odd rule does for a nested body.
bool writePoly(const std::string& path, const volgrid::SurfaceMesh& s, const double* hole)
{
  std::ofstream out(path);
  out.precision(17);
  out << s.numberOfPoints() << " 3 0 0\n";
  for (int32_t i = 0; i < s.numberOfPoints(); ++i)
    out << i << " " << s.point(i)[0] << " " << s.point(i)[1] << " " << s.point(i)[2] << "\n";
  out << s.numberOfTriangles() << " 0\n";
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
    out << "1\n3 " << s.triangle(t)[0] << " " << s.triangle(t)[1] << " " << s.triangle(t)[2] << "\n";
  if (hole)
    out << "1\n0 " << hole[0] << " " << hole[1] << " " << hole[2] << "\n";
  else
    out << "0\n";
  return static_cast<bool>(out);
}
} // namespace

int main(int argc, char** argv)
{
  std::string input, offPath;
  bool spheres = false;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--input") && i + 1 < argc)
      input = argv[++i];
    else if (!std::strcmp(argv[i], "--sphere-in-sphere"))
      spheres = true;
    else if (!std::strcmp(argv[i], "--write-poly") && i + 1 < argc)
      offPath = argv[++i];
    else
    {
      std::fprintf(stderr, "usage: %s (--input SURFACE | --sphere-in-sphere) [--write-poly PATH]\n", argv[0]);
      return 2;
    }
  }
  volgrid::SurfaceMesh surface;
  const volgrid::Status read = spheres ? sphereInSphere(surface) : volgrid::readSurface(input, surface);
  if (!read.ok() || (input.empty() && !spheres))
  {
    std::fprintf(stderr, "bench_mesher: %s\n", read.ok() ? "no input" : read.message.c_str());
    return 1;
  }
  const double origin[3] = { 0, 0, 0 };
  if (!offPath.empty() && !writePoly(offPath, surface, spheres ? origin : nullptr))
  {
    std::fprintf(stderr, "bench_mesher: cannot write %s\n", offPath.c_str());
    return 1;
  }
  volgrid::MesherOptions options;
  options.improvement.fieldPoints = false;
  options.improvement.optimize = false;
  volgrid::MesherResult result;
  const volgrid::Status status = volgrid::meshSurface(surface, options, result);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const volgrid::MesherStatistics& s = result.stats;
  std::printf("{\"bench\":\"mesher\",\"engine\":\"volgrid\",\"input\":\"%s\",\"ok\":%s,\"error\":\"%s\","
              "\"triangles\":%d,\"tets\":%lld,\"points\":%lld,\"steiner_interior\":%lld,"
              "\"seconds_check\":%.4f,\"seconds_delaunay\":%.4f,\"seconds_recovery\":%.4f,"
              "\"seconds_exterior\":%.4f,\"seconds_steiner_removal\":%.4f,\"seconds_total\":%.4f,"
              "\"peak_rss_mb\":%.1f}\n",
              spheres ? "sphere-in-sphere" : input.c_str(), status.ok() ? "true" : "false",
              status.ok() ? "" : status.message.substr(0, 120).c_str(), surface.numberOfTriangles(),
              static_cast<long long>(s.tets), static_cast<long long>(s.points),
              static_cast<long long>(s.steinerInterior), s.secondsCheck, s.secondsDelaunay, s.secondsRecovery,
              s.secondsExterior, s.secondsSteiner, s.secondsTotal, usage.ru_maxrss / 1024.0);
  return status.ok() ? 0 : 1;
}
