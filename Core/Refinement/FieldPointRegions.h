// The insertions of one large field point pass on all threads, by regions of space (issue 16: every
// core), with the same mesh for any thread count.
//
// The pass's tets are cut into `regions` boxes by median splits (a k-d tree over a sample of their
// centroids, so each box holds about as many). A vertex belongs to the box holding it; a tet belongs to a
// region when its four vertices do. Each region goes through its own tets in the pass's order, asks their
// sizes (eq. 4) a block at a time and inserts their points with TetEditor's region limit: a cavity may only
// hold the region's tets, so two regions never remove the same tet, and the tets of two regions never share
// a face (they would share three vertices), so the faces a cavity is glued to are its region's or those of
// tets no region removes. New points and tets of a region are its own: a point lies in its box (the
// centroid of four points of a box is in the box), and new slots come from the region's TetSlotPool.
// What a region does thus depends on nothing another region does, and any number of threads may run the
// regions in any order: the result is the same.
//
// A tet that spans two regions, and a point whose cavity reaches beyond its region (Deferred), are left for
// the caller, which takes them one after the other in the pass's order once the regions are done. (At
// about 37,000 tets a region, about one tet in ten spans two, and a region inserts about 70% of the
// pass's points.)
//
// Vertex numbers: while the regions run, region r numbers its points from a range of its own beyond the
// mesh's points (so that no thread grows `mesh.points`); afterwards the inserted points are renumbered
// to follow the mesh's points, region by region in insertion order. The order of the numbers, which the
// symbolic perturbation of the insphere test breaks ties by, is unchanged by that renumbering.
#pragma once

#include "Progress.h"
#include "Status.h"
#include "TetEditor.h"
#include "TetMesh.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace volgrid
{

// The number of regions a pass of `todoTets` tets is cut into: a power of two from 2 on, or 1 when the pass
// is too small to be worth it (the caller then inserts everything on one thread, as before regions existed).
// regionTets: the smallest region's share of the pass (0 = the default). It depends on the pass alone,
// never on the thread count.
int fieldPointRegionCount(int64_t regionTets, int64_t todoTets);

struct FieldPointPass
{
  const std::vector<int32_t>* todo = nullptr; // the pass's tets, in its order
  // birth[t] = the pass that created slot t (see FieldPoints.cxx); the regions set it for their new tets.
  std::vector<int32_t>* birth = nullptr;
  int pass = 1;
  double beta = 0; // minimum spacing in units of h
  // The size h at tet t's centroid when t wants a point there, else 0 (eq. 4); asked of unchanged tets only.
  std::function<double(int32_t t)> sizeWanted;
  bool sizeWantedConcurrently = false; // it may be asked from several threads at once (else one thread runs)
};

struct FieldPointRegionOutcome
{
  // todo indices left for the caller, ascending: tets that span two regions (not asked yet) and tets whose
  // point the region could not insert (its cavity reaches beyond the region).
  std::vector<size_t> deferred;
  std::vector<int32_t> created; // the slots the regions created (region by region, in order)
  int64_t inserted = 0;
  int64_t candidates = 0; // reached alive and wanting a point, not deferred
  int64_t rejectedSpacing = 0;
  int64_t rejectedOther = 0;
};

// Inserts the passes' points region by region on the threads.
class FieldPointRegions
{
public:
  // editor: the caller's (constraints and labels as in insertFieldPoints; no slot pool, no region limit),
  // which the first thread uses; the others get editors of their own. threads: ParallelFor.h's rule.
  FieldPointRegions(TetEditor& editor, int threads);
  ~FieldPointRegions();
  // One pass cut into `regions` (fieldPointRegionCount). Errors: Cancelled (the regions stop; the mesh is
  // consistent and keeps their points).
  Status insertPass(const FieldPointPass& pass, int regions, Progress* progress, FieldPointRegionOutcome& outcome);

private:
  TetEditor& editor_;
  int threads_;
  std::vector<std::unique_ptr<TetEditor>> more_; // the editors of threads 1, 2, ...
};

} // namespace volgrid
