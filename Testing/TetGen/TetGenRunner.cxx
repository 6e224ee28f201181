#include "TetGenRunner.h"

#include <tetgen.h>

#include "Predicates.h"

#include <chrono>
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
TetGenMesh meshSurface(const std::vector<double>& points, const std::vector<int32_t>& triangles, const char* switches)
{
  TetGenMesh result;
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size() / 3);
  in.pointlist = new REAL[points.size()];
  std::memcpy(in.pointlist, points.data(), points.size() * sizeof(double));
  in.numberoffacets = static_cast<int>(triangles.size() / 3);
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  for (int f = 0; f < in.numberoffacets; ++f)
  {
    tetgenio::facet& facet = in.facetlist[f];
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    facet.numberofholes = 0;
    facet.holelist = nullptr;
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k)
      facet.polygonlist[0].vertexlist[k] = triangles[3 * f + k];
  }
  std::vector<char> owned(switches, switches + std::strlen(switches) + 1);
  const auto start = std::chrono::steady_clock::now();
  try
  {
    tetrahedralize(owned.data(), &in, &out);
  }
  catch (int code)
  {
    result.error = "TetGen error code " + std::to_string(code);
    return result;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.points.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  result.tets.assign(out.tetrahedronlist, out.tetrahedronlist + 4 * out.numberoftetrahedra);
  // TetGen orients tets the other way round (Shewchuk's orient3d sign): flip if its first tet is
  // negative in VolGrid's convention, so that the checker judges every tet the same way.
  if (!result.tets.empty())
  {
    const int32_t* t = result.tets.data();
    if (volgrid::predicates::orient3d(&result.points[3 * t[0]], &result.points[3 * t[1]], &result.points[3 * t[2]],
                                      &result.points[3 * t[3]]) < 0)
    {
      for (size_t k = 0; k < result.tets.size(); k += 4)
        std::swap(result.tets[k], result.tets[k + 1]);
    }
  }
  result.ok = true;
  return result;
}

} // namespace volgrid_tetgen
