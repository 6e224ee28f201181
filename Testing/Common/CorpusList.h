// The shared corpus (../shared/data/real) as the tests see it: which files are clean closed surfaces,
// read from the watertight and defect columns of its SOURCES.md.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace volgrid_testing
{
// The cells of one markdown table row, trimmed ("| a | b |" -> {"", "a", "b"}).
inline std::vector<std::string> tableCells(const std::string& line)
{
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, '|'))
  {
    const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
    cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  return cells;
}

// Files marked watertight YES whose only listed defects are polygon faces or orientation.
inline std::vector<std::string> cleanClosedCorpusFiles(const std::string& dataDir)
{
  std::vector<std::string> files;
  std::ifstream in(dataDir + "/SOURCES.md");
  std::string line;
  while (std::getline(in, line))
  {
    if (line.size() < 2 || line[0] != '|')
      continue;
    const std::vector<std::string> cells = tableCells(line);
    if (cells.size() < 10 || cells[6] != "YES")
      continue;
    bool clean = true;
    if (cells[9] != "none found")
    {
      std::stringstream defects(cells[9]);
      std::string item;
      while (std::getline(defects, item, ';'))
        if (item.find("non-triangle faces") == std::string::npos &&
            item.find("inconsistently oriented edges") == std::string::npos)
          clean = false;
    }
    if (clean)
      files.push_back(cells[1]);
  }
  return files;
}

inline bool endsWith(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}
} // namespace volgrid_testing
