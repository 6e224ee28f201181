// Reading a surface by file extension; each format has its own file (OffReader, MeditReader,
// TetGenPolyReader, GmshReader, StlReader, PlyReader), the shared parsing helpers are in
// SurfaceReaderSupport, polygon triangulation in PolygonTriangulation. A trailing ".gz" is transparent:
// lowerExtension skips it and loadFile decompresses (GzipFile).
#include "SurfaceReader.h"
#include "GmshReader.h"
#include "MeditReader.h"
#include "ObjReader.h"
#include "OffReader.h"
#include "PlyReader.h"
#include "StlReader.h"
#include "SurfaceReaderSupport.h"
#include "TetGenPolyReader.h"

#include <string>

namespace volgrid
{

using namespace detail;

bool surfaceReaderSupports(const std::string& path)
{
  const std::string ext = lowerExtension(path);
  return ext == "off" || ext == "mesh" || ext == "poly" || ext == "smesh" || ext == "msh" || ext == "stl" ||
    ext == "ply" || ext == "obj";
}

Status readSurface(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info, const SurfaceReadOptions& options)
{
  const std::string ext = lowerExtension(path);
  if (ext == "off")
  {
    return readOFF(path, mesh, info, options);
  }
  if (ext == "mesh")
  {
    return readMedit(path, mesh, info, options);
  }
  if (ext == "poly" || ext == "smesh")
  {
    return readTetGen(path, mesh, info, options);
  }
  if (ext == "msh")
  {
    return readGmsh(path, mesh, info, options);
  }
  if (ext == "stl")
  {
    return readSTL(path, mesh, info, options);
  }
  if (ext == "ply")
  {
    return readPLY(path, mesh, info, options);
  }
  if (ext == "obj")
  {
    return readOBJ(path, mesh, info, options);
  }
  return readError(path, 0,
                   "unsupported file extension '." + ext +
                     "' (supported: .off .mesh .poly .smesh .msh .stl .ply .obj, each also gzip-compressed as .gz)");
}

} // namespace volgrid
