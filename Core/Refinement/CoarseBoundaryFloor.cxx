#include "CoarseBoundaryFloor.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace volgrid
{

Status CoarseBoundaryFloor::build(const double* xyz, const double* boundarySize, size_t nBoundary, size_t nNodes,
                                  double slope)
{
  largest_ = 0;
  for (size_t i = 0; i < nBoundary; ++i)
    if (std::isfinite(boundarySize[i]))
      largest_ = std::max(largest_, boundarySize[i]);
  // K - H must stay positive (limitGradation and the interpolant take positive values only); the nodes
  // without a size start far above K, so the floor there is what the boundary's cones give (or 0).
  k_ = 2 * largest_ + 1;
  std::vector<double> values(nNodes, 4 * k_);
  for (size_t i = 0; i < nBoundary; ++i)
    if (std::isfinite(boundarySize[i]) && boundarySize[i] > 0)
      values[i] = k_ - boundarySize[i];
  // Coincident nodes keep the smallest value: the largest spacing, as the max over cones wants.
  Status s = field_.build(xyz, nNodes, values.data());
  if (!s.ok())
    return s;
  if (!field_.degenerate())
    limitGradation(field_.mesh(), slope, field_.values());
  return Status::success();
}

double CoarseBoundaryFloor::evaluate(const double* p) const
{
  if (field_.empty())
    return 0;
  return floorOf(field_.evaluate(p));
}

double CoarseBoundaryFloor::evaluate(const double* p, int32_t& hint) const
{
  if (field_.empty())
    return 0;
  return floorOf(field_.evaluate(p, hint));
}

double CoarseBoundaryFloor::floorOf(double interpolated) const
{
  return std::isfinite(interpolated) ? std::max(0.0, k_ - interpolated) : 0;
}

} // namespace volgrid
