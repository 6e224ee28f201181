// TetGen writer: STEM.node (points), STEM.ele (tets with the region label as attribute) and STEM.face
// (boundary triangles with the patch label as marker), 1-based. Names are not part of the format.
#include "MeshWriter.h"
#include "OutputFile.h"

#include <cinttypes>
#include <cstdio>

namespace volgrid
{
std::string tetgenStem(const std::string& path)
{
  for (const char* ext : { ".node", ".ele", ".face" })
  {
    const std::string e(ext);
    if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
      return path.substr(0, path.size() - e.size());
  }
  return path;
}

Status writeTetGen(const std::string& path, const SolverMesh& mesh)
{
  const std::string stem = tetgenStem(path);
  OutputFile node, ele, face;
  Status s = node.open(stem + ".node");
  if (s.ok())
    s = ele.open(stem + ".ele");
  if (s.ok())
    s = face.open(stem + ".face");
  if (!s.ok())
    return s;
  std::fprintf(node.stream(), "%" PRId64 " 3 0 0\n", mesh.numberOfPoints());
  for (int64_t i = 0; i < mesh.numberOfPoints(); ++i)
  {
    const double* p = mesh.points.data() + 3 * i;
    std::fprintf(node.stream(), "%" PRId64 " %.17g %.17g %.17g\n", i + 1, p[0], p[1], p[2]);
  }
  std::fprintf(ele.stream(), "%" PRId64 " 4 1\n", mesh.numberOfTets());
  for (int64_t t = 0; t < mesh.numberOfTets(); ++t)
  {
    const int32_t* v = mesh.tets.data() + 4 * t;
    std::fprintf(ele.stream(), "%" PRId64 " %d %d %d %d %d\n", t + 1, v[0] + 1, v[1] + 1, v[2] + 1, v[3] + 1,
                 mesh.tetRegion[t]);
  }
  std::fprintf(face.stream(), "%" PRId64 " 1\n", mesh.numberOfTriangles());
  for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
  {
    const int32_t* v = mesh.triangles.data() + 3 * t;
    std::fprintf(face.stream(), "%" PRId64 " %d %d %d %d\n", t + 1, v[0] + 1, v[1] + 1, v[2] + 1,
                 mesh.trianglePatch[t]);
  }
  s = node.commit();
  if (s.ok())
    s = ele.commit();
  if (s.ok())
    s = face.commit();
  return s;
}

} // namespace volgrid
