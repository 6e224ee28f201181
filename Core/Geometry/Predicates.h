// Exact geometric predicates: the only place in Core where floating-point numbers decide topology.
//
// Each predicate first evaluates the determinant in plain double precision with a static/semi-static
// error bound; when the sign is not certain it re-evaluates exactly with floating-point expansion
// arithmetic (ExpansionArithmetic.h). The results are therefore the signs of the exact determinants
// of the input doubles, for any input (no tolerance, no epsilon).
//
// Conventions (all signs are -1, 0 or +1):
//   orient3d(a,b,c,d)   = sign of det[b-a; c-a; d-a] = sign of the signed volume of tetrahedron (a,b,c,d):
//                         +1 when d lies on the side the right-hand normal (b-a)x(c-a) points to.
//   insphere(a,b,c,d,e) = +1 when e is strictly inside the circumsphere of the positively oriented
//                         tetrahedron (a,b,c,d), -1 strictly outside, 0 on it. (For a negatively oriented
//                         tetrahedron the sign flips.)
//   The *SoS variants never return 0: ties are broken by Simulation of Simplicity with the caller's
//   global point ids, so the Delaunay triangulation of any input (cospherical grids included) is unique
//   and independent of insertion order.
//   SoS rule: point i is lifted to |p_i|^2 + eps^(r_i), r_i the rank of id_i in decreasing order (the
//   largest id gets the largest perturbation); on an exact tie the answer is minus the sign of the
//   lifted-column cofactor, in det[p_i, |p_i|^2, 1] (i = a..e), of the largest id whose cofactor is
//   nonzero (e.g. if e has the largest id, e is outside).
//
// Hot loops may include PredicatesInline.h for inline versions of the filtered fast paths (same results).
#pragma once

#include <cstdint>

namespace volgrid
{
namespace predicates
{

int orient3d(const double* a, const double* b, const double* c, const double* d);
int insphere(const double* a, const double* b, const double* c, const double* d, const double* e);

// insphere with the lifting perturbation |p_i|^2 + eps^(rank of id_i): never 0 when (a,b,c,d) is not flat.
// The ids must be distinct. Requires orient3d(a,b,c,d) != 0.
int insphereSoS(const double* a, const double* b, const double* c, const double* d, const double* e, int64_t ida,
                int64_t idb, int64_t idc, int64_t idd, int64_t ide);

// 2D in-circle test of d against triangle abc, all four points coplanar in 3D (used for degenerate hull
// faces). +1 when d is strictly inside the circumcircle of abc (whatever the orientation of abc), -1
// outside, 0 on it; 0 as well when a, b, c are collinear.
int incircle3d(const double* a, const double* b, const double* c, const double* d);

// Orientation of the projection of a,b,c onto the coordinate plane that drops axis `dropAxis` (0,1,2).
// The projected frame is (u, v) = ((k+1)%3, (k+2)%3), k = dropAxis, so the result is the sign of the
// k-th component of (b-a)x(c-a).
int orient2dProjected(const double* a, const double* b, const double* c, int dropAxis);

} // namespace predicates
} // namespace volgrid
