// libFuzzer target for one Core surface reader, chosen at compile time by VOLGRID_FUZZ_EXTENSION ("stl",
// "obj", "off", "ply", "mesh", "poly", "msh", or "stl.gz" for the gzip layer). The readers take a path, so
// each input is written to a private file in /dev/shm (or /tmp) with that extension and read back; any
// crash, sanitizer report or leak is a finding. A read must end in success or in a Status naming the file.
#include "SurfaceReader.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
std::string scratchPath()
{
  const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  return std::string(dir) + "/volgrid-fuzz-" + std::to_string(getpid()) + "." VOLGRID_FUZZ_EXTENSION;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const std::string path = scratchPath();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f)
    return 0;
  const bool written = std::fwrite(data, 1, size, f) == size;
  if (std::fclose(f) != 0 || !written)
    return 0;
  volgrid::SurfaceMesh mesh;
  volgrid::SurfaceReadInfo info;
  const volgrid::Status status = volgrid::readSurface(path, mesh, &info);
  if (!status.ok() && status.message.find(path) == std::string::npos)
  {
    std::fprintf(stderr, "the refusal does not name the file: %s\n", status.message.c_str());
    std::abort();
  }
  if (status.ok())
  {
    for (int32_t t = 0; t < mesh.numberOfTriangles(); ++t)
      for (int k = 0; k < 3; ++k)
        if (mesh.triangle(t)[k] < 0 || mesh.triangle(t)[k] >= mesh.numberOfPoints())
          std::abort(); // a triangle refers to a point that does not exist
  }
  return 0;
}
