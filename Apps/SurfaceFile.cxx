#include "SurfaceFile.h"

#include "VolGridSurfaceConversion.h"

#include "GzipFile.h"
#include "SurfaceReader.h"

#include "vtkCellArray.h"
#include "vtkDataSet.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLWriter.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace volgrid
{
namespace
{
bool fileReadable(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return static_cast<bool>(in);
}

bool vtkReadFormat(const std::string& ext)
{
  return ext == "obj" || ext == "ply" || ext == "vtp" || ext == "vtk";
}

// VTK's readers want a file name: a compressed .obj/.vtp/.vtk is decompressed into a private temporary
// file with the same inner extension, removed when this goes out of scope.
class DecompressedCopy
{
public:
  Status create(const std::string& gzPath, const std::string& ext)
  {
    std::string text;
    Status status = readGzipFile(gzPath, text);
    if (!status.ok())
      return status;
    std::string name = (std::filesystem::temp_directory_path() / "volgrid-gunzip-XXXXXX.").string() + ext;
    const int fd = mkstemps(name.data(), static_cast<int>(ext.size() + 1));
    if (fd < 0)
      return Status::failure(ErrorKind::InvalidOption, gzPath + ": cannot create a temporary file to decompress into");
    Path = name;
    const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    if (::close(fd) != 0 || !written)
      return Status::failure(ErrorKind::InvalidOption, gzPath + ": writing the decompressed temporary file failed");
    return Status::success();
  }
  ~DecompressedCopy()
  {
    if (!Path.empty())
      std::remove(Path.c_str());
  }
  const std::string& path() const { return Path; }

private:
  std::string Path;
};

// `path` names the file in messages; `readPath` is the file VTK reads (a decompressed copy or path).
Status readWithVtk(const std::string& path, const std::string& readPath, const std::string& ext, SurfaceMesh& mesh,
  std::string& info)
{
  vtkSmartPointer<vtkDataObject> data;
  std::string format;
  if (ext == "obj")
  {
    vtkNew<vtkOBJReader> r;
    r->SetFileName(readPath.c_str());
    r->Update();
    data = r->GetOutput();
    format = "OBJ";
  }
  else if (ext == "ply")
  {
    vtkNew<vtkPLYReader> r;
    r->SetFileName(readPath.c_str());
    r->Update();
    data = r->GetOutput();
    format = "PLY";
  }
  else if (ext == "vtp")
  {
    vtkNew<vtkXMLPolyDataReader> r;
    r->SetFileName(readPath.c_str());
    r->Update();
    data = r->GetOutput();
    format = "VTK XML poly data";
  }
  else
  {
    vtkNew<vtkGenericDataObjectReader> r;
    r->SetFileName(readPath.c_str());
    r->Update();
    data = r->GetOutput();
    format = "legacy VTK";
  }
  vtkDataSet* surface = vtkDataSet::SafeDownCast(data);
  VolGridSurfaceConversionInfo conversion;
  if (!surface || surface->GetNumberOfPoints() == 0)
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": no points could be read (unreadable, empty or not a surface)");
  }
  if (!VolGridPolyDataToSurfaceMesh(surface, mesh, &conversion))
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": the file has no triangles, quads or polygons");
  }
  std::ostringstream os;
  os << format << ", " << surface->GetNumberOfPoints() << " points, " << surface->GetNumberOfCells() << " cells";
  if (conversion.polygons)
    os << ", " << conversion.polygons << " polygons triangulated";
  if (conversion.strips)
    os << ", " << conversion.strips << " strips";
  if (conversion.skippedCells)
    os << ", " << conversion.skippedCells << " non-surface cells skipped";
  if (conversion.invalidCells)
    os << ", " << conversion.invalidCells << " cells with bad point ids skipped";
  info = os.str();
  return Status::success();
}

bool writeOff(const std::string& path, vtkPolyData* surface, std::string& error)
{
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f)
  {
    error = "cannot open '" + path + "' for writing";
    return false;
  }
  vtkPoints* points = surface->GetPoints();
  const vtkIdType np = points ? points->GetNumberOfPoints() : 0;
  vtkCellArray* polys = surface->GetPolys();
  std::fprintf(f, "OFF\n%lld %lld 0\n", static_cast<long long>(np), static_cast<long long>(polys->GetNumberOfCells()));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    std::fprintf(f, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
  }
  vtkIdType n;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    std::fprintf(f, "%lld", static_cast<long long>(n));
    for (vtkIdType k = 0; k < n; ++k)
      std::fprintf(f, " %lld", static_cast<long long>(ids[k]));
    std::fprintf(f, "\n");
  }
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok)
  {
    error = "writing '" + path + "' failed";
    return false;
  }
  return true;
}
} // namespace

