// OpenFOAM polyMesh reader (ASCII): CASE/constant/polyMesh/{points, faces, owner, neighbour, boundary}.
// Faces are triangles or quads; a cell of four triangles is a tet, of two triangles and three quads a
// prism, of one quad and four triangles a pyramid, each put together from its faces' loops turned out of
// the cell (an owner's loop points out of it, a neighbour's into it): positive volume for a valid mesh,
// prisms and pyramids in SolverMesh's order. Boundary patches become labels 1, 2, ... in the boundary
// file's order with their names, their faces boundary triangles and quads. All cells get region 1.
#include "MeshReader.h"
#include "SurfaceReaderSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace volgrid
{

using namespace detail;

namespace
{
// The file's tokens after its FoamFile header, with comments removed and ( ) { } ; as tokens of their own.
Status foamTokens(const std::string& path, std::vector<std::string>& tokens)
{
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
    return s;
  tokens.clear();
  std::string cur;
  auto flush = [&]
  {
    if (!cur.empty())
      tokens.push_back(cur), cur.clear();
  };
  for (size_t i = 0; i < text.size(); ++i)
  {
    const char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/')
      i = std::min(text.find('\n', i), text.size());
    else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*')
      i = std::min(text.find("*/", i + 2), text.size() - 1) + 1;
    else if (c == '(' || c == ')' || c == '{' || c == '}' || c == ';')
      flush(), tokens.push_back(std::string(1, c));
    else if (std::isspace(static_cast<unsigned char>(c)))
      flush();
    else
      cur += c;
  }
  flush();
  if (!tokens.empty() && tokens[0] == "FoamFile") // drop the header dictionary
  {
    const auto close = std::find(tokens.begin(), tokens.end(), "}");
    tokens.erase(tokens.begin(), close == tokens.end() ? close : close + 1);
  }
  if (tokens.size() < 3 || tokens[1] != "(")
    return readError(path, 0, "expected 'N ( ... )' after the FoamFile header");
  return Status::success();
}

// The numbers of a list "N ( ... )", with any parentheses inside skipped (points, "3(a b c)" faces).
Status foamNumbers(const std::string& path, std::vector<double>& values, int64_t& count)
{
  std::vector<std::string> tokens;
  Status s = foamTokens(path, tokens);
  if (!s.ok())
    return s;
  count = std::atoll(tokens[0].c_str());
  values.clear();
  for (size_t i = 2; i + 1 < tokens.size(); ++i)
    if (tokens[i] != "(" && tokens[i] != ")")
      values.push_back(std::atof(tokens[i].c_str()));
  return Status::success();
}

struct Patch
{
  std::string name;
  int64_t start = 0, size = 0;
};

Status readBoundary(const std::string& path, std::vector<Patch>& patches)
{
  std::vector<std::string> t;
  Status s = foamTokens(path, t);
  for (size_t i = 2; s.ok() && i + 1 < t.size(); ++i)
  {
    if (t[i + 1] != "{")
      continue;
    Patch p;
    p.name = t[i];
    for (i += 2; i + 1 < t.size() && t[i] != "}"; ++i)
    {
      if (t[i] == "nFaces")
        p.size = std::atoll(t[i + 1].c_str());
      else if (t[i] == "startFace")
        p.start = std::atoll(t[i + 1].c_str());
    }
    patches.push_back(p);
  }
  return s;
}

// The faces as point lists: face f is points[start[f] .. start[f + 1]).
struct FoamFaces
{
  std::vector<int64_t> start{ 0 };
  std::vector<int32_t> points;
  int size(int64_t f) const { return static_cast<int>(start[f + 1] - start[f]); }
  const int32_t* at(int64_t f) const { return points.data() + start[f]; }
};

// The flat "n p1 .. pn" values of the faces file as triangles and quads of points below numPoints.
Status parseFaces(const std::string& path, const std::vector<double>& values, int64_t numFaces, int64_t numPoints,
                  FoamFaces& faces)
{
  size_t i = 0;
  for (int64_t f = 0; f < numFaces; ++f)
  {
    const double n = i < values.size() ? values[i++] : 0;
    if (n != 3 && n != 4)
      return readError(path, 0,
                       "face " + std::to_string(f) + " has " + std::to_string(static_cast<int64_t>(n)) +
                         " points (only triangles and quads are read)");
    if (i + static_cast<size_t>(n) > values.size())
      return readError(path, 0, "the list ends inside face " + std::to_string(f));
    for (int k = 0; k < n; ++k, ++i)
    {
      if (!(values[i] >= 0 && values[i] < static_cast<double>(numPoints)) || values[i] != std::floor(values[i]))
        return readError(path, 0,
                         "face " + std::to_string(f) + " names point " + std::to_string(values[i]) + " of " +
                           std::to_string(numPoints));
      faces.points.push_back(static_cast<int32_t>(values[i]));
    }
    faces.start.push_back(static_cast<int64_t>(faces.points.size()));
  }
  if (i != values.size())
    return readError(path, 0, "more values than " + std::to_string(numFaces) + " faces");
  return Status::success();
}

// A cell's face: the face and whether the cell owns it.
struct CellFaceRef
{
  int64_t face;
  bool owned;
};

// Face f's loop turned out of the cell (kept from its first point); its size.
int outwardLoop(const FoamFaces& faces, CellFaceRef r, int32_t (&loop)[4])
{
  const int n = faces.size(r.face);
  const int32_t* p = faces.at(r.face);
  for (int k = 0; k < n; ++k)
    loop[k] = p[r.owned || k == 0 ? k : n - k];
  return n;
}

bool contains(const int32_t* loop, int n, int32_t v)
{
  return std::find(loop, loop + n, v) != loop + n;
}

// The cell of faces `refs` into `mesh`; false when its faces make no tet, prism or pyramid.
bool addCell(const FoamFaces& faces, const CellFaceRef* refs, int numFaces, SolverMesh& mesh)
{
  int32_t loops[5][4];
  int sizes[5], triangles[5], quads[5], numTriangles = 0, numQuads = 0;
  for (int k = 0; k < numFaces; ++k)
  {
    sizes[k] = outwardLoop(faces, refs[k], loops[k]);
    (sizes[k] == 3 ? triangles[numTriangles++] : quads[numQuads++]) = k;
  }
  if (numTriangles == 4 && numQuads == 0) // tet: the outward triangle (a c b) and the fourth point d
  {
    const int32_t* t = loops[0];
    for (int k = 0; k < 3; ++k)
      if (!contains(t, 3, loops[1][k]))
      {
        mesh.tets.insert(mesh.tets.end(), { t[0], t[2], t[1], loops[1][k] });
        mesh.tetRegion.push_back(1);
        return true;
      }
    return false;
  }
  if (numTriangles == 4 && numQuads == 1) // pyramid: the outward quad reversed turns towards the apex
  {
    const int32_t* q = loops[quads[0]];
    for (int k = 0; k < 3; ++k)
      if (!contains(q, 4, loops[triangles[0]][k]))
      {
        mesh.pyramids.insert(mesh.pyramids.end(), { q[0], q[3], q[2], q[1], loops[triangles[0]][k] });
        mesh.pyramidRegion.push_back(1);
        return true;
      }
    return false;
  }
  if (numTriangles != 2 || numQuads != 3)
    return false;
  // Prism: the base is the first triangle's outward loop reversed (its normal into the cell, towards the
  // top); each base point's top point is its neighbour across a side quad.
  const int32_t* bottom = loops[triangles[0]];
  const int32_t* top = loops[triangles[1]];
  const int32_t base[3] = { bottom[0], bottom[2], bottom[1] };
  int32_t above[3] = { -1, -1, -1 };
  for (int s = 0; s < 3; ++s)
    for (int k = 0; k < 4; ++k)
    {
      const int32_t u = loops[quads[s]][k], w = loops[quads[s]][(k + 1) % 4];
      for (int b = 0; b < 3; ++b)
      {
        if (u == base[b] && contains(top, 3, w))
          above[b] = w;
        if (w == base[b] && contains(top, 3, u))
          above[b] = u;
      }
    }
  if (above[0] < 0 || above[1] < 0 || above[2] < 0 || above[0] == above[1] || above[1] == above[2] ||
      above[0] == above[2])
    return false;
  mesh.prisms.insert(mesh.prisms.end(), { base[0], base[1], base[2], above[0], above[1], above[2] });
  mesh.prismRegion.push_back(1);
  return true;
}

Status readPolyMesh(const std::string& caseDir, SolverMesh& mesh)
{
  const std::string dir = caseDir + "/constant/polyMesh/";
  std::vector<double> faceValues, owner, neighbour;
  int64_t numPoints = 0, numFaces = 0, numOwner = 0, numInternal = 0;
  std::vector<Patch> patches;
  FoamFaces faces;
  Status s = foamNumbers(dir + "points", mesh.points, numPoints);
  if (s.ok())
    s = foamNumbers(dir + "faces", faceValues, numFaces);
  if (s.ok())
    s = foamNumbers(dir + "owner", owner, numOwner);
  if (s.ok())
    s = foamNumbers(dir + "neighbour", neighbour, numInternal);
  if (s.ok())
    s = readBoundary(dir + "boundary", patches);
  if (!s.ok())
    return s;
  if (static_cast<int64_t>(mesh.points.size()) != 3 * numPoints || numFaces < 0 ||
      static_cast<int64_t>(owner.size()) != numFaces || static_cast<int64_t>(neighbour.size()) != numInternal ||
      numInternal > numFaces)
    return readError(dir, 0, "inconsistent counts of points, faces, owners and neighbours");
  s = parseFaces(dir + "faces", faceValues, numFaces, numPoints, faces);
  if (!s.ok())
    return s;
  int64_t numCells = 0; // the highest cell number may occur as a neighbour only; a cell has 4 faces or more
  for (const std::vector<double>* cells : { &owner, &neighbour })
    for (double c : *cells)
    {
      if (!(c >= 0 && c < static_cast<double>(numFaces)))
        return readError(dir, 0, "a face's owner or neighbour is cell " + std::to_string(c));
      numCells = std::max(numCells, static_cast<int64_t>(c) + 1);
    }
  // Each cell's faces (at most 5 kept: more make it no tet, prism or pyramid), its triangles and quads.
  std::vector<std::array<int, 2>> sizes(static_cast<size_t>(numCells), { 0, 0 });
  std::vector<CellFaceRef> cellFaces(static_cast<size_t>(5 * numCells));
  auto add = [&](int64_t c, int64_t f, bool owned)
  {
    const int count = sizes[c][0] + sizes[c][1];
    if (count < 5)
      cellFaces[static_cast<size_t>(5 * c + count)] = { f, owned };
    ++sizes[c][faces.size(f) - 3];
  };
  for (int64_t f = 0; f < numFaces; ++f)
  {
    add(static_cast<int64_t>(owner[f]), f, true);
    if (f < numInternal)
      add(static_cast<int64_t>(neighbour[f]), f, false);
  }
  for (int64_t c = 0; c < numCells; ++c)
  {
    const int count = sizes[c][0] + sizes[c][1];
    if (count < 4 || count > 5 || !addCell(faces, &cellFaces[static_cast<size_t>(5 * c)], count, mesh))
      return readError(dir, 0,
                       "cell " + std::to_string(c) + " is not a tetrahedron, prism or pyramid (" +
                         std::to_string(count) + " faces: " + std::to_string(sizes[c][0]) + " triangles, " +
                         std::to_string(sizes[c][1]) + " quads)");
  }
  for (size_t p = 0; p < patches.size(); ++p)
  {
    mesh.patchNames[static_cast<int32_t>(p + 1)] = patches[p].name;
    for (int64_t f = std::max<int64_t>(patches[p].start, 0); f < patches[p].start + patches[p].size && f < numFaces;
         ++f)
    {
      const bool quad = faces.size(f) == 4;
      (quad ? mesh.quads : mesh.triangles)
        .insert((quad ? mesh.quads : mesh.triangles).end(), faces.at(f), faces.at(f) + faces.size(f));
      (quad ? mesh.quadPatch : mesh.trianglePatch).push_back(static_cast<int32_t>(p + 1));
    }
  }
  if (!finishReadCells(mesh))
    return readError(dir, 0, "no cells");
  return Status::success();
}

} // namespace

bool isOpenFoamCase(const std::string& path)
{
  std::error_code ec;
  return std::filesystem::is_regular_file(path + "/constant/polyMesh/faces", ec);
}

Status readOpenFOAM(const std::string& caseDir, SolverMesh& mesh)
{
  mesh = SolverMesh();
  const Status s = readPolyMesh(caseDir, mesh);
  if (!s.ok())
    mesh = SolverMesh();
  return s;
}

} // namespace volgrid
