#include "TetGenRunner.h"

#include <tetgen.h>

#include <cstring>

namespace volgrid_tetgen
{
TetGenResult delaunay(const std::vector<double>& xyz)
{
  TetGenResult result;
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(xyz.size() / 3);
  in.pointlist = new REAL[xyz.size()]; // freed by tetgenio with delete[]
  std::memcpy(in.pointlist, xyz.data(), xyz.size() * sizeof(double));
  char switches[] = "Q";
  try
  {
    tetrahedralize(switches, &in, &out);
  }
  catch (int code)
  {
    result.error = "TetGen error code " + std::to_string(code);
    return result;
  }
  result.ok = true;
  result.tets = out.numberoftetrahedra;
  result.points = out.numberofpoints;
  return result;
}
} // namespace volgrid_tetgen
