#include "OrthogonalityFirst.h"

#include "TetEditor.h"

#include <algorithm>

namespace volgrid
{

RegionCounts countRegion(const TetMesh& mesh, const std::vector<int32_t>& region, const OrthogonalityFirst& rule)
{
  auto centroid = [&](int32_t t, double c[3])
  {
    const int32_t* w = mesh.vertices(t);
    for (int k = 0; k < 3; ++k)
      c[k] = (mesh.point(w[0])[k] + mesh.point(w[1])[k] + mesh.point(w[2])[k] + mesh.point(w[3])[k]) / 4;
  };
  RegionCounts counts;
  for (const int32_t t : region)
  {
    const int32_t* w = mesh.vertices(t);
    const double q = tetSineQuality(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]));
    counts.worst = std::min(counts.worst, q);
    counts.below += q < rule.targetQuality;
    double ct[3], cu[3];
    centroid(t, ct);
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = mesh.neighbor(t, i);
      if (u < 0 || (u < t && std::binary_search(region.begin(), region.end(), u))) // a face inside: once
        continue;
      centroid(u, cu);
      int32_t f[3];
      mesh.faceVertices(t, i, f);
      counts.severe +=
        quality::triangleLineCosine(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), ct, cu) < rule.severeCosine;
    }
  }
  return counts;
}

} // namespace volgrid
