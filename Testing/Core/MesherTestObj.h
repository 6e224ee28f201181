// Minimal OBJ reader for the Core tests (Core has no OBJ reader: the CLI reads OBJ through VTK).
// v and f records only; polygons are fan-triangulated; v/vt/vn and negative indices accepted.
#pragma once

#include "SurfaceMesh.h"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace volgrid
{
namespace testshapes
{

inline bool readObj(const std::string& path, SurfaceMesh& m)
{
  std::ifstream in(path);
  if (!in)
    return false;
  m.clear();
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v")
    {
      double x = 0, y = 0, z = 0;
      ls >> x >> y >> z;
      m.addPoint(x, y, z);
    }
    else if (tag == "f")
    {
      std::vector<int32_t> ids;
      std::string tok;
      while (ls >> tok)
      {
        const long v = std::stol(tok.substr(0, tok.find('/')));
        ids.push_back(static_cast<int32_t>(v < 0 ? m.numberOfPoints() + v : v - 1));
      }
      for (size_t k = 2; k < ids.size(); ++k)
        m.addTriangle(ids[0], ids[k - 1], ids[k]);
    }
  }
  return true;
}

} // namespace testshapes
} // namespace volgrid
