#include "SurfaceReader.h"

#include "Predicates.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_map>

namespace volgrid
{

namespace
{

std::string lowerExtension(const std::string& path)
{
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

Status loadFile(const std::string& path, std::string& text)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return readError(path, 0, "cannot open file");
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0)
  {
    return readError(path, 0, "cannot determine the file size");
  }
  in.seekg(0, std::ios::beg);
  text.resize(static_cast<size_t>(size));
  if (size > 0 && !in.read(&text[0], size))
  {
    return readError(path, 0, "read error");
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

// Whitespace-separated tokens with line numbers and optional '#' comments to the end of the line.
class Scanner
{
public:
  Scanner(const std::string& text, const std::string& path, bool hashComments)
    : Text(text)
    , Path(path)
    , Comments(hashComments)
  {
  }

  int64_t line() const { return Line; }
  const std::string& path() const { return Path; }

  // Next token anywhere (crossing lines). False at end of input.
  bool next(std::string_view& tok)
  {
    skipSpace(true);
    if (Pos >= Text.size())
    {
      return false;
    }
    const size_t start = Pos;
    while (Pos < Text.size() && !isSpace(Text[Pos]) && !(Comments && Text[Pos] == '#'))
    {
      ++Pos;
    }
    tok = std::string_view(Text.data() + start, Pos - start);
    TokLine = Line;
    return true;
  }
  // Next token on the current line only. False at end of line.
  bool nextOnLine(std::string_view& tok)
  {
    skipSpace(false);
    if (Pos >= Text.size() || Text[Pos] == '\n' || Text[Pos] == '\r' || (Comments && Text[Pos] == '#'))
    {
      return false;
    }
    return next(tok);
  }
  // Skips the rest of the current line (including its end).
  void skipLine()
  {
    while (Pos < Text.size() && Text[Pos] != '\n')
    {
      ++Pos;
    }
    if (Pos < Text.size())
    {
      ++Pos;
      ++Line;
    }
  }
  // Collects the tokens of the next line that has any.
  bool nextLine(std::vector<std::string_view>& toks)
  {
    toks.clear();
    std::string_view tok;
    if (!next(tok))
    {
      return false;
    }
    toks.push_back(tok);
    while (nextOnLine(tok))
    {
      toks.push_back(tok);
    }
    return true;
  }
  bool atEnd()
  {
    skipSpace(true);
    return Pos >= Text.size();
  }

  Status error(const std::string& what) const { return readError(Path, TokLine > 0 ? TokLine : Line, what); }

  Status readDouble(double& v, const char* what)
  {
    std::string_view tok;
    if (!next(tok))
    {
      return error(std::string("unexpected end of file, expected ") + what);
    }
    if (!parseDouble(tok, v))
    {
      return error(std::string("expected ") + what + ", got '" + std::string(tok.substr(0, 40)) + "'");
    }
    return Status::success();
  }
  Status readInt(int64_t& v, const char* what)
  {
    std::string_view tok;
    if (!next(tok))
    {
      return error(std::string("unexpected end of file, expected ") + what);
    }
    if (!parseInt(tok, v))
    {
      return error(std::string("expected ") + what + ", got '" + std::string(tok.substr(0, 40)) + "'");
    }
    return Status::success();
  }
  Status readCount(int64_t& v, const char* what, int64_t limit)
  {
    Status s = readInt(v, what);
    if (!s.ok())
    {
      return s;
    }
    if (v < 0 || v > limit)
    {
      return error(std::string("invalid ") + what + " " + std::to_string(v));
    }
    return Status::success();
  }

private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  void skipSpace(bool crossLines)
  {
    while (Pos < Text.size())
    {
      const char c = Text[Pos];
      if (c == '\n')
      {
        if (!crossLines)
        {
          return;
        }
        ++Line;
        ++Pos;
      }
      else if (isSpace(c))
      {
        ++Pos;
      }
      else if (Comments && c == '#')
      {
        if (!crossLines)
        {
          return;
        }
        while (Pos < Text.size() && Text[Pos] != '\n')
        {
          ++Pos;
        }
      }
      else
      {
        return;
      }
    }
  }

  const std::string& Text;
  std::string Path;
  bool Comments;
  size_t Pos = 0;
  int64_t Line = 1;
  int64_t TokLine = 0;
};

// Limit on counts read from headers, so that a corrupt header cannot make us allocate terabytes.
int64_t countLimit(const std::string& text)
{
  return static_cast<int64_t>(text.size()) + 16;
}

// Finishes a read: finite check, optional merge, info.
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

// Adds a polygon face (point ids already validated) as triangles.
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
    info.warnings.push_back(std::to_string(info.fanFallbacks) +
      " polygon(s) could not be ear-clipped (self-intersecting or degenerate) and were fan-triangulated");
  }
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// Polygon triangulation by ear clipping in the polygon's plane.

namespace
{
struct PlaneFrame
{
  int drop = 2;  // coordinate axis dropped by the projection
  int sign = 1;  // sign that turns orient2dProjected into the loop's orientation (+1 = ear-convex)
};

double triangleQuality(const double* a, const double* b, const double* c)
{
  double e[3][3];
  for (int k = 0; k < 3; ++k)
  {
    e[0][k] = b[k] - a[k];
    e[1][k] = c[k] - b[k];
    e[2][k] = a[k] - c[k];
  }
  const double nx = e[0][1] * e[2][2] - e[0][2] * e[2][1];
  const double ny = e[0][2] * e[2][0] - e[0][0] * e[2][2];
  const double nz = e[0][0] * e[2][1] - e[0][1] * e[2][0];
  const double area2 = std::sqrt(nx * nx + ny * ny + nz * nz);
  double l2 = 0;
  for (int i = 0; i < 3; ++i)
  {
    l2 += e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
  }
  return l2 > 0 ? 2.0 * std::sqrt(3.0) * area2 / l2 : 0.0; // 1 for equilateral
}
} // namespace

bool triangulatePolygon(const std::vector<double>& points, const std::vector<int32_t>& loop,
  std::vector<int32_t>& out)
{
  const size_t n = loop.size();
  if (n < 3)
  {
    return false;
  }
  if (n == 3)
  {
    out.insert(out.end(), loop.begin(), loop.end());
    return true;
  }
  auto P = [&](int32_t id) { return points.data() + 3 * size_t(id); };
  // Newell normal: its largest component picks the projection, its sign the loop orientation there.
  double nrm[3] = { 0, 0, 0 };
  for (size_t i = 0; i < n; ++i)
  {
    const double* a = P(loop[i]);
    const double* b = P(loop[(i + 1) % n]);
    nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
    nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
    nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  PlaneFrame frame;
  for (int k = 0; k < 3; ++k)
  {
    if (std::fabs(nrm[k]) > std::fabs(nrm[frame.drop]))
    {
      frame.drop = k;
    }
  }
  auto fan = [&](const std::vector<int32_t>& rest) {
    for (size_t i = 1; i + 1 < rest.size(); ++i)
    {
      out.push_back(rest[0]);
      out.push_back(rest[i]);
      out.push_back(rest[i + 1]);
    }
  };
  if (nrm[frame.drop] == 0.0 || !std::isfinite(nrm[frame.drop]))
  {
    fan(loop);
    return false;
  }
  {
    // Calibrate the sign convention of orient2dProjected: the (u,v) = ((k+1)%3, (k+2)%3) frame is the
    // one whose signed area equals the Newell component nrm[k].
    const int k = frame.drop, u = (k + 1) % 3, v = (k + 2) % 3;
    double o[3] = { 0, 0, 0 }, pu[3] = { 0, 0, 0 }, pv[3] = { 0, 0, 0 };
    pu[u] = 1.0;
    pv[v] = 1.0;
    const int conv = predicates::orient2dProjected(o, pu, pv, k);
    frame.sign = conv * (nrm[k] > 0 ? 1 : -1);
  }
  auto orient = [&](int32_t a, int32_t b, int32_t c) {
    return predicates::orient2dProjected(P(a), P(b), P(c), frame.drop) * frame.sign;
  };

  std::vector<int32_t> prev(n), next(n);
  for (size_t i = 0; i < n; ++i)
  {
    prev[i] = static_cast<int32_t>((i + n - 1) % n);
    next[i] = static_cast<int32_t>((i + 1) % n);
  }
  std::vector<char> alive(n, 1);
  std::vector<double> quality(n, -1.0); // < 0: not an ear
  auto evaluate = [&](int32_t i) {
    const int32_t ia = prev[i], ic = next[i];
    const int32_t a = loop[ia], b = loop[i], c = loop[ic];
    quality[i] = -1.0;
    if (orient(a, b, c) <= 0)
    {
      return;
    }
    for (int32_t j = next[ic]; j != ia; j = next[j])
    {
      const int32_t p = loop[j];
      if (p == a || p == b || p == c)
      {
        continue;
      }
      if (orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0)
      {
        return; // p inside or on the ear: cutting it would cross or touch the boundary
      }
    }
    quality[i] = triangleQuality(P(a), P(b), P(c));
  };
  for (size_t i = 0; i < n; ++i)
  {
    evaluate(static_cast<int32_t>(i));
  }
  size_t remaining = n;
  int32_t start = 0;
  bool refreshed = false;
  while (remaining > 3)
  {
    int32_t best = -1;
    int32_t i = start;
    do
    {
      if (quality[i] >= 0 && (best < 0 || quality[i] > quality[best]))
      {
        best = i;
      }
      i = next[i];
    } while (i != start);
    if (best < 0)
    {
      if (!refreshed)
      {
        // Removing a vertex can unblock ears elsewhere; re-evaluate everything once before giving up.
        i = start;
        do
        {
          evaluate(i);
          i = next[i];
        } while (i != start);
        refreshed = true;
        continue;
      }
      std::vector<int32_t> rest;
      i = start;
      do
      {
        rest.push_back(loop[i]);
        i = next[i];
      } while (i != start);
      fan(rest);
      return false;
    }
    refreshed = false;
    const int32_t ia = prev[best], ic = next[best];
    out.push_back(loop[ia]);
    out.push_back(loop[best]);
    out.push_back(loop[ic]);
    alive[best] = 0;
    next[ia] = ic;
    prev[ic] = ia;
    --remaining;
    start = ia;
    if (remaining > 3)
    {
      evaluate(ia);
      evaluate(ic);
    }
  }
  out.push_back(loop[prev[start]]);
  out.push_back(loop[start]);
  out.push_back(loop[next[start]]);
  return true;
}

// ---------------------------------------------------------------------------------------------------

bool surfaceReaderSupports(const std::string& path)
{
  const std::string ext = lowerExtension(path);
  return ext == "off" || ext == "mesh" || ext == "poly" || ext == "smesh" || ext == "msh" || ext == "stl" ||
    ext == "ply";
}

Status readSurface(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info,
  const SurfaceReadOptions& options)
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
  return readError(
    path, 0, "unsupported file extension '." + ext + "' (supported: .off .mesh .poly .smesh .msh .stl .ply)");
}

// ---------------------------------------------------------------------------------------------------
// OFF

Status readOFF(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut,
  const SurfaceReadOptions& options)
{
  mesh.clear();
  SurfaceReadInfo localInfo;
  SurfaceReadInfo& info = infoOut ? *infoOut : localInfo;
  info = SurfaceReadInfo();
  info.format = "OFF";
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
  {
    return s;
  }
  Scanner sc(text, path, true);
  std::vector<std::string_view> toks;
  if (!sc.nextLine(toks))
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": empty file");
  }
  // Header keyword: [ST][C][N][4][n]OFF, possibly followed by the counts on the same line.
  std::string_view key = toks[0];
  bool hasNormals = false, hasColors = false, hasTex = false;
  size_t first = 0;
  if (key.size() >= 3 && key.substr(key.size() - 3) == "OFF")
  {
    std::string_view prefix = key.substr(0, key.size() - 3);
    if (prefix.size() >= 2 && prefix.substr(0, 2) == "ST")
    {
      hasTex = true;
      prefix.remove_prefix(2);
    }
    if (!prefix.empty() && prefix[0] == 'C')
    {
      hasColors = true;
      prefix.remove_prefix(1);
    }
    if (!prefix.empty() && prefix[0] == 'N')
    {
      hasNormals = true;
      prefix.remove_prefix(1);
    }
    if (!prefix.empty())
    {
      return sc.error("unsupported OFF variant '" + std::string(key) + "' (4D or n-dimensional OFF)");
    }
    first = 1;
    info.format = std::string(key);
  }
  else if (key == "OFF_BINARY" || (toks.size() > 1 && toks[1] == "BINARY"))
  {
    return sc.error("binary OFF is not supported");
  }
  (void)hasNormals;
  (void)hasColors;
  (void)hasTex;
  // Counts: nv nf [ne], possibly on the following line(s).
  std::vector<int64_t> counts;
  const int64_t limit = countLimit(text);
  for (size_t i = first; i < toks.size() && counts.size() < 3; ++i)
  {
    int64_t v = 0;
    if (!parseInt(toks[i], v))
    {
      return sc.error("expected vertex/face/edge counts, got '" + std::string(toks[i]) + "'");
    }
    counts.push_back(v);
  }
  while (counts.size() < 2)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file in the OFF header");
    }
    for (size_t i = 0; i < toks.size() && counts.size() < 3; ++i)
    {
      int64_t v = 0;
      if (!parseInt(toks[i], v))
      {
        return sc.error("expected vertex/face/edge counts, got '" + std::string(toks[i]) + "'");
      }
      counts.push_back(v);
    }
  }
  const int64_t nv = counts[0], nf = counts[1];
  if (nv < 0 || nf < 0 || nv > limit || nf > limit)
  {
    return sc.error("invalid counts in the OFF header");
  }
  mesh.points.reserve(3 * size_t(nv));
  for (int64_t i = 0; i < nv; ++i)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    }
    if (toks.size() < 3)
    {
      return sc.error("vertex " + std::to_string(i) + " has fewer than 3 coordinates");
    }
    double xyz[3];
    for (int k = 0; k < 3; ++k)
    {
      if (!parseDouble(toks[k], xyz[k]))
      {
        return sc.error("vertex " + std::to_string(i) + ": bad coordinate '" + std::string(toks[k]) + "'");
      }
    }
    mesh.addPoint(xyz[0], xyz[1], xyz[2]);
  }
  info.filePoints = nv;
  std::vector<int32_t> loop, scratch;
  mesh.triangles.reserve(3 * size_t(nf));
  for (int64_t f = 0; f < nf; ++f)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    }
    int64_t nc = 0;
    if (!parseInt(toks[0], nc) || nc < 0)
    {
      return sc.error("face " + std::to_string(f) + ": bad corner count '" + std::string(toks[0]) + "'");
    }
    if (static_cast<int64_t>(toks.size()) < nc + 1)
    {
      return sc.error("face " + std::to_string(f) + ": expected " + std::to_string(nc) + " vertex ids");
    }
    loop.clear();
    for (int64_t k = 0; k < nc; ++k)
    {
      int64_t id = 0;
      if (!parseInt(toks[1 + k], id) || id < 0 || id >= nv)
      {
        return sc.error("face " + std::to_string(f) + ": vertex id '" + std::string(toks[1 + k]) +
          "' out of range [0," + std::to_string(nv) + ")");
      }
      loop.push_back(static_cast<int32_t>(id));
    }
    ++info.fileFaces;
    if (nc < 3)
    {
      info.skippedElements++;
      continue;
    }
    addPolygon(mesh, loop, -1, info, scratch);
  }
  if (info.skippedElements > 0)
  {
    info.warnings.push_back(std::to_string(info.skippedElements) + " face(s) with fewer than 3 vertices skipped");
  }
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

