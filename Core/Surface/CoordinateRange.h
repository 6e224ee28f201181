// The coordinate range the mesher handles without overflow or underflow. The predicates are exact for any
// doubles, but sizes, volumes and quality measures are products of coordinate differences, and some
// summaries pass through single precision: measured on an octahedron, dihedral summaries go wrong past
// |x| = 1e39 or below an extent of 1e-39 (float's range), and from 1e100 field points were silently dropped
// and volumes became NaN. The supported range keeps a margin: |x| <= 1e30 and an extent >= 1e-30. Inputs
// outside are refused up front with the first point that is outside.
#pragma once

#include "Status.h"
#include "SurfaceMesh.h"

#include <string>

namespace volgrid
{

constexpr double kMaxCoordinateMagnitude = 1e30;
constexpr double kMinModelExtent = 1e-30;

// `what` names the input in the message (the file name). Assumes finite coordinates (the readers check).
Status checkCoordinateRange(const SurfaceMesh& surface, const std::string& what);

} // namespace volgrid
