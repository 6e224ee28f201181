// Helper editors for scoring vertex positions on more threads (BadTetSplitting, InsertionImprovement).
// A position is scored by writing it into a vertex slot and trying its cavity, so each extra thread needs
// an editor (stamps, cavity) and a vertex slot of its own. The helpers have no vertex map: they only
// locate and try cavities, never commit, and a map would cost a sweep of the mesh.
#pragma once

#include "ParallelFor.h"
#include "TetEditor.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace volgrid
{

class ScoringHelpers
{
public:
  ScoringHelpers(TetMesh& mesh, const FaceConstraints* constraints, int threads)
    : mesh_(mesh)
  {
    for (int w = 1; w < resolveThreads(threads); ++w)
      helpers_.push_back(std::make_unique<TetEditor>(mesh, constraints, nullptr, TetEditor::VertexMap::None));
  }

  // Threads that can score at once: the caller's editor and the helpers.
  int count() const { return static_cast<int>(helpers_.size()) + 1; }

  // Helper r (1 <= r < count()), whose slot in withSlots is nv + r.
  TetEditor& helper(int r) { return *helpers_[static_cast<size_t>(r - 1)]; }

  // Runs body() with `ranges - 1` extra vertex slots after the attempt's vertex nv (the mesh's last) and
  // removes them after it. The points may move: take slot addresses inside body.
  template<typename Body>
  void withSlots(int32_t nv, int ranges, Body&& body)
  {
    const size_t last = static_cast<size_t>(nv);
    const size_t extra = static_cast<size_t>(std::max(ranges, 1) - 1);
    mesh_.points.resize(3 * (last + 1 + extra));
    body();
    mesh_.points.resize(3 * (last + 1));
  }

private:
  TetMesh& mesh_;
  std::vector<std::unique_ptr<TetEditor>> helpers_;
};

} // namespace volgrid
