// PLY surfaces (ASCII and binary, either endianness): vertex x/y/z of any numeric type, `face` lists
// (polygons are ear-clipped in their plane) and `tristrips` lists (-1 restarts a strip; every other
// triangle of a strip is flipped so the strip keeps one orientation). Other elements and properties are
// skipped. VTK's vtkPLYReader ignores triangle strips, which is why VolGrid reads PLY itself.
#include "PlyReader.h"
#include "GzipFile.h"
#include "PolygonTriangulation.h"
#include "SurfaceReaderSupport.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace volgrid
{
namespace
{
enum class Encoding
{
  Ascii,
  BinaryLittle,
  BinaryBig
};

// PLY scalar types by size; 0 for an unknown name.
int typeSize(const std::string& t)
{
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
    return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
    return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32")
    return 4;
  if (t == "double" || t == "float64")
    return 8;
  return 0;
}

struct Property
{
  std::string name;
  std::string type;      // scalar type, or the item type of a list
  std::string countType; // non-empty for lists
};

struct Element
{
  std::string name;
  int64_t count = 0;
  std::vector<Property> properties;
};

// Reads scalars from the body in the file's encoding.
class BodyReader
{
public:
  BodyReader(std::istream& in, Encoding encoding)
    : in_(in)
    , encoding_(encoding)
  {
  }
  bool read(const std::string& type, double& value)
  {
    if (encoding_ == Encoding::Ascii)
    {
      std::string token;
      if (!(in_ >> token))
        return false;
      // The whole token must be a number ("1x", "abc" are errors; nan/inf are caught by the finite check).
      if (!detail::parseDouble(token, value))
      {
        BadToken = token.substr(0, 40);
        return false;
      }
      return true;
    }
    const int size = typeSize(type);
    unsigned char bytes[8];
    if (size == 0 || !in_.read(reinterpret_cast<char*>(bytes), size))
      return false;
    const bool swap = (encoding_ == Encoding::BinaryBig) == isLittleEndianHost();
    if (swap)
      for (int i = 0; i < size / 2; ++i)
        std::swap(bytes[i], bytes[size - 1 - i]);
    value = decode(type, bytes);
    return true;
  }
  // The last ASCII token that was not a number (empty when the input simply ended).
  std::string BadToken;

private:
  static bool isLittleEndianHost()
  {
    const uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }
  static double decode(const std::string& t, const unsigned char* b)
  {
    if (t == "char" || t == "int8")
      return static_cast<int8_t>(b[0]);
    if (t == "uchar" || t == "uint8")
      return b[0];
    if (t == "short" || t == "int16")
      return load<int16_t>(b);
    if (t == "ushort" || t == "uint16")
      return load<uint16_t>(b);
    if (t == "int" || t == "int32")
      return load<int32_t>(b);
    if (t == "uint" || t == "uint32")
      return load<uint32_t>(b);
    if (t == "float" || t == "float32")
      return load<float>(b);
    return load<double>(b);
  }
  template<class T>
  static double load(const unsigned char* b)
  {
    T v;
    std::memcpy(&v, b, sizeof v);
    return static_cast<double>(v);
  }
  std::istream& in_;
  Encoding encoding_;
};

// Fewest bytes one element can take: binary, the fixed sizes (lists at least their count); ASCII, two
// characters per property (a digit and a separator).
double minimumBytes(const Element& e, Encoding encoding)
{
  double bytes = 0;
  for (const Property& p : e.properties)
    bytes += encoding == Encoding::Ascii ? 2 : typeSize(p.countType.empty() ? p.type : p.countType);
  return bytes;
}

Status plyError(const std::string& path, const std::string& what)
{
  return Status::failure(ErrorKind::InvalidOption, path + ": " + what);
}

// The header after the magic line, up to end_header: the encoding and the elements with their properties.
Status readHeader(std::istream& in, const std::string& path, Encoding& encoding, std::vector<Element>& elements)
{
  std::string line;
  while (std::getline(in, line))
  {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format")
    {
      std::string f;
      words >> f;
      if (f == "ascii")
        encoding = Encoding::Ascii;
      else if (f == "binary_little_endian")
        encoding = Encoding::BinaryLittle;
      else if (f == "binary_big_endian")
        encoding = Encoding::BinaryBig;
      else
        return plyError(path, "unknown PLY format '" + f + "'");
    }
    else if (keyword == "element")
    {
      Element e;
      words >> e.name >> e.count;
      if (!words || e.count < 0)
        return plyError(path, "malformed element line '" + line + "'");
      elements.push_back(e);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
        return plyError(path, "property before any element");
      Property p;
      std::string first;
      words >> first;
      if (first == "list")
        words >> p.countType >> p.type >> p.name;
      else
      {
        p.type = first;
        words >> p.name;
      }
      if (!words || typeSize(p.type) == 0 || (!p.countType.empty() && typeSize(p.countType) == 0))
        return plyError(path, "unsupported property line '" + line + "'");
      elements.back().properties.push_back(p);
    }
    else if (keyword == "end_header")
      return Status::success();
  }
  return plyError(path, "the header has no end_header line");
}

// Counts the file cannot hold are refused before anything is allocated.
Status checkCounts(const std::string& path, const std::vector<Element>& elements, Encoding encoding, double fileBytes)
{
  for (const Element& e : elements)
  {
    // Entries without properties take no bytes: no file size could bound their count.
    if (e.count > 0 && e.properties.empty())
      return plyError(path,
                      "element '" + e.name + "' claims " + std::to_string(e.count) + " entries but has no properties");
    const double least = static_cast<double>(e.count) * minimumBytes(e, encoding);
    if (least > fileBytes || (e.name == "vertex" && e.count > INT32_MAX))
      return plyError(path,
                      "element '" + e.name + "' claims " + std::to_string(e.count) + " entries, more than the file's " +
                        std::to_string(static_cast<long long>(fileBytes)) + " bytes can hold");
  }
  return Status::success();
}

// One face (vertex ids, checked): a triangle as it is, a polygon ear-clipped in its plane (a fan where
// that fails); fewer than 3 vertices add nothing.
void addFace(const std::vector<int32_t>& list, std::vector<int32_t>& triangles, SurfaceMesh& mesh,
             SurfaceReadInfo& info)
{
  ++info.fileFaces;
  if (list.size() < 3)
    return;
  if (list.size() == 3)
  {
    mesh.addTriangle(list[0], list[1], list[2]);
    return;
  }
  ++info.polygonFaces;
  triangles.clear();
  if (!triangulatePolygon(mesh.points, list, triangles))
  {
    ++info.fanFallbacks;
    triangles.clear();
    for (size_t k = 1; k + 1 < list.size(); ++k)
      triangles.insert(triangles.end(), { list[0], list[k], list[k + 1] });
  }
  for (size_t k = 0; k + 2 < triangles.size(); k += 3)
    mesh.addTriangle(triangles[k], triangles[k + 1], triangles[k + 2]);
}

// One triangle strip (vertex ids, -1 restarts it): a b c d ... gives (a,b,c), (c,b,d), (c,d,e), ...:
// odd triangles are flipped; a triangle repeating a vertex (a turn of the strip) is none.
void addStrip(const std::vector<int32_t>& list, SurfaceMesh& mesh, SurfaceReadInfo& info)
{
  size_t start = 0;
  for (size_t k = 0; k <= list.size(); ++k)
  {
    if (k < list.size() && list[k] != -1)
      continue;
    for (size_t j = start; j + 2 < k; ++j)
    {
      const bool odd = (j - start) % 2 == 1;
      const int32_t a = list[j], b = list[j + 1], c = list[j + 2];
      if (a == b || b == c || a == c)
        continue; // strips repeat a vertex to turn: those are not triangles
      if (odd)
        mesh.addTriangle(b, a, c);
      else
        mesh.addTriangle(a, b, c);
      ++info.fileFaces;
    }
    start = k + 1;
  }
}

// The body: vertex x/y/z into mesh.points, face and tristrips index lists into triangles; other
// elements and properties read and dropped. Fails on a short file, a token that is not a number, a bad
// list length or a vertex id out of range.
Status readBody(BodyReader& body, const std::string& path, const std::vector<Element>& elements, SurfaceMesh& mesh,
                SurfaceReadInfo& info)
{
  auto endsInside = [&](const Element& e, int64_t i)
  {
    return plyError(path,
                    body.BadToken.empty()
                      ? "the file ends inside element '" + e.name + "' " + std::to_string(i)
                      : "element '" + e.name + "' " + std::to_string(i) + ": '" + body.BadToken + "' is not a number");
  };
  std::vector<int32_t> list, triangles;
  int32_t vertexCount = 0;
  for (const Element& e : elements)
  {
    const bool isVertex = e.name == "vertex";
    const bool isFace = e.name == "face";
    const bool isStrip = e.name == "tristrips";
    if (isVertex)
    {
      vertexCount = static_cast<int32_t>(e.count);
      mesh.points.reserve(3 * static_cast<size_t>(e.count));
      info.filePoints = e.count;
    }
    else if (!isFace && !isStrip)
    {
      info.skippedElements += e.count;
    }
    for (int64_t i = 0; i < e.count; ++i)
    {
      double xyz[3] = { 0, 0, 0 };
      for (const Property& p : e.properties)
      {
        double value = 0;
        if (p.countType.empty())
        {
          if (!body.read(p.type, value))
            return endsInside(e, i);
          if (isVertex && (p.name == "x" || p.name == "y" || p.name == "z"))
            xyz[p.name[0] - 'x'] = value;
          continue;
        }
        double countValue = 0;
        if (!body.read(p.countType, countValue) ||
            !(countValue >= 0 && countValue <= 1e8 && countValue == std::floor(countValue))) // NaN too
          return plyError(path, "bad list length in element '" + e.name + "' " + std::to_string(i));
        const bool indices = (isFace || isStrip) && (p.name == "vertex_indices" || p.name == "vertex_index");
        list.clear();
        for (int64_t k = 0; k < static_cast<int64_t>(countValue); ++k)
        {
          if (!body.read(p.type, value))
            return endsInside(e, i);
          if (indices && !(value >= -1 && value < vertexCount && value == std::floor(value)))
          {
            char id[32];
            std::snprintf(id, sizeof id, "%.17g", value);
            return plyError(path,
                            e.name + " " + std::to_string(i) + " refers to vertex " + id + " (the file has " +
                              std::to_string(vertexCount) + ")");
          }
          if (indices)
            list.push_back(static_cast<int32_t>(value));
        }
        if (!indices)
          continue;
        for (const int32_t id : list)
          if (id < -1 || id >= vertexCount || (id == -1 && !isStrip))
            return plyError(path,
                            e.name + " " + std::to_string(i) + " refers to vertex " + std::to_string(id) +
                              " (the file has " + std::to_string(vertexCount) + ")");
        if (isFace)
          addFace(list, triangles, mesh, info);
        else
          addStrip(list, mesh, info);
      }
      if (isVertex)
        mesh.points.insert(mesh.points.end(), xyz, xyz + 3);
    }
  }
  return Status::success();
}
} // namespace

Status readPLY(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const SurfaceReadOptions& options)
{
  mesh.clear();
  SurfaceReadInfo localInfo;
  SurfaceReadInfo& info = infoOut ? *infoOut : localInfo;
  info = SurfaceReadInfo();
  // A .ply.gz file is decompressed into memory and parsed from there.
  std::ifstream file;
  std::istringstream unpacked;
  const bool gzip = isGzipPath(path);
  if (gzip)
  {
    std::string text;
    const Status s = readGzipFile(path, text);
    if (!s.ok())
      return s;
    unpacked.str(std::move(text));
  }
  else
  {
    const Status regular = detail::checkRegularFile(path);
    if (!regular.ok())
      return regular;
    file.open(path, std::ios::binary);
    if (!file)
      return plyError(path, "cannot open the file");
  }
  std::istream& in = gzip ? static_cast<std::istream&>(unpacked) : file;
  const double fileBytes =
    gzip ? static_cast<double>(unpacked.str().size()) : static_cast<double>(detail::fileSize(path));

  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
    return plyError(path, "not a PLY file (no 'ply' magic line)");
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  Status s = readHeader(in, path, encoding, elements);
  if (!s.ok())
    return s;
  info.format = encoding == Encoding::Ascii ? "PLY ascii" : "PLY binary";
  s = checkCounts(path, elements, encoding, fileBytes);
  if (!s.ok())
    return s;
  BodyReader body(in, encoding);
  s = readBody(body, path, elements, mesh, info);
  if (!s.ok())
    return s;
  return detail::finish(path, mesh, &info, options.mergeCoincidentPoints);
}

} // namespace volgrid
