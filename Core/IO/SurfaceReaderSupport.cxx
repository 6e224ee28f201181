#include "SurfaceReaderSupport.h"

#include "GzipFile.h"
#include "PolygonTriangulation.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <sstream>

namespace volgrid::detail
{

std::string lowerExtension(const std::string& gzPath)
{
  const std::string path = stripGzipSuffix(gzPath);
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  std::string ext = path.substr(dot + 1);
  for (char& c : ext)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return ext;
}

Status readError(const std::string& path, int64_t line, const std::string& what)
{
  std::ostringstream os;
  os << path;
  if (line > 0)
  {
    os << ":" << line;
  }
  os << ": " << what;
  return Status::failure(ErrorKind::InvalidOption, os.str());
}

Status checkRegularFile(const std::string& path)
{
  struct stat st
  {
  };
  if (::stat(path.c_str(), &st) != 0)
  {
    return readError(path, 0, std::string("cannot open the file: ") + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode))
  {
    return readError(path, 0, "is a directory, not a file");
  }
  if (!S_ISREG(st.st_mode))
  {
    return readError(path, 0, "is not a regular file (a device, pipe or socket)");
  }
  return Status::success();
}

int64_t fileSize(const std::string& path)
{
  struct stat st
  {
  };
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) ? static_cast<int64_t>(st.st_size) : -1;
}

ReadStart::ReadStart(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const char* format)
  : info(infoOut ? *infoOut : Own)
{
  mesh.clear();
  this->info = SurfaceReadInfo();
  this->info.format = format;
  this->loaded = loadFile(path, this->text);
}

Status loadFile(const std::string& path, std::string& text)
{
  Status s = checkRegularFile(path);
  if (!s.ok())
  {
    return s;
  }
  if (isGzipPath(path))
  {
    return readGzipFile(path, text);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return readError(path, 0, std::string("cannot open the file: ") + std::strerror(errno));
  }
  const int64_t size = fileSize(path);
  if (size < 0)
  {
    return readError(path, 0, "cannot determine the file size");
  }
  try
  {
    text.resize(static_cast<size_t>(size));
  }
  catch (const std::bad_alloc&)
  {
    return readError(path, 0, "not enough memory to load the file (" + std::to_string(size) + " bytes)");
  }
  // istream::read takes a streamsize: read in pieces, so that files over 2 GiB load whole.
  size_t done = 0;
  while (done < text.size())
  {
    const size_t piece = std::min<size_t>(text.size() - done, size_t(1) << 30);
    if (!in.read(&text[done], static_cast<std::streamsize>(piece)))
    {
      return readError(path, 0, "read error after " + std::to_string(done + in.gcount()) + " bytes");
    }
    done += piece;
  }
  return Status::success();
}

bool parseDouble(std::string_view tok, double& value)
{
  if (!tok.empty() && tok[0] == '+')
  {
    tok.remove_prefix(1);
  }
  if (tok.empty())
  {
    return false;
  }
  const char* end = tok.data() + tok.size();
  auto r = std::from_chars(tok.data(), end, value);
  if (r.ec == std::errc() && r.ptr == end)
  {
    return true;
  }
  // from_chars rejects "inf"/"nan" spellings some writers use; strtod accepts them (then the finite
  // check reports them properly), and also values out of range.
  std::string copy(tok);
  char* stop = nullptr;
  value = std::strtod(copy.c_str(), &stop);
  return stop == copy.c_str() + copy.size();
}

bool parseInt(std::string_view tok, int64_t& value)
{
  if (!tok.empty() && tok[0] == '+')
  {
    tok.remove_prefix(1);
  }
  if (tok.empty())
  {
    return false;
  }
  const char* end = tok.data() + tok.size();
  auto r = std::from_chars(tok.data(), end, value);
  return r.ec == std::errc() && r.ptr == end;
}

int64_t countLimit(const std::string& text)
{
  return static_cast<int64_t>(text.size()) + 16;
}

Status finish(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info, bool merge)
{
  int32_t bad = -1;
  if (!allPointsFinite(mesh, &bad))
  {
    return Status::failure(ErrorKind::NonFinitePoint,
                           path + ": point " + std::to_string(bad) + " has a NaN or infinite coordinate", { bad });
  }
  if (mesh.numberOfTriangles() == 0)
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": the file contains no triangles");
  }
  if (merge)
  {
    const MergeResult r = mergeCoincidentPoints(mesh);
    if (info)
    {
      info->mergedPoints = r.mergedPoints;
    }
  }
  return Status::success();
}

void addPolygon(SurfaceMesh& mesh, const std::vector<int32_t>& loop, int32_t patch, SurfaceReadInfo& info,
                std::vector<int32_t>& scratch)
{
  if (loop.size() == 3)
  {
    mesh.addTriangle(loop[0], loop[1], loop[2], patch);
    return;
  }
  ++info.polygonFaces;
  scratch.clear();
  if (!triangulatePolygon(mesh.points, loop, scratch))
  {
    ++info.fanFallbacks;
  }
  for (size_t i = 0; i + 2 < scratch.size(); i += 3)
  {
    mesh.addTriangle(scratch[i], scratch[i + 1], scratch[i + 2], patch);
  }
}

void fanFallbackWarning(SurfaceReadInfo& info)
{
  if (info.fanFallbacks > 0)
  {
    info.warnings.push_back(
      std::to_string(info.fanFallbacks) +
      " polygon(s) could not be ear-clipped (self-intersecting or degenerate) and were fan-triangulated");
  }
}

} // namespace volgrid::detail
