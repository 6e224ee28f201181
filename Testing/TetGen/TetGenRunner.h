// TetGen behind a plain interface, so that tetgen.h (which defines REAL and more) stays in one file.
#pragma once

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
} // namespace volgrid_tetgen
