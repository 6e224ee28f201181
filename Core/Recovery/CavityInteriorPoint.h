// A point strictly inside a cavity, near one of its vertices: where Steiner removal (SteinerRemoval.h)
// puts an interior point when no vertex of the cavity left by a boundary Steiner point p sees all of
// its faces (so that p can leave the boundary: the cavity is filled by the cone from the new point).
#pragma once

#include "TetMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace volgrid
{

class CavityInteriorPoint
{
public:
  explicit CavityInteriorPoint(const TetMesh& mesh)
    : m_(mesh)
  {
  }

  // A point strictly inside the cavity bounded by `faces` (each seen positively from inside), near p.
  // Candidates, best shape first among the valid ones: p pushed along the mean normal of the faces through
  // p (the new boundary triangles), points between p and the cavity's centroid or the old tets'
  // centroids, and the Chebyshev centre of the kernel (the point deepest inside every face plane, found
  // by a small linear programme) with points between it and p. Every candidate is checked exactly.
  bool find(int32_t p, const std::vector<std::array<int32_t, 3>>& faces, double* out);

private:
  // The best-shaped valid candidate among the first four valid ones of cands_.
  bool pickCandidate(const std::vector<std::array<int32_t, 3>>& faces, double* out);
  bool chebyshevCentre(const std::vector<double>& dist, double L, double* y);

  const TetMesh& m_;
  std::vector<std::array<double, 3>> normals_, cands_; // scratch, kept between calls
  std::vector<double> tableau_;
};

} // namespace volgrid
