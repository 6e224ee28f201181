// SU2 native mesh writer (.su2, ASCII): NDIME, the tets (VTK type 10, 0-based point ids) then the
// boundary-layer prisms (VTK type 13, VTK's wedge order: the first triangle's normal points away from the
// second, as SU2's CPrism faces have it), the pyramids (VTK type 14, in SolverMesh's and VTK's order: the
// quad's normal towards the apex), the points, and one MARKER_TAG per patch with its boundary
// triangles (VTK type 5) and prism side quads (VTK type 9). SU2 has no region names.
#include "MeshWriter.h"
#include "OutputFile.h"

#include <cinttypes>
#include <cstdio>

namespace volgrid
{

Status writeSU2(const std::string& path, const SolverMesh& mesh)
{
  OutputFile out;
  Status s = out.open(path);
  if (!s.ok())
    return s;
  std::FILE* f = out.stream();
  const int64_t numPrisms = static_cast<int64_t>(mesh.prisms.size() / 6);
  const int64_t numPyramids = static_cast<int64_t>(mesh.pyramids.size() / 5);
  std::fprintf(f, "NDIME= 3\nNELEM= %" PRId64 "\n", mesh.numberOfTets() + numPrisms + numPyramids);
  for (int64_t t = 0; t < mesh.numberOfTets(); ++t)
  {
    const int32_t* v = mesh.tets.data() + 4 * t;
    std::fprintf(f, "10 %d %d %d %d %" PRId64 "\n", v[0], v[1], v[2], v[3], t);
  }
  for (int64_t w = 0; w < numPrisms; ++w) // SolverMesh's base normal points to the top: both triangles reversed
  {
    const int32_t* v = mesh.prisms.data() + 6 * w;
    std::fprintf(f, "13 %d %d %d %d %d %d %" PRId64 "\n", v[0], v[2], v[1], v[3], v[5], v[4], mesh.numberOfTets() + w);
  }
  for (int64_t y = 0; y < numPyramids; ++y)
  {
    const int32_t* v = mesh.pyramids.data() + 5 * y;
    std::fprintf(f, "14 %d %d %d %d %d %" PRId64 "\n", v[0], v[1], v[2], v[3], v[4],
                 mesh.numberOfTets() + numPrisms + y);
  }
  std::fprintf(f, "NPOIN= %" PRId64 "\n", mesh.numberOfPoints());
  for (int64_t i = 0; i < mesh.numberOfPoints(); ++i)
  {
    const double* p = mesh.points.data() + 3 * i;
    std::fprintf(f, "%.17g %.17g %.17g %" PRId64 "\n", p[0], p[1], p[2], i);
  }
  std::vector<int32_t> faces = mesh.trianglePatch;
  faces.insert(faces.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  const std::vector<int32_t> patches = distinctLabels(faces);
  const std::vector<int64_t> counts = labelCounts(faces, patches);
  std::fprintf(f, "NMARK= %zu\n", patches.size());
  for (size_t k = 0; k < patches.size(); ++k)
  {
    std::fprintf(f, "MARKER_TAG= %s\nMARKER_ELEMS= %" PRId64 "\n",
                 labelName(mesh.patchNames, patches[k], "patch").c_str(), counts[k]);
    for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
    {
      if (mesh.trianglePatch[t] != patches[k])
        continue;
      const int32_t* v = mesh.triangles.data() + 3 * t;
      std::fprintf(f, "5 %d %d %d\n", v[0], v[1], v[2]);
    }
    for (size_t q = 0; q < mesh.quadPatch.size(); ++q)
      if (mesh.quadPatch[q] == patches[k])
        std::fprintf(f, "9 %d %d %d %d\n", mesh.quads[4 * q], mesh.quads[4 * q + 1], mesh.quads[4 * q + 2],
                     mesh.quads[4 * q + 3]);
  }
  return out.commit();
}

} // namespace volgrid
