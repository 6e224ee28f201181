// gmsh .msh writers, ASCII 4.1 and 2.2. Each patch is a surface entity and each region a volume entity
// whose tag equals its label, carrying one physical group of the same tag named in $PhysicalNames.
// Node and element tags are 1-based; tets keep VolGrid's (and gmsh's) positive vertex order; prisms
// (type 6), pyramids (type 7) and boundary quads (type 3) of boundary layers are written when the mesh has them.
#include "MeshWriter.h"
#include "OutputFile.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>

namespace volgrid
{
namespace
{
void writeHeader(std::FILE* f, const char* version)
{
  std::fprintf(f, "$MeshFormat\n%s 0 8\n$EndMeshFormat\n", version);
}

void writePhysicalNames(std::FILE* f, const std::vector<int32_t>& patches, const std::vector<int32_t>& regions,
                        const SolverMesh& mesh)
{
  std::fprintf(f, "$PhysicalNames\n%zu\n", patches.size() + regions.size());
  for (int32_t p : patches)
    std::fprintf(f, "2 %d \"%s\"\n", p, labelName(mesh.patchNames, p, "patch").c_str());
  for (int32_t r : regions)
    std::fprintf(f, "3 %d \"%s\"\n", r, labelName(mesh.regionNames, r, "region").c_str());
  std::fprintf(f, "$EndPhysicalNames\n");
}

// Bounding box of the points of the cells (nv vertices each) carrying `label`.
void entityBox(const SolverMesh& mesh, const std::vector<int32_t>& cells, int nv, const std::vector<int32_t>& labels,
               int32_t label, double box[6])
{
  for (int k = 0; k < 3; ++k)
    box[k] = 1e300, box[3 + k] = -1e300;
  for (size_t c = 0; c < labels.size(); ++c)
  {
    if (labels[c] != label)
      continue;
    for (int v = 0; v < nv; ++v)
    {
      const double* p = mesh.points.data() + 3 * static_cast<size_t>(cells[nv * c + v]);
      for (int k = 0; k < 3; ++k)
        box[k] = std::min(box[k], p[k]), box[3 + k] = std::max(box[3 + k], p[k]);
    }
  }
}

// entityBox over more cells (boundary quads, prisms), grown into `box`.
void growBox(const SolverMesh& mesh, const std::vector<int32_t>& cells, int nv, const std::vector<int32_t>& labels,
             int32_t label, double box[6])
{
  double more[6];
  entityBox(mesh, cells, nv, labels, label, more);
  for (int k = 0; k < 3; ++k)
    box[k] = std::min(box[k], more[k]), box[3 + k] = std::max(box[3 + k], more[3 + k]);
}

void writeEntities(std::FILE* f, const SolverMesh& mesh, const std::vector<int32_t>& patches,
                   const std::vector<int32_t>& regions)
{
  std::fprintf(f, "$Entities\n0 0 %zu %zu\n", patches.size(), regions.size());
  double b[6];
  for (int32_t p : patches)
  {
    entityBox(mesh, mesh.triangles, 3, mesh.trianglePatch, p, b);
    growBox(mesh, mesh.quads, 4, mesh.quadPatch, p, b);
    std::fprintf(f, "%d %.17g %.17g %.17g %.17g %.17g %.17g 1 %d 0\n", p, b[0], b[1], b[2], b[3], b[4], b[5], p);
  }
  for (int32_t r : regions)
  {
    entityBox(mesh, mesh.tets, 4, mesh.tetRegion, r, b);
    growBox(mesh, mesh.prisms, 6, mesh.prismRegion, r, b);
    growBox(mesh, mesh.pyramids, 5, mesh.pyramidRegion, r, b);
    std::fprintf(f, "%d %.17g %.17g %.17g %.17g %.17g %.17g 1 %d 0\n", r, b[0], b[1], b[2], b[3], b[4], b[5], r);
  }
  std::fprintf(f, "$EndEntities\n");
}

// The elements carrying `label`, numbered from `next`; 2.2 lines also carry the physical and entity tags.
// gmsh element types: 2 triangle, 3 quad, 4 tet, 6 prism, 7 pyramid.
void writeCells(std::FILE* f, const std::vector<int32_t>& cells, int nv, int type, const std::vector<int32_t>& labels,
                int32_t label, int64_t& next, bool v22)
{
  for (size_t c = 0; c < labels.size(); ++c)
  {
    if (labels[c] != label)
      continue;
    if (v22)
      std::fprintf(f, "%" PRId64 " %d 2 %d %d", next++, type, label, label);
    else
      std::fprintf(f, "%" PRId64, next++);
    for (int v = 0; v < nv; ++v)
      std::fprintf(f, " %d", cells[nv * c + v] + 1);
    std::fputc('\n', f);
  }
}

Status writeGmsh(const std::string& path, const SolverMesh& mesh, bool v22)
{
  OutputFile out;
  Status s = out.open(path);
  if (!s.ok())
    return s;
  std::FILE* f = out.stream();
  std::vector<int32_t> allPatches = mesh.trianglePatch, allRegions = mesh.tetRegion;
  allPatches.insert(allPatches.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  allRegions.insert(allRegions.end(), mesh.prismRegion.begin(), mesh.prismRegion.end());
  allRegions.insert(allRegions.end(), mesh.pyramidRegion.begin(), mesh.pyramidRegion.end());
  const std::vector<int32_t> patches = distinctLabels(allPatches);
  const std::vector<int32_t> regions = distinctLabels(allRegions);
  // One block per (entity, element type) that has elements (gmsh 4.1).
  struct Block
  {
    int dim, tag, type, nv;
    const std::vector<int32_t>* cells;
    const std::vector<int32_t>* labels;
    int64_t count;
  };
  std::vector<Block> blocks;
  const auto add = [&](int dim, const std::vector<int32_t>& tags, int type, int nv, const std::vector<int32_t>& cells,
                       const std::vector<int32_t>& labels)
  {
    const std::vector<int64_t> counts = labelCounts(labels, tags);
    for (size_t k = 0; k < tags.size(); ++k)
      if (counts[k] > 0)
        blocks.push_back({ dim, tags[k], type, nv, &cells, &labels, counts[k] });
  };
  add(2, patches, 2, 3, mesh.triangles, mesh.trianglePatch);
  add(2, patches, 3, 4, mesh.quads, mesh.quadPatch);
  add(3, regions, 4, 4, mesh.tets, mesh.tetRegion);
  add(3, regions, 6, 6, mesh.prisms, mesh.prismRegion);
  add(3, regions, 7, 5, mesh.pyramids, mesh.pyramidRegion);
  const int64_t np = mesh.numberOfPoints(),
                ne = mesh.numberOfTriangles() + mesh.numberOfTets() + static_cast<int64_t>(mesh.quads.size() / 4) +
    static_cast<int64_t>(mesh.prisms.size() / 6) + static_cast<int64_t>(mesh.pyramids.size() / 5);
  writeHeader(f, v22 ? "2.2" : "4.1");
  writePhysicalNames(f, patches, regions, mesh);
  if (!v22)
  {
    writeEntities(f, mesh, patches, regions);
    // All nodes in one block on the first volume entity (their classification does not matter here).
    std::fprintf(f, "$Nodes\n1 %" PRId64 " 1 %" PRId64 "\n3 %d 0 %" PRId64 "\n", np, np,
                 regions.empty() ? 1 : regions[0], np);
    for (int64_t i = 0; i < np; ++i)
      std::fprintf(f, "%" PRId64 "\n", i + 1);
  }
  else
    std::fprintf(f, "$Nodes\n%" PRId64 "\n", np);
  for (int64_t i = 0; i < np; ++i)
  {
    const double* p = mesh.points.data() + 3 * i;
    if (v22)
      std::fprintf(f, "%" PRId64 " ", i + 1);
    std::fprintf(f, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
  }
  std::fprintf(f, "$EndNodes\n$Elements\n");
  if (v22)
    std::fprintf(f, "%" PRId64 "\n", ne);
  else
    std::fprintf(f, "%zu %" PRId64 " 1 %" PRId64 "\n", blocks.size(), ne, ne);
  int64_t next = 1;
  for (const Block& b : blocks)
  {
    if (!v22)
      std::fprintf(f, "%d %d %d %" PRId64 "\n", b.dim, b.tag, b.type, b.count);
    writeCells(f, *b.cells, b.nv, b.type, *b.labels, b.tag, next, v22);
  }
  std::fprintf(f, "$EndElements\n");
  return out.commit();
}
} // namespace

Status writeGmsh41(const std::string& path, const SolverMesh& mesh)
{
  return writeGmsh(path, mesh, false);
}

Status writeGmsh22(const std::string& path, const SolverMesh& mesh)
{
  return writeGmsh(path, mesh, true);
}

} // namespace volgrid
