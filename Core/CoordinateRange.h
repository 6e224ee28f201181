// The coordinate range the mesher handles without overflow or underflow. The predicates are exact for any
// doubles, but sizes, volumes and quality measures are products of up to five coordinate differences:
// past |x| = 1e50 they overflow (field points were silently dropped, volumes became NaN), below an extent
// of 1e-50 they underflow. Inputs outside are refused up front with the first point that is outside.
#pragma once

#include "Status.h"
#include "SurfaceMesh.h"

#include <string>

namespace volgrid
{

constexpr double kMaxCoordinateMagnitude = 1e50;
constexpr double kMinModelExtent = 1e-50;

// `what` names the input in the message (the file name). Assumes finite coordinates (the readers check).
Status checkCoordinateRange(const SurfaceMesh& surface, const std::string& what);

} // namespace volgrid
