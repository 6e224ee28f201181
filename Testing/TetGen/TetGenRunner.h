// TetGen behind a plain interface, so that tetgen.h (which defines REAL and more) stays in one file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid_tetgen
{
struct TetGenResult
{
  bool ok = false;
  std::string error;
  long long tets = 0;
  long long points = 0;
};

// Plain Delaunay tetrahedralization of the points (TetGen switches "Q").
TetGenResult delaunay(const std::vector<double>& xyz);

struct TetGenMesh
{
  bool ok = false;
  std::string error;
  double seconds = 0;
  std::vector<double> points; // TetGen's output points: the input points first, in order
  std::vector<int32_t> tets;  // 4 per tet, reoriented to VolGrid's positive convention
};

// Boundary-conforming mesh of a closed triangle surface with the given switches (e.g. "pYQ"): every
// triangle is a facet. TetGen aborts are caught and reported in `error`.
TetGenMesh meshSurface(const std::vector<double>& points, const std::vector<int32_t>& triangles, const char* switches);
} // namespace volgrid_tetgen
