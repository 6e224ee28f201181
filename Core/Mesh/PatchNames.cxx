// Patch and region names: defaults, the user's `--patch NAME=ID,...` grouping, OpenFOAM's word rule.
#include "PatchNames.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <set>

namespace volgrid
{
namespace
{
bool parseLabel(const std::string& text, int32_t& value)
{
  if (text.empty())
    return false;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || v < INT32_MIN || v > INT32_MAX)
    return false;
  value = static_cast<int32_t>(v);
  return true;
}
} // namespace

std::string labelName(const NameTable& names, int32_t label, const char* prefix)
{
  const auto it = names.find(label);
  if (it != names.end() && !it->second.empty())
    return it->second;
  return std::string(prefix) + std::to_string(label);
}

Status parsePatchAssignment(const std::string& text, PatchAssignment& assignment)
{
  size_t start = 0;
  bool current = false; // a group is open for bare ids
  while (start <= text.size())
  {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string token = text.substr(start, comma - start);
    start = comma + 1;
    std::string idText = token;
    const size_t eq = token.find('=');
    if (eq != std::string::npos)
    {
      const std::string name = token.substr(0, eq);
      if (name.empty())
        return Status::failure(ErrorKind::InvalidOption, "--patch: empty name in '" + token + "'");
      assignment.names.push_back(name);
      assignment.ids.emplace_back();
      current = true;
      idText = token.substr(eq + 1);
    }
    int32_t id = 0;
    if (!current)
      return Status::failure(ErrorKind::InvalidOption, "--patch: '" + token + "' comes before any NAME=ID");
    if (!parseLabel(idText, id))
      return Status::failure(ErrorKind::InvalidOption, "--patch: '" + idText + "' is not a patch id");
    assignment.ids.back().push_back(id);
  }
  return Status::success();
}

Status applyPatchAssignment(const PatchAssignment& assignment, std::vector<int32_t>& labels, NameTable& names)
{
  std::map<int32_t, int32_t> newLabel;
  const std::set<int32_t> present(labels.begin(), labels.end());
  for (size_t g = 0; g < assignment.names.size(); ++g)
  {
    for (int32_t id : assignment.ids[g])
    {
      if (!newLabel.emplace(id, static_cast<int32_t>(g + 1)).second)
        return Status::failure(ErrorKind::InvalidOption,
                               "--patch: patch id " + std::to_string(id) + " is assigned twice");
      if (!present.count(id))
        return Status::failure(ErrorKind::InvalidOption,
                               "--patch: no boundary triangle has patch id " + std::to_string(id));
    }
  }
  NameTable renamed;
  for (size_t g = 0; g < assignment.names.size(); ++g)
    renamed[static_cast<int32_t>(g + 1)] = assignment.names[g];
  int32_t next = static_cast<int32_t>(assignment.names.size()) + 1;
  for (int32_t id : present)
  {
    if (newLabel.count(id))
      continue;
    newLabel[id] = next;
    renamed[next++] = labelName(names, id, "patch");
  }
  for (int32_t& l : labels)
    l = newLabel[l];
  names = renamed;
  return Status::success();
}

bool isOpenFoamWord(const std::string& name)
{
  if (name.empty())
    return false;
  for (char c : name)
  {
    if (c <= ' ' || c > '~')
      return false;
    if (std::string("\"'/\\;{}()[]#$").find(c) != std::string::npos)
      return false;
  }
  return true;
}

} // namespace volgrid