std::string surfaceFileExtension(const std::string& path)
{
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool surfaceFileSupported(const std::string& path)
{
  return surfaceReaderSupports(path) || vtkReadFormat(surfaceFileExtension(stripGzipSuffix(path)));
}

Status readAnySurface(const std::string& path, SurfaceMesh& mesh, std::string& info)
{
  return readAnySurface(path, mesh, info, true);
}

Status readAnySurface(const std::string& path, SurfaceMesh& mesh, std::string& info, bool mergeCoincidentPoints)
{
  mesh.clear();
  info.clear();
  if (!surfaceFileSupported(path))
  {
    return Status::failure(ErrorKind::InvalidOption,
      path + ": unknown surface file type (expected .off .mesh .poly .smesh .msh .stl .obj .ply .vtp .vtk, or one "
             "of them gzip-compressed as .gz)");
  }
  if (!fileReadable(path))
  {
    return Status::failure(ErrorKind::InvalidOption, path + ": cannot open the file");
  }
  if (surfaceReaderSupports(path))
  {
    SurfaceReadInfo readInfo;
    SurfaceReadOptions options;
    options.mergeCoincidentPoints = mergeCoincidentPoints;
    const Status status = readSurface(path, mesh, &readInfo, options);
    if (!status.ok())
      return status;
    std::ostringstream os;
    os << readInfo.format << ", " << readInfo.fileFaces << " faces";
    if (readInfo.polygonFaces)
      os << ", " << readInfo.polygonFaces << " polygons triangulated";
    if (readInfo.holeRegions)
      os << ", " << readInfo.holeRegions << " facet hole(s) cut out";
    if (readInfo.mergedPoints)
      os << ", " << readInfo.mergedPoints << " coincident points merged";
    if (readInfo.skippedElements)
      os << ", " << readInfo.skippedElements << " other elements skipped";
    for (const std::string& w : readInfo.warnings)
      os << "; " << w;
    info = os.str();
  }
  else
  {
    const std::string ext = surfaceFileExtension(stripGzipSuffix(path));
    DecompressedCopy copy;
    if (isGzipPath(path))
    {
      const Status status = copy.create(path, ext);
      if (!status.ok())
        return status;
    }
    const Status status = readWithVtk(path, isGzipPath(path) ? copy.path() : path, ext, mesh, info);
    if (!status.ok())
      return status;
    // vtkOBJReader duplicates a point for each texture coordinate or normal it is used with: merging is
    // needed to recover the file's connectivity.
    if (mergeCoincidentPoints || ext == "obj")
    {
      const MergeResult merged = volgrid::mergeCoincidentPoints(mesh);
      if (merged.mergedPoints)
        info += ", " + std::to_string(merged.mergedPoints) + " coincident points merged";
    }
  }
  if (mesh.numberOfTriangles() == 0)
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": the file has no triangles");
  }
  return Status::success();
}

bool writeSurfaceFile(const std::string& path, vtkPolyData* surface, std::string& error)
{
  const std::string ext = surfaceFileExtension(path);
  int ok = 0;
  if (ext == "vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetFileName(path.c_str());
    w->SetInputData(surface);
    // Binary (base64 inline), not raw appended: Debian 12's ParaView 5.11 cannot read raw appended data back.
    w->SetDataModeToBinary();
    ok = w->Write();
  }
  else if (ext == "vtk")
  {
    vtkNew<vtkPolyDataWriter> w;
    w->SetFileName(path.c_str());
    w->SetInputData(surface);
    w->SetFileTypeToBinary();
    ok = w->Write();
  }
  else if (ext == "stl")
  {
    vtkNew<vtkSTLWriter> w;
    w->SetFileName(path.c_str());
    w->SetInputData(surface);
    w->SetFileTypeToBinary();
    ok = w->Write();
  }
  else if (ext == "off")
  {
    return writeOff(path, surface, error);
  }
  else
  {
    error = "unknown output type '." + ext + "' (expected vtp, vtk, stl or off)";
    return false;
  }
  if (!ok)
  {
    error = "writing '" + path + "' failed";
    return false;
  }
  return true;
}
} // namespace volgrid
