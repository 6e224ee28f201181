// OpenFOAM polyMesh reader (ASCII, tetrahedral cells only): CASE/constant/polyMesh/{points, faces, owner,
// neighbour, boundary}. Each cell's four triangles give its tet (oriented positive from a face the cell
// owns, whose loop points out of it); boundary patches become labels 1, 2, ... in the boundary file's
// order with their names. All tets get region 1.
#include "MeshReader.h"
#include "SurfaceReaderSupport.h"

#include <algorithm>
#include <array>
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
} // namespace

bool isOpenFoamCase(const std::string& path)
{
  std::error_code ec;
  return std::filesystem::is_regular_file(path + "/constant/polyMesh/faces", ec);
}

Status readOpenFOAM(const std::string& caseDir, SolverMesh& mesh)
{
  mesh = SolverMesh();
  const std::string dir = caseDir + "/constant/polyMesh/";
  std::vector<double> faces, owner, neighbour;
  int64_t numPoints = 0, numFaces = 0, numOwner = 0, numInternal = 0;
  std::vector<Patch> patches;
  Status s = foamNumbers(dir + "points", mesh.points, numPoints);
  if (s.ok())
    s = foamNumbers(dir + "faces", faces, numFaces);
  if (s.ok())
    s = foamNumbers(dir + "owner", owner, numOwner);
  if (s.ok())
    s = foamNumbers(dir + "neighbour", neighbour, numInternal);
  if (s.ok())
    s = readBoundary(dir + "boundary", patches);
  if (!s.ok())
    return s;
  if (static_cast<int64_t>(mesh.points.size()) != 3 * numPoints || static_cast<int64_t>(faces.size()) != 4 * numFaces ||
      static_cast<int64_t>(owner.size()) != numFaces || static_cast<int64_t>(neighbour.size()) != numInternal)
    return readError(dir, 0, "inconsistent counts (only triangular faces, i.e. tetrahedral cells, are read)");
  auto loop = [&](int64_t f)
  {
    return std::array<int32_t, 3>{ static_cast<int32_t>(faces[4 * f + 1]), static_cast<int32_t>(faces[4 * f + 2]),
                                   static_cast<int32_t>(faces[4 * f + 3]) };
  };
  int64_t numCells = 0; // the highest cell number may occur as a neighbour only
  for (const std::vector<double>* cells : { &owner, &neighbour })
    for (double c : *cells)
      numCells = std::max(numCells, static_cast<int64_t>(c) + 1);
  // Per cell: its first face, whether the cell owns it (the loop then points out of the cell), and one
  // other face (for the fourth point).
  std::vector<int64_t> firstFace(numCells, -1), otherFace(numCells, -1), faceCount(numCells, 0);
  std::vector<char> owns(numCells, 0);
  auto add = [&](int64_t c, int64_t f, bool owned)
  {
    ++faceCount[c];
    if (firstFace[c] < 0)
      firstFace[c] = f, owns[c] = owned;
    else if (otherFace[c] < 0)
      otherFace[c] = f;
  };
  for (int64_t f = 0; f < numFaces; ++f)
  {
    add(static_cast<int64_t>(owner[f]), f, true);
    if (f < numInternal)
      add(static_cast<int64_t>(neighbour[f]), f, false);
  }
  for (int64_t c = 0; c < numCells; ++c)
  {
    if (faceCount[c] != 4)
      return readError(
        dir, 0, "cell " + std::to_string(c) + " is not a tetrahedron (" + std::to_string(faceCount[c]) + " faces)");
    const std::array<int32_t, 3> l = loop(firstFace[c]);
    int32_t apex = -1;
    for (int32_t v : loop(otherFace[c]))
      if (std::find(l.begin(), l.end(), v) == l.end())
        apex = v;
    if (apex < 0)
      return readError(dir, 0, "cell " + std::to_string(c) + ": no fourth point");
    // An owned face's loop points away from the apex, a neighbour's towards it: (a c b d), (a b c d).
    if (owns[c])
      mesh.tets.insert(mesh.tets.end(), { l[0], l[2], l[1], apex });
    else
      mesh.tets.insert(mesh.tets.end(), { l[0], l[1], l[2], apex });
  }
  mesh.tetRegion.assign(static_cast<size_t>(numCells), 1);
  for (size_t p = 0; p < patches.size(); ++p)
  {
    mesh.patchNames[static_cast<int32_t>(p + 1)] = patches[p].name;
    for (int64_t f = patches[p].start; f < patches[p].start + patches[p].size && f < numFaces; ++f)
    {
      const std::array<int32_t, 3> l = loop(f);
      mesh.triangles.insert(mesh.triangles.end(), l.begin(), l.end());
      mesh.trianglePatch.push_back(static_cast<int32_t>(p + 1));
    }
  }
  return Status::success();
}

} // namespace volgrid
