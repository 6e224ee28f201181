#include "SurfaceFile.h"

#include "CliSupport.h"

#include "VolGridSurfaceConversion.h"
#include "XmlDataFiles.h"

#include "AtomicFile.h"
#include "GzipFile.h"
#include "SurfaceReader.h"

#include "vtkCellArray.h"
#include "vtkDataSet.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLWriter.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

namespace volgrid
{
namespace
{
// Empty when `path` is a regular file that opens; otherwise the reason, in the user's terms.
std::string unreadableReason(const std::string& path)
{
  struct stat st
  {
  };
  if (::stat(path.c_str(), &st) != 0)
    return std::string("cannot open the file: ") + std::strerror(errno);
  if (S_ISDIR(st.st_mode))
    return "is a directory, not a surface file";
  if (!S_ISREG(st.st_mode))
    return "is not a regular file (a device, pipe or socket)";
  std::ifstream in(path, std::ios::binary);
  return in ? std::string() : std::string("cannot open the file: ") + std::strerror(errno);
}

bool vtkReadFormat(const std::string& ext)
{
  return ext == "vtp" || ext == "vtk";
}

// VTK's readers want a file name: a compressed .vtp/.vtk is decompressed into a private temporary
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
    // write() moves at most about 2 GiB per call: loop until everything is written.
    size_t done = 0;
    int writeErrno = 0;
    while (done < text.size())
    {
      const ssize_t n = ::write(fd, text.data() + done, std::min<size_t>(text.size() - done, size_t(1) << 30));
      if (n < 0 && errno == EINTR)
        continue;
      if (n <= 0)
      {
        writeErrno = n < 0 ? errno : EIO;
        break;
      }
      done += static_cast<size_t>(n);
    }
    if (::close(fd) != 0 && writeErrno == 0)
      writeErrno = errno;
    if (writeErrno != 0)
      return Status::failure(ErrorKind::InvalidOption,
                             gzPath + ": writing the decompressed temporary file '" + name +
                               "' failed: " + std::strerror(writeErrno));
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
  if (ext == "ply")
  {
    vtkNew<vtkPLYReader> r;
    r->SetFileName(readPath.c_str());
    r->Update();
    data = r->GetOutput();
    format = "PLY";
  }
  else if (ext == "vtp")
  {
    std::string ignored; // the caller names the file in its own message
    data = cli::readXmlDataSet(readPath, ignored);
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
    return Status::failure(ErrorKind::EmptyInput,
                           path + ": no points could be read (unreadable, empty or not a surface)");
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

// OFF text (points and polygons), built in memory and written atomically.
bool writeOff(const std::string& path, vtkPolyData* surface, std::string& error)
{
  std::ostringstream os;
  os.precision(17);
  vtkPoints* points = surface->GetPoints();
  const vtkIdType np = points ? points->GetNumberOfPoints() : 0;
  vtkCellArray* polys = surface->GetPolys();
  os << "OFF\n" << np << " " << polys->GetNumberOfCells() << " 0\n";
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    os << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  vtkIdType n;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    os << n;
    for (vtkIdType k = 0; k < n; ++k)
      os << " " << ids[k];
    os << "\n";
  }
  return writeFileAtomically(path, os.str(), error);
}

// Legacy VTK (binary), built in memory and written atomically.
bool writeLegacyVtk(const std::string& path, vtkPolyData* surface, std::string& error)
{
  vtkNew<vtkPolyDataWriter> w;
  w->WriteToOutputStringOn();
  w->SetInputData(surface);
  w->SetFileTypeToBinary();
  if (w->Write() != 1)
  {
    error = "cannot write '" + path + "': VTK could not encode the surface";
    return false;
  }
  const std::string bytes(w->GetOutputString(), static_cast<size_t>(w->GetOutputStringLength()));
  return writeFileAtomically(path, bytes, error);
}

// Binary STL: vtkSTLWriter writes the temporary by name; its size (84 + 50 per triangle) is checked.
bool writeBinaryStl(const std::string& path, vtkPolyData* surface, std::string& error)
{
  AtomicFile file;
  if (!file.open(path, error))
    return false;
  vtkNew<vtkSTLWriter> w;
  w->SetFileName(file.temporaryPath().c_str());
  w->SetInputData(surface);
  w->SetFileTypeToBinary();
  if (w->Write() != 1 || w->GetErrorCode() != 0)
  {
    error = "writing '" + path + "' failed (disk full or not writable?); the earlier file, if any, is unchanged";
    return false;
  }
  long long triangles = 0;
  bool allTriangles = surface->GetNumberOfStrips() == 0;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); allTriangles && polys->GetNextCell(n, ids);)
    allTriangles = n == 3, ++triangles;
  return file.commit(error, allTriangles ? 84 + 50 * triangles : -1);
}
} // namespace

std::string surfaceFileExtension(const std::string& path)
{
  return cli::lowerExtension(path);
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
    return Status::failure(
      ErrorKind::InvalidOption,
      path +
        ": unknown surface file type (expected .off .mesh .poly .smesh .msh .stl .obj .ply .vtp .vtk, or one "
        "of them gzip-compressed as .gz)");
  }
  const std::string unreadable = unreadableReason(path);
  if (!unreadable.empty())
  {
    return Status::failure(ErrorKind::InvalidOption, path + ": " + unreadable);
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
  if (ext == "vtp")
    return cli::writeXmlDataSet(path, surface, error);
  if (ext == "vtk")
    return writeLegacyVtk(path, surface, error);
  if (ext == "stl")
    return writeBinaryStl(path, surface, error);
  if (ext == "off")
    return writeOff(path, surface, error);
  error = "unknown output type '." + ext + "' (expected vtp, vtk, stl or off)";
  return false;
}
} // namespace volgrid
