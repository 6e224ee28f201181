// Exact orient3d / insphere in fixed-width integer arithmetic, for inputs whose coordinates span a
// narrow binary exponent range (internal to the predicates; see PredicatesFixed.cxx for the bounds).
//
// Every finite double is an integer multiple of 2^low, low the exponent of its least significant set
// bit. When all coordinates of one call, divided by the common 2^low (the smallest such exponent over
// the call), are integers of magnitude < 2^61, the determinants are evaluated exactly on those integers
// with 64-bit differences, 128-bit 2x2 minors and 192/320-bit products and sums. The sign of a
// determinant that is homogeneous in the coordinate differences does not change under the positive
// scaling by 2^-low, so the result is the exact sign for the input doubles. Otherwise (exponent spread
// too wide, subnormal coordinates) the functions return false and the caller uses the expansion path.
//
// This is the common case of real meshes (coordinates of one bounding box, no values many orders of
// magnitude smaller than the box unless exactly zero) and in particular of structured grids with
// non-dyadic spacing (x0 + i h), whose exactly cospherical / coplanar configurations make the floating
// filters fail and would otherwise go to the full expansion evaluation from raw coordinates.
#pragma once

#include <cstdint>

namespace volgrid
{
namespace predicates
{
namespace fixedpoint
{

// Sign of det[b-a; c-a; d-a] in *sign; false (and *sign untouched) when the inputs do not fit.
bool orient3d(const double* a, const double* b, const double* c, const double* d, int* sign);

// insphere(a,b,c,d,e) (Predicates.h convention: -sign of det[p - e, |p - e|^2]) in *sign; false when the
// inputs do not fit.
bool insphere(const double* a, const double* b, const double* c, const double* d, const double* e, int* sign);

// The integer images of n <= 5 points at one common power-of-two scale (every |coordinate| < 2^61), for
// callers that evaluate several determinants of the same points (the SoS tie-break); false when the
// points do not fit.
bool toFixed(const double* const* pts, int n, int64_t (*out)[3]);
// Sign of det[b-a; c-a; d-a] of integer images from toFixed.
int orient3dFixed(const int64_t* a, const int64_t* b, const int64_t* c, const int64_t* d);

} // namespace fixedpoint
} // namespace predicates
} // namespace volgrid
