// Splitting of the tets the optimiser cannot fix (MeshImprovement.h, stage 4): slivers and caps spanned
// by boundary vertices, which no flip or move can change without touching the boundary.
//
// Tets still below `degrees` after optimisation (typically slivers and caps spanned by boundary vertices,
// which no flip or move can fix) are removed by a new interior point, inserted with the quality-driven
// cavity of TetEditor::qualityInsertion at the position where the worst tet it creates is best:
// candidates (edge midpoints, centroid, circumcentre, points over each face on both sides at the height of
// a regular tet and at half of it; for a tet spanned by four boundary vertices also points off each edge
// midpoint along its two faces' normals) scored without touching the mesh, then a pattern search from the
// best one. The point goes in only when its cavity holds the bad tet and its worst new tet beats both the bad
// tet and the worst tet it replaces: every insertion is a strict local improvement. Constrained faces are
// never crossed, so the boundary is untouched. Returns the number of points inserted.
//
// speculative: the worst tet gets the best point found even when that does not improve it at once (the
// caller optimises around it and keeps the result only if the mesh's worst tet got better).
//
// With SplitRequest::orthogonalityFirst, a position also scores -3 when its insertion would add faces a
// solver finds severely non-orthogonal, and the best position goes in only when it leaves no more tets
// under `degrees` than it replaces (for tets that are not nearly flat: OrthogonalityFirst.h).
#pragma once

#include "OrthogonalityFirst.h"
#include "Progress.h"
#include "TetEditor.h"
#include "TetMesh.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace volgrid
{

struct SplitRequest
{
  double degrees = 18; // tets below this (min(theta_min, 180 - theta_max), degrees) are split, worst first
  int64_t maxPoints = 0;
  bool speculative = false; // see above
  size_t skip = 0;          // the first `skip` bad tets are left alone
  // Optional: the tets under `degrees` in (quality, slot) order, exactly what a sweep of the mesh would collect
  // (e.g. an optimisation worklist), so that no sweep is needed.
  const std::vector<std::pair<double, int32_t>>* below = nullptr;
  // The candidate positions of a tet are scored on this many threads (ParallelFor.h's rule); the mesh is the
  // same for any count.
  int threads = 1;
  // Optional: asked every 64 bad tets whether to stop (the points inserted so far stay; the caller reports
  // the cancellation).
  Progress* progress = nullptr;
  // Optional: receives (appended) the slots of the tets the insertions created, some of them destroyed again
  // by later insertions of the call, so that the caller can find the tets under a target without a sweep
  // (MeshScan.h, collectSineBelowAmong).
  std::vector<int32_t>* created = nullptr;
  // Optional: TetEditor::lockedVertices() of this mesh and constraints, when the caller keeps it (a vertex
  // past its end is a point added since, unlocked): no sweep of the mesh for it.
  const std::vector<uint8_t>* constrainedLocks = nullptr;
  // Optional: the caller's editor of this mesh with the same constraints and labels, through which every
  // edit of the mesh since its vertex map was built went: refreshed (TetEditor::refreshVertexMap) instead
  // of a new editor's sweep.
  TetEditor* editor = nullptr;
  // Off by default. On (OrthogonalityFirst.h), for a bad tet not nearly flat: no position whose insertion
  // adds severely non-orthogonal faces, and no insertion that leaves more tets under `degrees` than it
  // replaces.
  OrthogonalityFirst orthogonalityFirst;
};

// Splits the bad tets of `request`; labels (per tet slot, optional) follow the new tets. Returns the number
// of points inserted.
int64_t splitBadTets(TetMesh& mesh, const FaceConstraints* constraints, std::vector<int32_t>* labels,
                     const SplitRequest& request);

} // namespace volgrid
