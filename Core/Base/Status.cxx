#include "Status.h"

namespace volgrid
{

const char* errorKindName(ErrorKind kind)
{
  switch (kind)
  {
    case ErrorKind::None:
      return "none";
    case ErrorKind::EmptyInput:
      return "empty input";
    case ErrorKind::NonFinitePoint:
      return "non-finite point";
    case ErrorKind::DegenerateInput:
      return "degenerate input";
    case ErrorKind::InvalidOption:
      return "invalid option";
    case ErrorKind::OpenSurface:
      return "open surface";
    case ErrorKind::NonManifoldEdge:
      return "non-manifold edge";
    case ErrorKind::DegenerateTriangle:
      return "degenerate triangle";
    case ErrorKind::DuplicateTriangle:
      return "duplicate triangle";
    case ErrorKind::SelfIntersection:
      return "self-intersection";
    case ErrorKind::IntersectingShells:
      return "intersecting shells";
    case ErrorKind::RecoveryFailed:
      return "boundary recovery failed";
    case ErrorKind::Cancelled:
      return "cancelled";
    case ErrorKind::InternalError:
      return "internal error";
  }
  return "unknown";
}

} // namespace volgrid
