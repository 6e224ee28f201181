// How small the size may get near a boundary whose own triangles are coarse: a cap on the size (--max-edge)
// below the boundary's spacing cannot be met next to that boundary. A boundary triangle of edge H carries
// one tet, and with interior points a cap's distance away that tet is a flat cap and its neighbours are
// slivers, which no optimisation fixes without touching the boundary. Measured on the ONERA M6 domain
// (far-field triangles of edge 11.5) with --max-edge 1.5: 28,000 of the 37,000 tets under 18 deg at the
// end of the quality stage lay within 2 units of the far field, and they made the stage's rounds slow.
//
// The floor is max over boundary nodes s of (H_s - slope |x - s|): the boundary's spacing, shrinking away
// from it at the gradation's rate, so that the size grades from the boundary's triangles down to the
// cap as it grows elsewhere. It is computed as the gradation limit (limitGradation, a shortest-path
// bound over the background Delaunay of the nodes) of K - H_s, with K above every H_s, and interpolated
// linearly between the nodes.
//
// A node's spacing counts only as far as its cone fits in kFloorShareOfDepth of the domain's depth there
// (the caller lowers it to cap + slope * share * depth): a coarse far field around a small body grades
// down over a thin shell of a large domain, while a box of twelve triangles, as deep as its triangles are
// wide, keeps the cap its user asked for inside it.
#pragma once

#include "SizingField.h"
#include "Status.h"

#include <cstddef>
#include <cstdint>

namespace volgrid
{

inline constexpr double kFloorShareOfDepth = 0.25;

class CoarseBoundaryFloor
{
public:
  // xyz: the nodes (boundary nodes first, then nodes of no size of their own, such as a lattice that
  // lets the floor fall to zero in between); boundarySize: the spacing H at each of the first nBoundary
  // nodes. slope > 0: the gradation's (gradation - 1).
  Status build(const double* xyz, const double* boundarySize, size_t nBoundary, size_t nNodes, double slope);
  // The floor at p (0 where no boundary node reaches); 0 before build. With a hint of the caller's own,
  // as LinearInterpolant::evaluate: callers with hints of their own may query at once.
  double evaluate(const double* p) const;
  double evaluate(const double* p, int32_t& hint) const;
  // The largest boundary spacing: a cap at or above it never meets the floor.
  double largestBoundarySize() const { return largest_; }

private:
  double floorOf(double interpolated) const; // the floor from the interpolated K - floor
  LinearInterpolant field_;                  // K - floor
  double k_ = 0;
  double largest_ = 0;
};

} // namespace volgrid
