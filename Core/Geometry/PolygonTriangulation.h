// Triangulation of planar polygons in their plane with exact orientation tests (projected orient2d):
// single loops by ear clipping (triangulatePolygon, declared in SurfaceReader.h), loops with holes by
// bridging the holes into the outer loop (PolygonTriangulationHoles.cxx), and TetGen-style facets made
// of several polygons plus hole points (PolygonTriangulationFacet.cxx).
#pragma once

#include <cstdint>
#include <vector>

namespace volgrid
{

// A coordinate plane onto which a (nearly) planar polygon projects without degenerating: the axis
// `drop` is removed and (u, v) = ((drop+1)%3, (drop+2)%3) remain. orient() is exact and positive for a
// counter-clockwise turn in (u, v).
struct ProjectionFrame
{
  int drop = 2;

  // The axis of the largest component of `normal`; false when the normal is zero or not finite.
  bool chooseFrom(const double normal[3]);
  int orient(const double* a, const double* b, const double* c) const;
  // Exact lexicographic (u, v) comparison: a before b.
  bool lessUV(const double* a, const double* b) const;
};

// Newell normal (twice the vector area) of a loop of point ids, added to `normal`.
void addNewellNormal(const std::vector<double>& points, const std::vector<int32_t>& loop, double normal[3]);

// Exact orientation of a simple loop in the frame: +1 counter-clockwise, -1 clockwise, 0 degenerate.
// Decided at the lexicographically lowest corner, which is convex in a simple polygon.
int loopOrientation(const std::vector<double>& points, const std::vector<int32_t>& loop, const ProjectionFrame& frame);

// Ear clipping of `loop` in `frame`, where `sign` (+1/-1) is the loop's orientation there; triangles
// keep the loop's orientation. Ids may repeat (bridged holes). Returns false and appends a fan of what
// is left when no ear exists.
bool earClipPolygon(const std::vector<double>& points, const std::vector<int32_t>& loop, const ProjectionFrame& frame,
                    int sign, std::vector<int32_t>& triangles);

// Triangulates the region inside `outer` and outside every loop of `holes` (simple, disjoint loops
// strictly inside `outer`; any orientations): each hole is joined to the outer boundary by a bridge
// edge that crosses nothing (checked exactly), then the joined loop is ear-clipped. Triangles take the
// orientation of `outer`; every edge of every loop is a triangle edge. Returns false when a hole could
// not be bridged (the hole is then ignored) or ear clipping fell back to a fan.
bool triangulatePolygonWithHoles(const std::vector<double>& points, const std::vector<int32_t>& outer,
                                 const std::vector<std::vector<int32_t>>& holes, const ProjectionFrame& frame,
                                 std::vector<int32_t>& triangles);

struct FacetTriangulationInfo
{
  int64_t regions = 0;          // polygon regions triangulated
  int64_t holeRegions = 0;      // regions removed because a hole point lies in them
  int64_t unusedHolePoints = 0; // hole points outside every polygon of the facet
  int64_t failures = 0;         // regions whose triangulation fell back (bridge or ear clipping failed)
};

// A planar facet given as polygons and hole points, with TetGen's meaning: the polygons split the
// plane into regions (a polygon's region is its inside minus the polygons nested directly in it); a
// region holding a hole point is removed, every other region inside some polygon is triangulated.
// Nesting and hole location are decided with exact point-in-polygon tests in the facet's projection.
// Polygons with fewer than 3 corners are ignored. Each region's triangles take the orientation of the
// polygon bounding it. `holePoints` holds 3 doubles per point. Returns false when any region failed.
bool triangulateFacet(const std::vector<double>& points, const std::vector<std::vector<int32_t>>& polygons,
                      const std::vector<double>& holePoints, std::vector<int32_t>& triangles,
                      FacetTriangulationInfo* info = nullptr);

// Triangulates a planar (or nearly planar) polygon given by point ids of `points` (3 doubles each) by
// ear clipping in the polygon's plane: orientation tests are exact (projected orient2d), and among the
// valid ears the best-shaped one is cut first. Triangles keep the loop's orientation. Returns false
// (and appends a fan for what is left) when no ear exists (self-intersecting or degenerate polygon).
bool triangulatePolygon(const std::vector<double>& points, const std::vector<int32_t>& loop,
                        std::vector<int32_t>& triangles);

} // namespace volgrid
