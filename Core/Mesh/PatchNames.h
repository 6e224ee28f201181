// Names of boundary patches and volume regions: the side table that travels with the integer PatchId
// and Region labels from the readers (Medit refs, STL solid names, gmsh $PhysicalNames, "farfield" for a
// generated enclosure) to the solver writers, and the user's renaming (`--patch NAME=ID,...`).
#pragma once

#include "Status.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace volgrid
{
using NameTable = std::map<int32_t, std::string>; // label -> name (labels without an entry get a default)

// The name of `label` in `names`, or "<prefix><label>" (e.g. "patch3", "region0") when it has none.
std::string labelName(const NameTable& names, int32_t label, const char* prefix);

// The user's grouping of input patch ids under new names, in the order given: group k gets label k + 1.
struct PatchAssignment
{
  std::vector<std::string> names;
  std::vector<std::vector<int32_t>> ids; // input patch ids of each group
  bool empty() const { return names.empty(); }
};

// Parses "NAME=ID,ID,NAME=ID,..." (a token with '=' starts a group, a bare id adds to the current one)
// and appends to `assignment` (the option may be given several times). Errors name the bad token.
Status parsePatchAssignment(const std::string& text, PatchAssignment& assignment);

// Relabels `labels` in place: ids of group k become k + 1; every other id gets its own new label after
// the groups (ascending old id), keeping its old name from `names` or "patch<old>". `names` is replaced
// by the new table. Fails (and changes nothing) when the assignment names an id twice or an id that no
// label carries.
Status applyPatchAssignment(const PatchAssignment& assignment, std::vector<int32_t>& labels, NameTable& names);

// True for a valid OpenFOAM word: non-empty, printable ASCII, none of space " ' / \ ; { } ( ) [ ] # $.
bool isOpenFoamWord(const std::string& name);

} // namespace volgrid