// ---------------------------------------------------------------------------------------------------
// Medit .mesh (ASCII)

Status readMedit(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut,
  const SurfaceReadOptions& options)
{
  mesh.clear();
  SurfaceReadInfo localInfo;
  SurfaceReadInfo& info = infoOut ? *infoOut : localInfo;
  info = SurfaceReadInfo();
  info.format = "Medit";
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
  {
    return s;
  }
  if (lowerExtension(path) == "meshb" || text.find('\0') != std::string::npos)
  {
    return readError(path, 0, "binary Medit (.meshb) is not supported");
  }
  Scanner sc(text, path, true);
  const int64_t limit = countLimit(text);
  int64_t dim = 3;
  bool haveVertices = false;
  std::vector<int32_t> loop, scratch;
  // Entries per record of the sections we skip.
  static const std::pair<const char*, int> skipped[] = { { "Edges", 3 }, { "Tetrahedra", 5 },
    { "Prisms", 7 }, { "Pentahedra", 7 }, { "Hexahedra", 9 }, { "Corners", 1 }, { "Ridges", 1 },
    { "RequiredVertices", 1 }, { "RequiredEdges", 1 }, { "RequiredTriangles", 1 },
    { "RequiredQuadrilaterals", 1 }, { "Normals", 3 }, { "Tangents", 3 }, { "NormalAtVertices", 2 },
    { "NormalAtTriangleVertices", 3 }, { "NormalAtQuadrilateralVertices", 3 }, { "TangentAtVertices", 2 },
    { "TangentAtEdgeVertices", 3 }, { "Crack", 2 }, { "Edges", 3 } };
  std::string_view tok;
  while (sc.next(tok))
  {
    if (tok == "End")
    {
      break;
    }
    if (tok == "MeshVersionFormatted")
    {
      int64_t v;
      s = sc.readInt(v, "version number");
      if (!s.ok())
      {
        return s;
      }
      continue;
    }
    if (tok == "Dimension")
    {
      s = sc.readInt(dim, "dimension");
      if (!s.ok())
      {
        return s;
      }
      if (dim != 3)
      {
        return sc.error("only 3D Medit meshes are supported (Dimension " + std::to_string(dim) + ")");
      }
      continue;
    }
    if (tok == "Vertices")
    {
      int64_t nv;
      s = sc.readCount(nv, "vertex count", limit);
      if (!s.ok())
      {
        return s;
      }
      mesh.points.reserve(3 * size_t(nv));
      for (int64_t i = 0; i < nv; ++i)
      {
        double xyz[3];
        int64_t ref;
        for (int k = 0; k < 3; ++k)
        {
          s = sc.readDouble(xyz[k], "a vertex coordinate");
          if (!s.ok())
          {
            return s;
          }
        }
        s = sc.readInt(ref, "a vertex reference");
        if (!s.ok())
        {
          return s;
        }
        mesh.addPoint(xyz[0], xyz[1], xyz[2]);
      }
      info.filePoints += nv;
      haveVertices = true;
      continue;
    }
    if (tok == "Triangles" || tok == "Quadrilaterals")
    {
      const int nc = tok == "Triangles" ? 3 : 4;
      if (!haveVertices)
      {
        return sc.error("element section before the Vertices section");
      }
      int64_t ne;
      s = sc.readCount(ne, "element count", limit);
      if (!s.ok())
      {
        return s;
      }
      const int64_t nv = mesh.numberOfPoints();
      for (int64_t e = 0; e < ne; ++e)
      {
        loop.clear();
        for (int k = 0; k < nc; ++k)
        {
          int64_t id;
          s = sc.readInt(id, "a vertex id");
          if (!s.ok())
          {
            return s;
          }
          if (id < 1 || id > nv)
          {
            return sc.error("element " + std::to_string(e + 1) + ": vertex id " + std::to_string(id) +
              " out of range [1," + std::to_string(nv) + "]");
          }
          loop.push_back(static_cast<int32_t>(id - 1));
        }
        int64_t ref;
        s = sc.readInt(ref, "an element reference");
        if (!s.ok())
        {
          return s;
        }
        ++info.fileFaces;
        addPolygon(mesh, loop, static_cast<int32_t>(ref), info, scratch);
      }
      continue;
    }
    int per = -1;
    for (const auto& sk : skipped)
    {
      if (tok == sk.first)
      {
        per = sk.second;
      }
    }
    if (per < 0)
    {
      return sc.error("unknown Medit keyword '" + std::string(tok.substr(0, 40)) + "'");
    }
    int64_t ne;
    s = sc.readCount(ne, "entry count", limit);
    if (!s.ok())
    {
      return s;
    }
    for (int64_t e = 0; e < ne * per; ++e)
    {
      if (!sc.next(tok))
      {
        return sc.error("unexpected end of file in a skipped section");
      }
    }
    info.skippedElements += ne;
  }
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

// ---------------------------------------------------------------------------------------------------
// TetGen .poly / .smesh

namespace
{
// Reads a node list (header line already tokenised in `header`). Returns the index base.
Status readTetGenNodes(Scanner& sc, const std::vector<std::string_view>& header, SurfaceMesh& mesh,
  int64_t limit, int64_t& base)
{
  int64_t n = 0, dim = 3, nattr = 0, nbm = 0;
  if (!parseInt(header[0], n) || n < 0 || n > limit)
  {
    return sc.error("bad node count '" + std::string(header[0]) + "'");
  }
  if (header.size() > 1 && (!parseInt(header[1], dim) || dim != 3))
  {
    return sc.error("only 3D node lists are supported");
  }
  if (header.size() > 2 && (!parseInt(header[2], nattr) || nattr < 0))
  {
    return sc.error("bad attribute count");
  }
  if (header.size() > 3 && (!parseInt(header[3], nbm) || nbm < 0))
  {
    return sc.error("bad boundary-marker flag");
  }
  std::vector<std::string_view> toks;
  mesh.points.reserve(3 * size_t(n));
  for (int64_t i = 0; i < n; ++i)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(i) + " of " + std::to_string(n) + " nodes");
    }
    int64_t id = 0;
    double xyz[3];
    if (toks.size() < 4 || !parseInt(toks[0], id))
    {
      return sc.error("node " + std::to_string(i) + ": expected 'index x y z'");
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!parseDouble(toks[1 + k], xyz[k]))
      {
        return sc.error("node " + std::to_string(id) + ": bad coordinate '" + std::string(toks[1 + k]) + "'");
      }
    }
    if (i == 0)
    {
      base = id;
    }
    else if (id != base + i)
    {
      return sc.error("node indices must be consecutive: expected " + std::to_string(base + i) + ", got " +
        std::to_string(id));
    }
    mesh.addPoint(xyz[0], xyz[1], xyz[2]);
  }
  return Status::success();
}

