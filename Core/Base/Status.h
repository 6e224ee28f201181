// A typed result for Core operations that can fail on bad input: what went wrong, a sentence for the
// user, and the first offending ids. The filters turn it into vtkErrorMacro, the CLI into stderr and a
// non-zero exit code.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

enum class ErrorKind
{
  None,
  EmptyInput,
  NonFinitePoint,     // NaN or Inf coordinates
  DegenerateInput,    // fewer than four affinely independent points
  InvalidOption,      // absurd parameter value
  OpenSurface,        // boundary edges (used by one triangle)
  NonManifoldEdge,    // edges used by more than two triangles
  DegenerateTriangle, // zero-area (collinear) triangles
  DuplicateTriangle,  // the same three vertices twice
  SelfIntersection,   // triangles that cross or overlap
  IntersectingShells, // two shells that cross each other
  RecoveryFailed,     // a boundary edge/facet could not be recovered
  Cancelled,          // the user aborted
  InternalError       // an invariant broke: a bug, reported rather than hidden
};

const char* errorKindName(ErrorKind kind);

struct Status
{
  ErrorKind kind = ErrorKind::None;
  std::string message;           // complete sentence: what, how many, where
  std::vector<int64_t> firstIds; // first offending point/triangle ids (at most a handful)

  bool ok() const { return kind == ErrorKind::None; }
  static Status success() { return Status(); }
  static Status failure(ErrorKind k, std::string msg, std::vector<int64_t> ids = {})
  {
    Status s;
    s.kind = k;
    s.message = std::move(msg);
    s.firstIds = std::move(ids);
    return s;
  }
};

} // namespace volgrid
