// Label bookkeeping of SolverMesh: dense positive patch and region labels with their names.
#include "SolverMesh.h"

#include <algorithm>
#include <map>

namespace volgrid
{
namespace
{
void renumber(std::vector<int32_t>& labels, NameTable& names, const char* prefix)
{
  const std::vector<int32_t> old = distinctLabels(labels);
  std::map<int32_t, int32_t> toNew;
  NameTable renamed;
  for (size_t k = 0; k < old.size(); ++k)
  {
    toNew[old[k]] = static_cast<int32_t>(k + 1);
    renamed[static_cast<int32_t>(k + 1)] = labelName(names, old[k], prefix);
  }
  for (int32_t& l : labels)
    l = toNew[l];
  names = renamed;
}
} // namespace

bool hasLayerCells(const SolverMesh& mesh)
{
  return !mesh.prisms.empty() || !mesh.pyramids.empty();
}

bool finishReadCells(SolverMesh& mesh)
{
  if (!hasLayerCells(mesh))
  {
    mesh.quads.clear();
    mesh.quadPatch.clear();
  }
  return !mesh.tets.empty() || hasLayerCells(mesh);
}

std::vector<int32_t> distinctLabels(const std::vector<int32_t>& labels)
{
  std::vector<int32_t> d(labels);
  std::sort(d.begin(), d.end());
  d.erase(std::unique(d.begin(), d.end()), d.end());
  return d;
}

void normalizeLabels(SolverMesh& mesh)
{
  mesh.tetRegion.resize(mesh.tets.size() / 4, 0);
  mesh.trianglePatch.resize(mesh.triangles.size() / 3, 0);
  mesh.prismRegion.resize(mesh.prisms.size() / 6, 0);
  mesh.quadPatch.resize(mesh.quads.size() / 4, 0);
  mesh.pyramidRegion.resize(mesh.pyramids.size() / 5, 0);
  // Triangles and quads share the patch labels, tets and prisms the region labels.
  const auto together = [](std::vector<int32_t>& a, std::vector<int32_t>& b, NameTable& names, const char* prefix)
  {
    const size_t na = a.size();
    a.insert(a.end(), b.begin(), b.end());
    renumber(a, names, prefix);
    std::copy(a.begin() + static_cast<std::ptrdiff_t>(na), a.end(), b.begin());
    a.resize(na);
  };
  together(mesh.trianglePatch, mesh.quadPatch, mesh.patchNames, "patch");
  std::vector<int32_t> layerCells = mesh.prismRegion; // prisms and pyramids
  layerCells.insert(layerCells.end(), mesh.pyramidRegion.begin(), mesh.pyramidRegion.end());
  together(mesh.tetRegion, layerCells, mesh.regionNames, "region");
  std::copy(layerCells.begin(), layerCells.begin() + static_cast<std::ptrdiff_t>(mesh.prismRegion.size()),
            mesh.prismRegion.begin());
  std::copy(layerCells.begin() + static_cast<std::ptrdiff_t>(mesh.prismRegion.size()), layerCells.end(),
            mesh.pyramidRegion.begin());
}

std::vector<int64_t> labelCounts(const std::vector<int32_t>& labels, const std::vector<int32_t>& distinct)
{
  std::vector<int64_t> counts(distinct.size(), 0);
  for (int32_t l : labels)
  {
    const auto it = std::lower_bound(distinct.begin(), distinct.end(), l);
    if (it != distinct.end() && *it == l)
      ++counts[static_cast<size_t>(it - distinct.begin())];
  }
  return counts;
}

} // namespace volgrid
