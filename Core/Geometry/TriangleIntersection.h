// Exact triangle-triangle intersection: the primitives behind trianglesIntersect and
// triangleIsDegenerate (below). Every decision is an exact orientation test;
// coplanar cases are decided in the projection that drops one axis. The helpers below are shared with
// the point-in-surface test (ShellNesting.cxx). Internal to Core.
#pragma once

#include <cstdint>

namespace volgrid
{

// True when the closed triangles (p0,p1,p2) and (q0,q1,q2) intersect beyond the corners they share.
// ip/iq are vertex identities (equal ids mean the same vertex; pass distinct ids when nothing is
// shared). Both triangles must be non-degenerate.
bool trianglesIntersect(const double* const p[3], const int32_t ip[3], const double* const q[3], const int32_t iq[3]);

// True when triangle (a,b,c) has zero area (collinear corners), exactly.
bool triangleIsDegenerate(const double* a, const double* b, const double* c);

} // namespace volgrid

namespace volgrid::detail
{

// Axis whose projection keeps triangle (a,b,c) non-degenerate, or -1 when it is collinear.
int projectionAxis(const double* a, const double* b, const double* c);

// Closed point-in-triangle test in the projection dropping `axis`; o = orient2dProjected(a,b,c,axis) != 0.
bool pointInTriangle2(const double* p, const double* a, const double* b, const double* c, int axis, int o);

// Closed segment-triangle test for a segment in the triangle's plane.
bool coplanarSegmentTriangle(const double* p, const double* q, const double* a, const double* b, const double* c);

} // namespace volgrid::detail
