// Checks on an output path made before any work starts, so that a run never ends with nothing written
// or with the user's input overwritten: the extension is one a writer handles, the path does not name
// one of the inputs (the same file under another name included), and its directory accepts a new file.
#pragma once

#include <string>
#include <vector>

namespace volgrid
{
namespace cli
{
// `role` names the output in messages ("OUT", "--boundary"). `extensions`: lower case, no dot. Prints
// "volgrid COMMAND: ..." to stderr and returns the exit code (2: bad argument, 1: not writable); 0 when fine.
int checkOutputPath(const char* command, const char* role, const std::string& out,
                    const std::vector<std::string>& extensions, const std::vector<std::string>& inputs);

// True when both paths name the same existing file (same device and inode).
bool sameFile(const std::string& a, const std::string& b);
} // namespace cli
} // namespace volgrid
