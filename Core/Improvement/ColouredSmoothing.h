// Smoothing of many vertices on all threads, with the same result at any thread count.
//
// A smoothing move (MeshSmoothing.h) writes only the moved vertex and reads only its star, so two vertices
// that share no tet can move at the same time. The vertices are split into colour classes (greedy
// colouring in the given order: a vertex takes the smallest colour none of its neighbours in the list
// has); the classes move one after the other, each class in parallel. Which class a vertex falls in
// depends only on the list and the mesh, never on the thread count, so the mesh does not either.
#pragma once

#include "MeshSmoothing.h"
#include "OrthogonalityFirst.h"
#include "Progress.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

// Smooths `vertices` (distinct, unlocked, in the order that decides the colouring) on `threads`
// (ParallelFor.h rule). moves[i] receives the move of vertices[i]. The editor's vertex map must be
// current; smoothing changes no tet, so it stays current.
// rule (optional, OrthogonalityFirst.h): once a class has moved, a move whose star the rule binds and now
// holds more tets under the target or more severe faces is undone (in list order; the counts are taken
// with the whole class moved, so they do not depend on the threads either).
// progress (optional) is asked before each class but the first; when it says stop, the classes left do not
// move (their moves stay None).
void smoothColoured(TetEditor& editor, const std::vector<int32_t>& vertices, const SmoothingOptions& options,
                    int threads, std::vector<SmoothMove>& moves, const OrthogonalityFirst* rule = nullptr,
                    Progress* progress = nullptr);

} // namespace volgrid