Status readPolygonLine(Scanner& sc, const std::vector<std::string_view>& toks, int64_t base, int64_t nv,
  std::vector<int32_t>& loop, size_t& used)
{
  int64_t nc = 0;
  if (!parseInt(toks[0], nc) || nc < 0)
  {
    return sc.error("bad polygon corner count '" + std::string(toks[0]) + "'");
  }
  if (static_cast<int64_t>(toks.size()) < nc + 1)
  {
    return sc.error("polygon with " + std::to_string(nc) + " corners lists fewer ids");
  }
  loop.clear();
  for (int64_t k = 0; k < nc; ++k)
  {
    int64_t id = 0;
    if (!parseInt(toks[1 + k], id) || id < base || id >= base + nv)
    {
      return sc.error("polygon corner '" + std::string(toks[1 + k]) + "' is not a node index in [" +
        std::to_string(base) + "," + std::to_string(base + nv - 1) + "]");
    }
    loop.push_back(static_cast<int32_t>(id - base));
  }
  used = static_cast<size_t>(nc + 1);
  return Status::success();
}
} // namespace

Status readTetGen(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut,
  const SurfaceReadOptions& options)
{
  mesh.clear();
  SurfaceReadInfo localInfo;
  SurfaceReadInfo& info = infoOut ? *infoOut : localInfo;
  info = SurfaceReadInfo();
  const bool smesh = lowerExtension(path) == "smesh";
  info.format = smesh ? "TetGen smesh" : "TetGen poly";
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
  {
    return s;
  }
  Scanner sc(text, path, true);
  const int64_t limit = countLimit(text);
  std::vector<std::string_view> toks;
  if (!sc.nextLine(toks))
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": empty file");
  }
  int64_t base = 0;
  int64_t nodeCount = 0;
  if (!parseInt(toks[0], nodeCount))
  {
    return sc.error("expected the node count, got '" + std::string(toks[0]) + "'");
  }
  std::string nodeText;
  if (nodeCount == 0)
  {
    // Nodes are in the sibling .node file.
    const size_t dot = path.find_last_of('.');
    const std::string nodePath = path.substr(0, dot) + ".node";
    s = loadFile(nodePath, nodeText);
    if (!s.ok())
    {
      return readError(path, sc.line(), "the node list is empty and " + nodePath + " cannot be read");
    }
    Scanner nsc(nodeText, nodePath, true);
    std::vector<std::string_view> nh;
    if (!nsc.nextLine(nh))
    {
      return readError(nodePath, 0, "empty .node file");
    }
    s = readTetGenNodes(nsc, nh, mesh, countLimit(nodeText), base);
  }
  else
  {
    s = readTetGenNodes(sc, toks, mesh, limit, base);
  }
  if (!s.ok())
  {
    return s;
  }
  const int64_t nv = mesh.numberOfPoints();
  info.filePoints = nv;
  if (!sc.nextLine(toks))
  {
    return sc.error("unexpected end of file: the facet list is missing");
  }
  int64_t nf = 0, hasMarkers = 0;
  if (!parseInt(toks[0], nf) || nf < 0 || nf > limit)
  {
    return sc.error("bad facet count '" + std::string(toks[0]) + "'");
  }
  if (toks.size() > 1 && !parseInt(toks[1], hasMarkers))
  {
    return sc.error("bad boundary-marker flag '" + std::string(toks[1]) + "'");
  }
  std::vector<int32_t> loop, scratch;
  int64_t holeFacets = 0;
  for (int64_t f = 0; f < nf; ++f)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(f) + " of " + std::to_string(nf) + " facets");
    }
    if (smesh)
    {
      size_t used = 0;
      s = readPolygonLine(sc, toks, base, nv, loop, used);
      if (!s.ok())
      {
        return s;
      }
      int64_t marker = -1;
      if (hasMarkers && toks.size() > used)
      {
        parseInt(toks[used], marker);
      }
      ++info.fileFaces;
      if (loop.size() < 3)
      {
        ++info.skippedElements;
        continue;
      }
      addPolygon(mesh, loop, static_cast<int32_t>(hasMarkers ? marker : f), info, scratch);
      continue;
    }
    // .poly: "npolygons [nholes] [marker]", polygons, hole points.
    int64_t npoly = 0, nholes = 0, marker = f;
    if (!parseInt(toks[0], npoly) || npoly < 0 || npoly > limit)
    {
      return sc.error("facet " + std::to_string(f) + ": bad polygon count '" + std::string(toks[0]) + "'");
    }
    if (toks.size() > 1 && (!parseInt(toks[1], nholes) || nholes < 0 || nholes > limit))
    {
      return sc.error("facet " + std::to_string(f) + ": bad hole count '" + std::string(toks[1]) + "'");
    }
    if (hasMarkers && toks.size() > 2)
    {
      parseInt(toks[2], marker);
    }
    std::vector<std::vector<int32_t>> polygons;
    for (int64_t p = 0; p < npoly; ++p)
    {
      if (!sc.nextLine(toks))
      {
        return sc.error("unexpected end of file in facet " + std::to_string(f));
      }
      size_t used = 0;
      s = readPolygonLine(sc, toks, base, nv, loop, used);
      if (!s.ok())
      {
        return s;
      }
      polygons.push_back(loop);
    }
    std::vector<double> holes;
    for (int64_t h = 0; h < nholes; ++h)
    {
      if (!sc.nextLine(toks) || toks.size() < 4)
      {
        return sc.error("facet " + std::to_string(f) + ": expected a hole point 'index x y z'");
      }
      for (int k = 1; k <= 3; ++k)
      {
        double v;
        if (!parseDouble(toks[k], v))
        {
          return sc.error("facet " + std::to_string(f) + ": bad hole coordinate");
        }
        holes.push_back(v);
      }
    }
    ++info.fileFaces;
    if (nholes > 0)
    {
      ++holeFacets;
      if (holeFacets == 1)
      {
        return sc.error("facet " + std::to_string(f) + " has " + std::to_string(nholes) +
          " hole(s): facets with holes are not supported by this reader");
      }
    }
    for (const auto& poly : polygons)
    {
      if (poly.size() < 3)
      {
        ++info.skippedElements; // segments and isolated points inside a facet
        continue;
      }
      addPolygon(mesh, poly, static_cast<int32_t>(marker), info, scratch);
    }
  }
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

