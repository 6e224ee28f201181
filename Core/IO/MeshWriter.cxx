// Format choice and dispatch of the solver mesh writers.
#include "MeshWriter.h"

#include <algorithm>
#include <cctype>

namespace volgrid
{
namespace
{
std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool contains(const std::string& text, const char* word)
{
  return lower(text).find(word) != std::string::npos;
}

bool normalized(const std::vector<int32_t>& labels)
{
  const std::vector<int32_t> d = distinctLabels(labels);
  for (size_t k = 0; k < d.size(); ++k)
    if (d[k] != static_cast<int32_t>(k + 1))
      return false;
  return true;
}
} // namespace

MeshFormat meshFormatFromName(const std::string& name)
{
  const std::string n = lower(name);
  if (n == "gmsh" || n == "msh" || n == "gmsh41" || n == "msh41")
    return MeshFormat::Gmsh41;
  if (n == "gmsh22" || n == "msh22" || n == "gmsh2")
    return MeshFormat::Gmsh22;
  if (n == "su2")
    return MeshFormat::SU2;
  if (n == "openfoam" || n == "polymesh" || n == "foam")
    return MeshFormat::OpenFOAM;
  if (n == "medit" || n == "mesh")
    return MeshFormat::Medit;
  if (n == "tetgen")
    return MeshFormat::TetGen;
  if (n == "cgns")
    return MeshFormat::CGNS;
  if (n == "exodus" || n == "exo" || n == "exodusii")
    return MeshFormat::Exodus;
  return MeshFormat::Unknown;
}

MeshFormat meshFormatFromPath(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return MeshFormat::Unknown;
  const std::string ext = lower(path.substr(dot + 1));
  if (ext == "msh")
    return MeshFormat::Gmsh41;
  if (ext == "su2")
    return MeshFormat::SU2;
  if (ext == "mesh")
    return MeshFormat::Medit;
  if (ext == "node" || ext == "ele" || ext == "face")
    return MeshFormat::TetGen;
  if (ext == "cgns")
    return MeshFormat::CGNS;
  if (ext == "exo" || ext == "e" || ext == "ex2")
    return MeshFormat::Exodus;
  return MeshFormat::Unknown;
}

const char* meshFormatName(MeshFormat format)
{
  switch (format)
  {
    case MeshFormat::Gmsh41:
      return "gmsh 4.1";
    case MeshFormat::Gmsh22:
      return "gmsh 2.2";
    case MeshFormat::SU2:
      return "SU2";
    case MeshFormat::OpenFOAM:
      return "OpenFOAM polyMesh";
    case MeshFormat::Medit:
      return "Medit";
    case MeshFormat::TetGen:
      return "TetGen";
    case MeshFormat::CGNS:
      return "CGNS";
    case MeshFormat::Exodus:
      return "Exodus II";
    default:
      return "unknown";
  }
}

bool writesPrisms(MeshFormat format)
{
  return format == MeshFormat::Gmsh41 || format == MeshFormat::Gmsh22 || format == MeshFormat::OpenFOAM ||
    format == MeshFormat::SU2 || format == MeshFormat::Medit || format == MeshFormat::CGNS ||
    format == MeshFormat::Exodus;
}

std::string defaultOpenFoamPatchType(const std::string& name)
{
  if (contains(name, "symmetry"))
    return "symmetryPlane";
  if (contains(name, "farfield") || contains(name, "inlet") || contains(name, "outlet"))
    return "patch";
  return "wall";
}

Status writeSolverMesh(const std::string& path, const SolverMesh& mesh, MeshFormat format,
                       const MeshWriteOptions& options)
{
  std::vector<int32_t> patches = mesh.trianglePatch, regions = mesh.tetRegion;
  patches.insert(patches.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  regions.insert(regions.end(), mesh.prismRegion.begin(), mesh.prismRegion.end());
  regions.insert(regions.end(), mesh.pyramidRegion.begin(), mesh.pyramidRegion.end());
  if (!normalized(patches) || !normalized(regions) || mesh.tetRegion.size() != mesh.tets.size() / 4 ||
      mesh.trianglePatch.size() != mesh.triangles.size() / 3 || mesh.prismRegion.size() != mesh.prisms.size() / 6 ||
      mesh.quadPatch.size() != mesh.quads.size() / 4 || mesh.pyramidRegion.size() != mesh.pyramids.size() / 5)
  {
    SolverMesh copy = mesh;
    normalizeLabels(copy);
    return writeSolverMesh(path, copy, format, options);
  }
  if ((!mesh.prisms.empty() || !mesh.quads.empty() || !mesh.pyramids.empty()) && !writesPrisms(format))
    return Status::failure(ErrorKind::InvalidOption,
                           "'" + path + "': boundary-layer prisms are not written to " + meshFormatName(format) +
                             " (gmsh, OpenFOAM, SU2, Medit, CGNS, Exodus II and VTK take them and their pyramids); "
                             "split them into tets for this format");
  switch (format)
  {
    case MeshFormat::Gmsh41:
      return writeGmsh41(path, mesh);
    case MeshFormat::Gmsh22:
      return writeGmsh22(path, mesh);
    case MeshFormat::SU2:
      return writeSU2(path, mesh);
    case MeshFormat::OpenFOAM:
      return writeOpenFOAM(path, mesh, options);
    case MeshFormat::Medit:
      return writeMedit(path, mesh);
    case MeshFormat::TetGen:
      return writeTetGen(path, mesh);
    case MeshFormat::CGNS:
      return writeCGNS(path, mesh);
    case MeshFormat::Exodus:
      return writeExodus(path, mesh);
    default:
      break;
  }
  return Status::failure(ErrorKind::InvalidOption, "no writer for '" + path + "'");
}

} // namespace volgrid
