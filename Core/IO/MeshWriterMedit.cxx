// Medit .mesh writer (ASCII, MeshVersionFormatted 2): Vertices (ref 0), Triangles with the patch label
// as ref, Tetrahedra with the region label as ref; with boundary layers also Quadrilaterals (prism sides
// on a symmetry plane, patch label), Prisms and Pyramids (region label). Prisms and pyramids keep
// SolverMesh's order, the one the tets have too: the first face's normal (base triangle, quad) points to
// the rest of the cell (gmsh's order; VTK's wedge is the reverse). Medit has no names: each label's name
// goes into a comment line "# VolGrid patch LABEL NAME" / "# VolGrid region LABEL NAME" that other
// readers skip and VolGrid's reader takes back.
#include "MeshWriter.h"
#include "OutputFile.h"

#include <cinttypes>
#include <cstdio>

namespace volgrid
{
namespace
{
// A section of cells with n points each (1-based ids) and a label each; none when there are no cells,
// so tet-only files stay as they were.
void writeCells(std::FILE* f, const char* section, const std::vector<int32_t>& cells, size_t n,
                const std::vector<int32_t>& labels)
{
  if (labels.empty())
    return;
  std::fprintf(f, "%s\n%zu\n", section, labels.size());
  for (size_t c = 0; c < labels.size(); ++c)
  {
    for (size_t k = 0; k < n; ++k)
      std::fprintf(f, "%d ", cells[n * c + k] + 1);
    std::fprintf(f, "%d\n", labels[c]);
  }
}
} // namespace

Status writeMedit(const std::string& path, const SolverMesh& mesh)
{
  OutputFile out;
  Status s = out.open(path);
  if (!s.ok())
    return s;
  std::FILE* f = out.stream();
  std::fprintf(f, "MeshVersionFormatted 2\n");
  std::vector<int32_t> patches = mesh.trianglePatch, regions = mesh.tetRegion;
  patches.insert(patches.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  regions.insert(regions.end(), mesh.prismRegion.begin(), mesh.prismRegion.end());
  regions.insert(regions.end(), mesh.pyramidRegion.begin(), mesh.pyramidRegion.end());
  for (int32_t p : distinctLabels(patches))
    std::fprintf(f, "# VolGrid patch %d %s\n", p, labelName(mesh.patchNames, p, "patch").c_str());
  for (int32_t r : distinctLabels(regions))
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
  writeCells(f, "Quadrilaterals", mesh.quads, 4, mesh.quadPatch);
  std::fprintf(f, "Tetrahedra\n%" PRId64 "\n", mesh.numberOfTets());
  for (int64_t t = 0; t < mesh.numberOfTets(); ++t)
  {
    const int32_t* v = mesh.tets.data() + 4 * t;
    std::fprintf(f, "%d %d %d %d %d\n", v[0] + 1, v[1] + 1, v[2] + 1, v[3] + 1, mesh.tetRegion[t]);
  }
  writeCells(f, "Prisms", mesh.prisms, 6, mesh.prismRegion);
  writeCells(f, "Pyramids", mesh.pyramids, 5, mesh.pyramidRegion);
  std::fprintf(f, "End\n");
  return out.commit();
}

} // namespace volgrid