// ---------------------------------------------------------------------------------------------------
// gmsh .msh (ASCII, versions 2.x and 4.x)

namespace
{
Status skipSection(Scanner& sc, std::string_view name)
{
  const std::string endTag = "$End" + std::string(name.substr(1));
  std::string_view tok;
  while (sc.next(tok))
  {
    if (tok == endTag)
    {
      return Status::success();
    }
  }
  return sc.error("section " + std::string(name) + " is not closed by " + endTag);
}
} // namespace

Status readGmsh(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut,
  const SurfaceReadOptions& options)
{
  mesh.clear();
  SurfaceReadInfo localInfo;
  SurfaceReadInfo& info = infoOut ? *infoOut : localInfo;
  info = SurfaceReadInfo();
  info.format = "gmsh";
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
  {
    return s;
  }
  Scanner sc(text, path, false);
  const int64_t limit = countLimit(text);
  std::string_view tok;
  double version = 0;
  bool haveFormat = false;
  std::unordered_map<int64_t, int32_t> nodeIndex;
  std::vector<int32_t> loop, scratch;
  std::vector<std::string_view> toks;
  auto node = [&](int64_t tag, int32_t& index) -> Status {
    auto it = nodeIndex.find(tag);
    if (it == nodeIndex.end())
    {
      return sc.error("element refers to unknown node " + std::to_string(tag));
    }
    index = it->second;
    return Status::success();
  };
  auto addElement = [&](int64_t type, int32_t patch) { // nodes already in loop
    ++info.fileFaces;
    addPolygon(mesh, loop, patch, info, scratch);
    (void)type;
  };
  while (sc.next(tok))
  {
    if (tok.empty() || tok[0] != '$')
    {
      return sc.error("expected a section tag such as $Nodes, got '" + std::string(tok.substr(0, 40)) + "'");
    }
    if (tok == "$MeshFormat")
    {
      int64_t fileType = 0, dataSize = 0;
      s = sc.readDouble(version, "the format version");
      if (s.ok())
      {
        s = sc.readInt(fileType, "the file type");
      }
      if (s.ok())
      {
        s = sc.readInt(dataSize, "the data size");
      }
      if (!s.ok())
      {
        return s;
      }
      if (fileType != 0)
      {
        return sc.error("binary .msh files are not supported (write ASCII with gmsh -format msh2 or msh4)");
      }
      if (version < 2.0 || version >= 5.0)
      {
        return sc.error("unsupported .msh version " + std::to_string(version) + " (2.x and 4.x are supported)");
      }
      if (version >= 3.0 && version < 4.0)
      {
        return sc.error("unsupported .msh version 3 (2.x and 4.x are supported)");
      }
      info.format = "gmsh " + std::string(version >= 4.0 ? (version >= 4.05 ? "4.1" : "4.0") : "2");
      haveFormat = true;
      s = skipSection(sc, tok);
      if (!s.ok())
      {
        return s;
      }
      continue;
    }
    if (tok == "$Nodes")
    {
      if (!haveFormat)
      {
        return sc.error("$Nodes before $MeshFormat");
      }
      if (version < 3.0)
      {
        int64_t n;
        s = sc.readCount(n, "node count", limit);
        if (!s.ok())
        {
          return s;
        }
        nodeIndex.reserve(size_t(n));
        for (int64_t i = 0; i < n; ++i)
        {
          int64_t tag;
          double xyz[3];
          s = sc.readInt(tag, "a node tag");
          for (int k = 0; k < 3 && s.ok(); ++k)
          {
            s = sc.readDouble(xyz[k], "a node coordinate");
          }
          if (!s.ok())
          {
            return s;
          }
          nodeIndex[tag] = mesh.addPoint(xyz[0], xyz[1], xyz[2]);
        }
      }
      else
      {
        const bool v41 = version >= 4.05;
        int64_t nblocks, n, dummy;
        s = sc.readCount(nblocks, "entity block count", limit);
        if (s.ok())
        {
          s = sc.readCount(n, "node count", limit);
        }
        if (s.ok() && v41)
        {
          s = sc.readInt(dummy, "the minimum node tag");
          if (s.ok())
          {
            s = sc.readInt(dummy, "the maximum node tag");
          }
        }
        if (!s.ok())
        {
          return s;
        }
        nodeIndex.reserve(size_t(n));
        std::vector<int64_t> tags;
        for (int64_t b = 0; b < nblocks; ++b)
        {
          int64_t h[4];
          for (int k = 0; k < 4 && s.ok(); ++k)
          {
            s = sc.readInt(h[k], "a node block header value");
          }
          if (!s.ok())
          {
            return s;
          }
          const int64_t entityDim = v41 ? h[0] : h[1];
          const int64_t parametric = h[2];
          const int64_t count = h[3];
          if (count < 0 || count > limit)
          {
            return sc.error("bad node block size " + std::to_string(count));
          }
          const int64_t nparam = parametric ? std::max<int64_t>(entityDim, 0) : 0;
          if (v41)
          {
            tags.resize(size_t(count));
            for (int64_t i = 0; i < count && s.ok(); ++i)
            {
              s = sc.readInt(tags[i], "a node tag");
            }
          }
          for (int64_t i = 0; i < count && s.ok(); ++i)
          {
            int64_t tag = 0;
            if (!v41)
            {
              s = sc.readInt(tag, "a node tag");
            }
            else
            {
              tag = tags[i];
            }
            double xyz[3], uvw;
            for (int k = 0; k < 3 && s.ok(); ++k)
            {
              s = sc.readDouble(xyz[k], "a node coordinate");
            }
            for (int64_t k = 0; k < nparam && s.ok(); ++k)
            {
              s = sc.readDouble(uvw, "a parametric coordinate");
            }
            if (s.ok())
            {
              nodeIndex[tag] = mesh.addPoint(xyz[0], xyz[1], xyz[2]);
            }
          }
          if (!s.ok())
          {
            return s;
          }
        }
      }
      s = skipSection(sc, tok);
      if (!s.ok())
      {
        return s;
      }
      continue;
    }
    if (tok == "$Elements")
    {
      if (!haveFormat)
      {
        return sc.error("$Elements before $MeshFormat");
      }
      if (version < 3.0)
      {
        int64_t n;
        s = sc.readCount(n, "element count", limit);
        if (!s.ok())
        {
          return s;
        }
        sc.skipLine();
        for (int64_t e = 0; e < n; ++e)
        {
          if (!sc.nextLine(toks))
          {
            return sc.error("unexpected end of file: read " + std::to_string(e) + " of " + std::to_string(n) + " elements");
          }
          int64_t id, type, ntags;
          if (toks.size() < 3 || !parseInt(toks[0], id) || !parseInt(toks[1], type) || !parseInt(toks[2], ntags) ||
            ntags < 0 || static_cast<int64_t>(toks.size()) < 3 + ntags)
          {
            return sc.error("malformed element line");
          }
          if (type != 2 && type != 3)
          {
            ++info.skippedElements;
            continue;
          }
          const int nc = type == 2 ? 3 : 4;
          if (static_cast<int64_t>(toks.size()) < 3 + ntags + nc)
          {
            return sc.error("element " + std::to_string(id) + ": too few node tags");
          }
          int64_t physical = 0, elementary = 0;
          if (ntags > 0)
          {
            parseInt(toks[3], physical);
          }
          if (ntags > 1)
          {
            parseInt(toks[4], elementary);
          }
          loop.clear();
          for (int k = 0; k < nc; ++k)
          {
            int64_t tag;
            int32_t index;
            if (!parseInt(toks[3 + ntags + k], tag))
            {
              return sc.error("element " + std::to_string(id) + ": bad node tag");
            }
            s = node(tag, index);
            if (!s.ok())
            {
              return s;
            }
            loop.push_back(index);
          }
          addElement(type, static_cast<int32_t>(physical != 0 ? physical : elementary));
        }
      }
      else
      {
        const bool v41 = version >= 4.05;
        int64_t nblocks, n, dummy;
        s = sc.readCount(nblocks, "element block count", limit);
        if (s.ok())
        {
          s = sc.readCount(n, "element count", limit);
        }
        if (s.ok() && v41)
        {
          s = sc.readInt(dummy, "the minimum element tag");
          if (s.ok())
          {
            s = sc.readInt(dummy, "the maximum element tag");
          }
        }
        if (!s.ok())
        {
          return s;
        }
        for (int64_t b = 0; b < nblocks; ++b)
        {
          int64_t h[4];
          for (int k = 0; k < 4 && s.ok(); ++k)
          {
            s = sc.readInt(h[k], "an element block header value");
          }
          if (!s.ok())
          {
            return s;
          }
          const int64_t entityTag = v41 ? h[1] : h[0];
          const int64_t type = h[2];
          const int64_t count = h[3];
          if (count < 0 || count > limit)
          {
            return sc.error("bad element block size " + std::to_string(count));
          }
          sc.skipLine();
          for (int64_t e = 0; e < count; ++e)
          {
            if (!sc.nextLine(toks))
            {
              return sc.error("unexpected end of file in an element block");
            }
            if (type != 2 && type != 3)
            {
              ++info.skippedElements;
              continue;
            }
            const size_t nc = type == 2 ? 3 : 4;
            if (toks.size() < nc + 1)
            {
              return sc.error("element with too few node tags");
            }
            loop.clear();
            for (size_t k = 0; k < nc; ++k)
            {
              int64_t tag;
              int32_t index;
              if (!parseInt(toks[1 + k], tag))
              {
                return sc.error("bad node tag '" + std::string(toks[1 + k]) + "'");
              }
              s = node(tag, index);
              if (!s.ok())
              {
                return s;
              }
              loop.push_back(index);
            }
            addElement(type, static_cast<int32_t>(entityTag));
          }
        }
      }
      s = skipSection(sc, tok);
      if (!s.ok())
      {
        return s;
      }
      continue;
    }
    s = skipSection(sc, tok);
    if (!s.ok())
    {
      return s;
    }
  }
  info.filePoints = mesh.numberOfPoints();
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

// ---------------------------------------------------------------------------------------------------
// STL

Status readSTL(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const SurfaceReadOptions&)
{
  mesh.clear();
  SurfaceReadInfo localInfo;
  SurfaceReadInfo& info = infoOut ? *infoOut : localInfo;
  info = SurfaceReadInfo();
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
  {
    return s;
  }
  if (text.empty())
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": empty file");
  }
  bool binary = false;
  uint32_t count = 0;
  if (text.size() >= 84)
  {
    std::memcpy(&count, text.data() + 80, 4); // little-endian hosts only (x86, ARM)
    binary = 84 + 50 * uint64_t(count) == text.size();
  }
  size_t firstNonSpace = text.find_first_not_of(" \t\r\n");
  const bool startsWithSolid = firstNonSpace != std::string::npos && text.compare(firstNonSpace, 5, "solid") == 0;
  if (binary && startsWithSolid)
  {
    // Some binary writers start the header with "solid"; an ASCII file whose size happens to match
    // is recognised by its 'facet' keyword right after the first line.
    const size_t eol = text.find('\n');
    const size_t facet = eol == std::string::npos ? std::string::npos : text.find_first_not_of(" \t\r\n", eol);
    binary = !(facet != std::string::npos && (text.compare(facet, 5, "facet") == 0 || text.compare(facet, 8, "endsolid") == 0));
  }
  if (binary)
  {
    info.format = "STL binary";
    info.solids = 1;
    mesh.points.reserve(9 * size_t(count));
    mesh.triangles.reserve(3 * size_t(count));
    const char* p = text.data() + 84;
    for (uint32_t t = 0; t < count; ++t, p += 50)
    {
      float v[12];
      std::memcpy(v, p, 48);
      const int32_t a = mesh.addPoint(v[3], v[4], v[5]);
      const int32_t b = mesh.addPoint(v[6], v[7], v[8]);
      const int32_t c = mesh.addPoint(v[9], v[10], v[11]);
      mesh.addTriangle(a, b, c, 0);
    }
    info.fileFaces = count;
  }
  else if (startsWithSolid && text.find('\0') != std::string::npos && text.size() >= 84)
  {
    // "solid" header but binary content (NUL bytes): a binary file whose size does not match.
    return readError(path, 0, "binary STL header announces " + std::to_string(count) + " triangles (" +
      std::to_string(84 + 50 * uint64_t(count)) + " bytes) but the file has " + std::to_string(text.size()) +
      " bytes");
  }
  else if (startsWithSolid)
  {
    info.format = "STL ascii";
    Scanner sc(text, path, false);
    std::string_view tok;
    std::vector<int32_t> loop, scratch;
    int32_t solid = -1;
    int64_t strayFacets = 0;
    bool inSolid = false;
    while (sc.next(tok))
    {
      if (!inSolid)
      {
        if (tok == "solid")
        {
          ++solid;
          inSolid = true;
          sc.skipLine(); // the solid's name
          continue;
        }
        if (tok == "facet" && solid >= 0)
        {
          // Facets after 'endsolid' without a new 'solid' (gmsh's multi_solid.stl): keep reading them
          // as part of the last solid.
          ++strayFacets;
          inSolid = true;
        }
        else
        {
        // Text after the last endsolid (gmsh appends its .geo commands): ignore, but say so.
        info.warnings.push_back("text after 'endsolid' at line " + std::to_string(sc.line()) + " ignored");
        break;
        }
      }
      if (tok == "endsolid")
      {
        inSolid = false;
        sc.skipLine();
        continue;
      }
      if (tok != "facet")
      {
        return sc.error("expected 'facet' or 'endsolid', got '" + std::string(tok.substr(0, 40)) + "'");
      }
      // facet normal nx ny nz
      if (!sc.next(tok))
      {
        return sc.error("unexpected end of file in a facet");
      }
      if (tok == "normal")
      {
        double nrm;
        for (int k = 0; k < 3; ++k)
        {
          s = sc.readDouble(nrm, "a normal component");
          if (!s.ok())
          {
            return s;
          }
        }
        if (!sc.next(tok))
        {
          return sc.error("unexpected end of file in a facet");
        }
      }
      if (tok != "outer")
      {
        return sc.error("expected 'outer loop', got '" + std::string(tok.substr(0, 40)) + "'");
      }
      if (!sc.next(tok) || tok != "loop")
      {
        return sc.error("expected 'loop' after 'outer'");
      }
      loop.clear();
      while (true)
      {
        if (!sc.next(tok))
        {
          return sc.error("unexpected end of file in a facet loop");
        }
        if (tok == "endloop")
        {
          break;
        }
        if (tok != "vertex")
        {
          return sc.error("expected 'vertex' or 'endloop', got '" + std::string(tok.substr(0, 40)) + "'");
        }
        double xyz[3];
        for (int k = 0; k < 3; ++k)
        {
          s = sc.readDouble(xyz[k], "a vertex coordinate");
          if (!s.ok())
          {
            return s;
          }
        }
        loop.push_back(mesh.addPoint(xyz[0], xyz[1], xyz[2]));
      }
      if (!sc.next(tok) || tok != "endfacet")
      {
        return sc.error("expected 'endfacet'");
      }
      ++info.fileFaces;
      if (loop.size() < 3)
      {
        ++info.skippedElements;
        continue;
      }
      addPolygon(mesh, loop, solid, info, scratch);
    }
    if (strayFacets > 0)
    {
      info.warnings.push_back(std::to_string(strayFacets) + " time(s) facets followed 'endsolid' without a new 'solid'");
    }
    if (inSolid)
    {
      info.warnings.push_back("missing 'endsolid' at the end of the file");
    }
    info.solids = solid + 1;
  }
  else
  {
    if (text.size() < 84)
    {
      return readError(path, 0, "neither ASCII STL (no 'solid' keyword) nor binary STL (shorter than 84 bytes)");
    }
    return readError(path, 0, "binary STL header announces " + std::to_string(count) + " triangles (" +
      std::to_string(84 + 50 * uint64_t(count)) + " bytes) but the file has " + std::to_string(text.size()) +
      " bytes, and it is not ASCII STL either");
  }
  info.filePoints = mesh.numberOfPoints();
  fanFallbackWarning(info);
  return finish(path, mesh, &info, true);
}

} // namespace volgrid
