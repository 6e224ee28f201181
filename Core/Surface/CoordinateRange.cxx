#include "CoordinateRange.h"

#include <cmath>
#include <cstdio>

namespace volgrid
{

Status checkCoordinateRange(const SurfaceMesh& surface, const std::string& what)
{
  char text[256];
  for (int32_t i = 0; i < surface.numberOfPoints(); ++i)
  {
    const double* p = surface.point(i);
    const double largest = std::fmax(std::fabs(p[0]), std::fmax(std::fabs(p[1]), std::fabs(p[2])));
    if (largest > kMaxCoordinateMagnitude)
    {
      std::snprintf(
        text, sizeof text,
        ": point %d has a coordinate of magnitude %.3g; coordinates up to %.0e are supported (sizes and volumes "
        "would overflow): scale the model down",
        static_cast<int>(i), largest, kMaxCoordinateMagnitude);
      return Status::failure(ErrorKind::InvalidOption, what + text, { i });
    }
  }
  const BoundingBox box = boundingBox(surface, true);
  const double extent = box.valid ? box.diagonal() : 0;
  if (box.valid && extent < kMinModelExtent)
  {
    std::snprintf(
      text, sizeof text,
      ": the model is only %.3g across; at least %.0e is needed (sizes and volumes would underflow): scale it up",
      extent, kMinModelExtent);
    return Status::failure(ErrorKind::InvalidOption, what + text);
  }
  return Status::success();
}

} // namespace volgrid
