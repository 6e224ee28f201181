// Whole-mesh scans of the quality stage (the smallest sine quality, the tets below a quality, how many of
// them) on Core's thread pool (ParallelFor.h: 0 = all cores). Each range of tet slots gives a partial;
// the partials are merged in slot order, so the result is the same for any thread count. The mesh must
// be free of ghost tets. Sine quality: tetSineQuality (TetEditor.h).
#pragma once

#include "Progress.h"
#include "TetMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace volgrid
{

// The smallest sine quality of the live tets; 2 when there is none.
double minSineQuality(const TetMesh& mesh, int threads);

// How many live tets have a sine quality under q.
int64_t countSineBelow(const TetMesh& mesh, double q, int threads);

// Every live tet with a sine quality under q as (quality, tet), in slot order (out is cleared first).
// progress (optional) is asked between blocks of kSlotsPerQuestion slots (a sweep of 5M tets takes a
// quarter of a second on one thread); when it says stop, false and out holds the tets of the blocks done.
bool collectSineBelow(const TetMesh& mesh, double q, int threads, std::vector<std::pair<double, int32_t>>& out,
                      Progress* progress = nullptr);
constexpr int64_t kSlotsPerQuestion = int64_t{ 1 } << 20;

// The same among the slots `candidates` (sorted and deduplicated here), as (quality, tet) in that order:
// after an edit, the tets under q before it (those it left keep their quality) and the tets it created
// are all the mesh has under q, so this gives what collectSineBelow, sorted, would give, without a sweep.
void collectSineBelowAmong(const TetMesh& mesh, double q, std::vector<int32_t>& candidates,
                           std::vector<std::pair<double, int32_t>>& out);

} // namespace volgrid
