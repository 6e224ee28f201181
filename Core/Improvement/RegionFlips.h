// The flips of one large sweep on all threads, by regions of space (issue 16: every core), with the same
// mesh for any thread count (MeshRegions.h says why regions may run at once).
//
// The sweep's tets are cut into boxes (RegionBoxes.h) of about 4,096 of them each (regionFlipCount). Each region
// goes through its tets in the sweep's order (slot order) with an editor of its own: its slots come from
// its TetSlotPool, and TetEditor::RegionLimit lets it replace only the region's tets. A tet whose best flip
// would replace a tet of another region, or that spans two regions, is left for the caller, which flips
// those one after the other afterwards, in slot order. New tets still under the aim are tried again in
// their region, as the one-thread sweep tries them.
#pragma once

#include "Progress.h"
#include "Status.h"
#include "TetEditor.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace volgrid
{

// The regions for a sweep of `tets` tets: a power of two, or 1 when the sweep is too small to be worth it.
// regionTets: the smallest region's share of the sweep (0 = the default, 4,096). It depends on
// the sweep alone, never on the thread count.
int regionFlipCount(int64_t regionTets, int64_t tets);

// What one tet's flip attempt did.
enum class FlipAttempt
{
  None,    // no flip improves it
  Made,    // one did (created: its new tets)
  Deferred // the flip that improves it needs a tet outside the editor's region; nothing changed
};

struct RegionFlipOutcome
{
  std::vector<int32_t> deferred; // sweep tets left for the caller, ascending
  std::vector<int32_t> created;  // the slots the regions created, region by region, in order
  int64_t made = 0;              // successful attempts
};

// The attempts on the tets `sweep` (ascending slots) under `aim` (quality(t) < aim), cut into `regions`.
// attempt(editor, t, created) is called from several threads at once, each with its own editor (the
// caller's constraints and labels, no vertex map; regionLimit and slotPool set); it must edit through
// that editor only. mainEditor: the caller's; its vertex map gets the new tets (mapTetsMadeElsewhere).
// Errors: Cancelled (the regions stop; the mesh is valid and keeps their flips).
Status flipByRegions(TetEditor& mainEditor, const std::vector<int32_t>& sweep, int regions, int threads, double aim,
                     const std::function<double(int32_t)>& quality,
                     const std::function<FlipAttempt(TetEditor&, int32_t, std::vector<int32_t>&)>& attempt,
                     Progress* progress, RegionFlipOutcome& outcome);

} // namespace volgrid
