#include "NodeFile.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace volgrid
{
namespace
{
// Next line with content, comments stripped; false at end of file.
bool nextDataLine(std::istream& in, std::string& line, long& lineNumber)
{
  while (std::getline(in, line))
  {
    ++lineNumber;
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      return true;
    }
  }
  return false;
}
} // namespace

Status readNodeFile(const std::string& path, std::vector<double>& xyz)
{
  std::ifstream in(path);
  if (!in)
  {
    return Status::failure(ErrorKind::EmptyInput, "cannot open '" + path + "'");
  }
  std::string line;
  long lineNumber = 0;
  auto fail = [&](const std::string& what)
  { return Status::failure(ErrorKind::EmptyInput, path + ":" + std::to_string(lineNumber) + ": " + what); };
  if (!nextDataLine(in, line, lineNumber))
  {
    return fail("no header line");
  }
  long count = -1, dimension = -1, attributes = 0, markers = 0;
  std::istringstream header(line);
  header >> count >> dimension;
  if (!header || count < 0)
  {
    return fail("header must start with the point count and the dimension");
  }
  header >> attributes >> markers;
  if (dimension != 3)
  {
    return fail("dimension " + std::to_string(dimension) + " is not supported (3 expected)");
  }
  xyz.clear();
  xyz.reserve(3 * static_cast<size_t>(count));
  for (long i = 0; i < count; ++i)
  {
    if (!nextDataLine(in, line, lineNumber))
    {
      return fail("file ends after " + std::to_string(i) + " of " + std::to_string(count) + " points");
    }
    // strtod, unlike iostreams, reads "nan" and "inf": the kernel then reports them by id.
    const char* cursor = line.c_str();
    char* end = nullptr;
    std::strtol(cursor, &end, 10);
    if (end == cursor)
    {
      return fail("expected '<id> x y z'");
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      cursor = end;
      const double value = std::strtod(cursor, &end);
      if (end == cursor)
      {
        return fail("expected '<id> x y z'");
      }
      xyz.push_back(value);
    }
  }
  return Status::success();
}

} // namespace volgrid
