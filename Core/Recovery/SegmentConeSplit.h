// Recovery of a missing segment by Steiner points on it whose pieces become edges at once.
//
// The open segment ab crosses a chain of tets t_1 .. t_K (t_1 has vertex a, t_K vertex b), consecutive
// ones sharing the face the segment crosses. One step replaces a prefix of the chain by cones so that a
// piece of ab starting at a becomes an edge:
//   - the whole chain at once, by the cone from a or from b over its faces: ab is recovered;
//   - else a prefix t_1 .. t_j, with E the point where ab crosses the face between t_j and t_j+1: the
//     cone from a over the prefix with that face split in three at E (and t_j+1 coned from E), or the
//     cone from E over t_1 .. t_j+1. The piece aE is an edge; the longest j that works is taken.
// A cone may take in tets beyond the chain across faces its apex does not see (up to a few dozen, never
// across a constraint face); it is valid when every cone tet is positively oriented (exact orient3d), no
// vertex or constraint edge vanishes inside it, and no new edge joins two points of the segment's line
// other than consecutive ones (onLine: a, b, the input edge's end points and its other Steiner points).
// The caller repeats the step from E. A one-tet prefix coned from a is valid whenever E lies in the open
// crossed face, so each step advances; long needles crossing dozens of tets take a handful of points
// instead of the one per crossed face of the paper's "points at the intersections of the missing edge
// with the tets". E is the rounded intersection (just off the exact line): validity never depends on
// that, only on the exact signs.
//
// Not handled (Failed, mesh untouched): the segment passing through an edge or a vertex of the mesh, a
// crossed face that is a constraint, no valid cone after rounding.
#pragma once

#include "BoundaryRecovery.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace volgrid
{

enum class ConeStep
{
  Failed,    // mesh untouched
  Recovered, // ab is an edge now
  Advanced   // *newPoint was added on ab and a-newPoint is an edge; the rest (newPoint-b) is still missing
};

// One step from a (see above). The caller registers the new point (vertex kind, subfaces) and goes on
// from it.
ConeStep coneStepAlongSegment(MeshEditor& editor, const BoundaryConstraints& bc, int32_t a, int32_t b,
                              const std::function<bool(int32_t)>& onLine, int32_t* newPoint);

} // namespace volgrid
