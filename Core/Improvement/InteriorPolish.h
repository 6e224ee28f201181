// Interior polish (issue 16, acceptance 3): the last quality step for the tets with no vertex on the
// boundary whose dihedral angles leave [interiorDegrees, 180 - interiorDegrees].
//
// Why a step of its own: the rounds before it (QualityRounds.h) take an edit when it raises the worst tet it
// touches. Most bad interior tets that survive them sit next to a worse tet that touches the boundary, whose
// angle the boundary triangles hold down: no move of a shared vertex raises that tet, so none is taken, and
// the interior tet beside it stays as it is.
//
// Here a tet scores its sine quality over the sine of the angle it must reach (interiorDegrees inside,
// boundaryDegrees for a tet with a vertex on the boundary: TetNeeds.h). For each bad interior tet, in slot
// order, as long as it is bad:
//   1. its vertices are smoothed for the star's smallest score (smoothVertexWeighted, MeshSmoothing.h);
//      when that score's tet cannot rise, it is set aside and the next smallest is tried;
//   2. edge removal on its edges and 2-3 flips of its faces, judged by TetNeeds;
//   3. collapses of its vertices, or of their nearest neighbours, onto a neighbour, judged by TetNeeds;
//   4. a new point inside or beside it, placed where the quality-driven insertion (TetEditor.h, cavity
//      holding the tet) makes the best smallest score, and kept when its tets pay for the cavity's
//      (TetNeeds). The split rounds before this step judge a point by the worst raw quality, so a boundary
//      tet at 11 degrees beside the cavity blocks a point that would lift an interior tet from 12 to 16;
//      here that boundary tet has what it must have. On the ONERA M6 domain this leaves 56 bad interior
//      tets where steps 1 to 3 left 62 (the handle model: 502 against 547).
// What never gets worse: no tet falls under min(its quality, the angle it must reach) nor under the mesh's
// worst at the start (so the smallest and the largest dihedral angle hold), the share of tets under 10
// degrees does not rise, and an edit that adds a severely non-orthogonal face (checkMesh's 70 degrees)
// where it works is undone. So the step runs last, after the orthogonality moves, and leaves every figure
// they reported as good or better. The work follows the bad interior tets, not the mesh (one sweep finds
// them); one edit after another in slot order, so the mesh is the same for any thread count. Locked
// vertices (constrained faces, the caller's) never move and are never removed: the boundary is kept
// exactly.
#pragma once

#include "Progress.h"
#include "Status.h"
#include "TetEditor.h"
#include "TetNeeds.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

struct InteriorPolishOptions
{
  double interiorDegrees = kInteriorDegrees; // every dihedral angle of a tet with no boundary vertex in [this, 180 - this]
  double boundaryDegrees = 10; // what a tet touching the boundary must keep when it has it
  int passes = 4;              // sweeps over the bad interior tets while one moves a vertex
  int threads = 0;             // the first sweep for bad tets (ParallelFor.h's rule; same mesh for any count)
};

struct InteriorPolishReport
{
  int64_t before = 0; // interior tets outside the range before the step
  int64_t after = 0;  // and after it
  int64_t moves = 0; // vertex moves and flips
  int64_t flips = 0;
  int64_t collapses = 0;    // vertices removed
  int64_t splits = 0;       // points added
  int64_t severeChange = 0; // severely non-orthogonal faces the step removed (<= 0: it adds none)
  double seconds = 0;
};

// boundaryVertex[v] != 0: v is on the boundary (tets holding it are not interior). locked (optional): more
// vertices that never move (cluster points). The editor's vertex map must be current; it stays so, for the
// points step 4 adds too. The editor's labels (optional, per tet slot: the region) go to each new tet from
// the tets it replaces. Errors: Cancelled (the mesh is valid; the edits made stay).
Status polishInterior(TetEditor& editor, const std::vector<uint8_t>& boundaryVertex,
                      const std::vector<uint8_t>* locked, const InteriorPolishOptions& options,
                      Progress* progress = nullptr, InteriorPolishReport* report = nullptr);

} // namespace volgrid
