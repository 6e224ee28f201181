// Layers, then the conforming mesher on the rest, merged into one conformal mixed mesh.
#include "LayeredMesher.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <set>

namespace volgrid
{
namespace
{
std::array<int32_t, 3> sortedTriangle(const int32_t* v)
{
  std::array<int32_t, 3> t = { v[0], v[1], v[2] };
  std::sort(t.begin(), t.end());
  return t;
}

// Appends the tet region to `out`, mapping the mesher's points onto the layer's (exactly the same
// coordinates: the mesher's input was copied from them).
void mergeTets(const LayerResult& layers, const MesherResult& tets, LayeredMeshResult& out)
{
  out.points = layers.points;
  std::vector<int32_t> map(tets.points.size() / 3, -1);
  for (size_t i = 0; i < layers.tetBoundaryPoint.size(); ++i)
    map[tets.inputToOutputPoint[i]] = layers.tetBoundaryPoint[i];
  for (size_t p = 0; p < map.size(); ++p)
    if (map[p] < 0)
    {
      map[p] = static_cast<int32_t>(out.points.size() / 3);
      out.points.insert(out.points.end(), tets.points.begin() + 3 * p, tets.points.begin() + 3 * p + 3);
    }
  for (const int32_t v : tets.tets)
    out.tets.push_back(map[v]);
  out.tetRegion = tets.tetRegion;
  out.tetLayer.assign(tets.tets.size() / 4, -1);
  out.tetReason.assign(tets.tets.size() / 4, 0);
  std::set<std::array<int32_t, 3>> onTets;
  for (size_t t = 0; t < tets.boundaryPatch.size(); ++t)
  {
    int32_t v[3];
    for (int i = 0; i < 3; ++i)
      v[i] = map[tets.boundaryTriangles[3 * t + i]];
    if (tets.boundaryPatch[t] == layers.interfacePatch)
    {
      ++out.tetBoundaryOnInterface;
      onTets.insert(sortedTriangle(v));
      continue;
    }
    out.boundaryTriangles.insert(out.boundaryTriangles.end(), v, v + 3);
    out.boundaryPatch.push_back(tets.boundaryPatch[t]);
  }
  for (size_t t = 0; t < out.interfaceTriangles.size(); t += 3)
    out.interfaceOnTets += onTets.count(sortedTriangle(out.interfaceTriangles.data() + t)) ? 1 : 0;
}

// The cells over triangles with collapsed corners: their tets, and their pyramids (or each pyramid's two
// tets, its quad cut through its smallest id as the split prisms cut it).
void addCollapsedCells(const LayerResult& layers, bool splitPrisms, LayeredMeshResult& result)
{
  const auto addTets = [&](const int32_t* v, size_t n, int32_t layer, uint8_t reason)
  {
    result.tets.insert(result.tets.end(), v, v + 4 * n);
    result.tetRegion.insert(result.tetRegion.end(), n, 0);
    result.tetLayer.insert(result.tetLayer.end(), n, layer);
    result.tetReason.insert(result.tetReason.end(), n, reason);
  };
  for (size_t t = 0; t < layers.tetLayer.size(); ++t)
    addTets(layers.tets.data() + 4 * t, 1, layers.tetLayer[t], layers.tetReason[t]);
  if (!splitPrisms)
  {
    result.pyramids = layers.pyramids;
    result.pyramidLayer = layers.pyramidLayer;
    result.pyramidReason = layers.pyramidReason;
    return;
  }
  for (size_t p = 0; p < layers.pyramidLayer.size(); ++p)
  {
    int32_t split[8];
    splitPyramid(layers.pyramids.data() + 5 * p, split);
    addTets(split, 2, layers.pyramidLayer[p], layers.pyramidReason[p]);
  }
}
} // namespace

Status meshSurfaceWithLayers(const SurfaceMesh& surface, const MesherOptions& mesherOptions,
                             const LayerOptions& layerOptions, LayeredMeshResult& result, Progress* progress)
{
  const auto started = std::chrono::steady_clock::now();
  result = LayeredMeshResult();
  LayerResult layers;
  Status status = growLayers(surface, layerOptions, layers, progress);
  if (!status.ok())
    return status;
  for (size_t t = 0; t < layers.tetBoundary.patchIds.size(); ++t)
    if (layers.tetBoundary.patchIds[t] == layers.interfacePatch)
      for (int i = 0; i < 3; ++i)
        result.interfaceTriangles.push_back(layers.tetBoundaryPoint[layers.tetBoundary.triangles[3 * t + i]]);
  MesherResult tets;
  status = meshSurface(layers.tetBoundary, mesherOptions, tets, progress);
  if (!status.ok())
  {
    result = LayeredMeshResult();
    status.message = "meshing outside the boundary layers: " + status.message;
    return status;
  }
  mergeTets(layers, tets, result);
  result.wallTriangles = layers.wallTriangles;
  result.boundaryTriangles.insert(result.boundaryTriangles.begin(), layers.wallTriangles.begin(),
                                  layers.wallTriangles.end());
  result.boundaryPatch.insert(result.boundaryPatch.begin(), layers.wallPatch.begin(), layers.wallPatch.end());
  // Prism sides on symmetry planes: two triangles cut through the quad's smallest id, as splitPrism does.
  result.sideQuads = layers.sideQuads;
  result.sidePatch = layers.sidePatch;
  for (size_t q = 0; q < layers.sidePatch.size() && layerOptions.splitPrisms; ++q)
  {
    const int32_t* v = layers.sideQuads.data() + 4 * q;
    const int m = static_cast<int>(std::min_element(v, v + 4) - v);
    const int32_t a = v[m], b = v[(m + 1) % 4], c = v[(m + 2) % 4], d = v[(m + 3) % 4];
    result.boundaryTriangles.insert(result.boundaryTriangles.end(), { a, b, c, a, c, d });
    result.boundaryPatch.insert(result.boundaryPatch.end(), 2, layers.sidePatch[q]);
  }
  result.patchNames = layers.tetBoundary.patchNames;
  result.patchNames.erase(layers.interfacePatch);
  if (layerOptions.splitPrisms)
    for (size_t p = 0; p < layers.prismLayer.size(); ++p)
    {
      int32_t split[12];
      splitPrism(layers.prisms.data() + 6 * p, result.points.data(), split);
      result.tets.insert(result.tets.end(), split, split + 12);
      result.tetRegion.insert(result.tetRegion.end(), 3, 0);
      result.tetLayer.insert(result.tetLayer.end(), 3, layers.prismLayer[p]);
      result.tetReason.insert(result.tetReason.end(), 3, layers.prismReason[p]);
    }
  else
  {
    result.wedges = layers.prisms;
    result.wedgeLayer = layers.prismLayer;
    result.wedgeReason = layers.prismReason;
  }
  addCollapsedCells(layers, layerOptions.splitPrisms, result);
  result.layerStats = layers.stats;
  result.mesherStats = tets.stats;
  result.warnings = tets.warnings;
  if (!wallRefinementNote(layers.stats.wallRefinement).empty())
    result.warnings.push_back(wallRefinementNote(layers.stats.wallRefinement));
  for (std::string& text : wallFaceWarnings(layers.stats.wallFaceQuality))
    result.warnings.push_back(std::move(text));
  if (result.interfaceOnTets != static_cast<int64_t>(result.interfaceTriangles.size() / 3) ||
      result.tetBoundaryOnInterface != result.interfaceOnTets)
  {
    const int64_t asked = static_cast<int64_t>(result.interfaceTriangles.size() / 3);
    result = LayeredMeshResult();
    return Status::failure(ErrorKind::InternalError,
                           "the tet region does not share the last layer's surface exactly (" + std::to_string(asked) +
                             " layer faces) : a bug, please report it");
  }
  result.transition = measureLayerTransition(result, layerOptions.resolved().layers);
  const std::string transitionWarning = layerTransitionWarning(result.transition);
  if (!transitionWarning.empty())
    result.warnings.push_back(transitionWarning);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return Status::success();
}

SolverMesh layeredSolverMesh(const LayeredMeshResult& r)
{
  SolverMesh mesh;
  mesh.points = r.points;
  mesh.tets = r.tets;
  mesh.tetRegion = r.tetRegion;
  mesh.triangles = r.boundaryTriangles;
  mesh.trianglePatch = r.boundaryPatch;
  mesh.patchNames = r.patchNames;
  mesh.prisms = r.wedges;
  mesh.prismRegion.assign(r.wedges.size() / 6, 0);
  mesh.pyramids = r.pyramids;
  mesh.pyramidRegion.assign(r.pyramids.size() / 5, 0);
  if (!r.wedges.empty()) // split prisms put their side quads into boundaryTriangles
  {
    mesh.quads = r.sideQuads;
    mesh.quadPatch = r.sidePatch;
  }
  return mesh;
}

} // namespace volgrid
