// Size gradation of a tet mesh as a solver sees it (issue 16): the ratio between the sizes of
// face-neighbouring tets. A tet's size is the mean length of its six edges; the ratio of an interior face
// (a face shared by two tets) is the larger size over the smaller one. The summary gives the median, the
// 99th percentile (the value at index floor(0.99 n) of the n ratios sorted, as make bench's
// volgrid_bench_mesh_stats) and the maximum, and how many faces exceed a threshold (e.g. the gradation
// option: a mesh whose sizes follow h(v) <= h(u) + (G - 1) |uv| should keep most ratios under G).
// Faces held by one tet (the boundary) have no ratio. Plain measurement: no tolerance decides anything.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace volgrid
{

class TetMesh;

struct SizeRatioSummary
{
  int64_t faces = 0; // interior faces measured
  double median = 1, p99 = 1, max = 1;
  int64_t aboveThreshold = 0; // faces whose ratio is strictly above `threshold`
};

// points: xyz per point; tets: 4 point ids per tet. Threshold <= 0: aboveThreshold stays 0. threads: the
// rule of ParallelFor.h (0 = all cores); the summary is the same for any value.
SizeRatioSummary summarizeSizeRatios(const double* points, const int32_t* tets, size_t numTets, double threshold = 0,
                                     int threads = 1);
// The same from the tet pairs of the shared faces, as checkBoundaryConformity (BoundaryCheck.h) finds them:
// no face matching of its own. The same summary as the call above for a valid mesh.
SizeRatioSummary summarizeSizeRatios(const double* points, const int32_t* tets, size_t numTets,
                                     const std::vector<std::pair<int32_t, int32_t>>& sharedFaces, double threshold = 0,
                                     int threads = 1);
// The same over a mesh with adjacency (faces with a neighbour; ghost tets, if any, are skipped).
SizeRatioSummary summarizeSizeRatios(const TetMesh& mesh, double threshold = 0);

} // namespace volgrid
