// Internal to the readers of SurfaceReader.h (one format per file: OffReader, MeditReader,
// TetGenPolyReader, GmshReader, StlReader, PlyReader): loading a file, error messages that name the file
// and the line, whole-token number parsing, a whitespace tokenizer that counts lines, and the common end
// of every read (finite check, optional merge). Not part of the Core API.
#pragma once

#include "Status.h"
#include "SurfaceMesh.h"
#include "SurfaceReader.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace volgrid::detail
{

// The extension after the last dot of the file name, lower-cased; empty when there is none. A trailing
// ".gz" is skipped: "wing.STL.gz" gives "stl" (loadFile decompresses such files).
std::string lowerExtension(const std::string& path);

// "path:line: what" as an ErrorKind::InvalidOption status (line <= 0: no line number).
Status readError(const std::string& path, int64_t line, const std::string& what);

// Success when `path` is a regular file that can be opened; otherwise names the problem ("is a
// directory", "does not exist", the OS reason).
Status checkRegularFile(const std::string& path);

// Size in bytes of a regular file (-1 when it cannot be determined).
int64_t fileSize(const std::string& path);

// Reads the whole file (binary mode) into text; a file whose name ends in ".gz" is decompressed.
Status loadFile(const std::string& path, std::string& text);

// The start every text reader shares: the mesh cleared, the caller's info (or a local one when it passed
// none) reset with the format's name, the whole file read into `text` (`loaded` says whether it was).
class ReadStart
{
public:
  ReadStart(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const char* format);
  ReadStart(const ReadStart&) = delete;
  ReadStart& operator=(const ReadStart&) = delete;

private:
  SurfaceReadInfo Own; // before `info`, which may refer to it

public:
  SurfaceReadInfo& info;
  std::string text;
  Status loaded;
};

// True when the whole token is a number (a leading '+' is allowed).
bool parseDouble(std::string_view tok, double& value);
bool parseInt(std::string_view tok, int64_t& value);

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
int64_t countLimit(const std::string& text);

// Finishes a read: finite check, optional merge, info.
Status finish(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info, bool merge);

// Adds a polygon face (point ids already validated) as triangles.
void addPolygon(SurfaceMesh& mesh, const std::vector<int32_t>& loop, int32_t patch, SurfaceReadInfo& info,
                std::vector<int32_t>& scratch);

// Adds the warning about polygons that were fan-triangulated, when there were any.
void fanFallbackWarning(SurfaceReadInfo& info);

} // namespace volgrid::detail
