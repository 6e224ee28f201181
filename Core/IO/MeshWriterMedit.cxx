// Medit .mesh writer (ASCII, MeshVersionFormatted 2): Vertices (ref 0), Triangles with the patch label
// as ref, Tetrahedra with the region label as ref. Medit has no names: each label's name goes into a
// comment line "# VolGrid patch LABEL NAME" / "# VolGrid region LABEL NAME" that other readers skip and
// VolGrid's reader takes back.
#include "MeshWriter.h"
#include "OutputFile.h"

#include <cinttypes>
#include <cstdio>

namespace volgrid
{

Status writeMedit(const std::string& path, const SolverMesh& mesh)
{
  OutputFile out;
  Status s = out.open(path);
  if (!s.ok())
    return s;
  std::FILE* f = out.stream();
  std::fprintf(f, "MeshVersionFormatted 2\n");
  for (int32_t p : distinctLabels(mesh.trianglePatch))
    std::fprintf(f, "# VolGrid patch %d %s\n", p, labelName(mesh.patchNames, p, "patch").c_str());
  for (int32_t r : distinctLabels(mesh.tetRegion))
    std::fprintf(f, "# VolGrid region %d %s\n", r, labelName(mesh.regionNames, r, "region").c_str());
  std::fprintf(f, "Dimension 3\nVertices\n%" PRId64 "\n", mesh.numberOfPoints());
  for (int64_t i = 0; i < mesh.numberOfPoints(); ++i)
  {
    const double* p = mesh.points.data() + 3 * i;
    std::fprintf(f, "%.17g %.17g %.17g 0\n", p[0], p[1], p[2]);
  }
  std::fprintf(f, "Triangles\n%" PRId64 "\n", mesh.numberOfTriangles());
  for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
  {
    const int32_t* v = mesh.triangles.data() + 3 * t;
    std::fprintf(f, "%d %d %d %d\n", v[0] + 1, v[1] + 1, v[2] + 1, mesh.trianglePatch[t]);
  }
  std::fprintf(f, "Tetrahedra\n%" PRId64 "\n", mesh.numberOfTets());
  for (int64_t t = 0; t < mesh.numberOfTets(); ++t)
  {
    const int32_t* v = mesh.tets.data() + 4 * t;
    std::fprintf(f, "%d %d %d %d %d\n", v[0] + 1, v[1] + 1, v[2] + 1, v[3] + 1, mesh.tetRegion[t]);
  }
  std::fprintf(f, "End\n");
  return out.commit();
}

} // namespace volgrid
