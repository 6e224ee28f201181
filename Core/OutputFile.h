// An output file that appears only when complete: written to a temporary file beside the target,
// renamed over it on commit(). A failed or abandoned write removes the temporary file and leaves no
// partial file; errors name the path and the operating system's reason.
#pragma once

#include "Status.h"

#include <cstdio>
#include <string>

namespace volgrid
{

class OutputFile
{
public:
  OutputFile() = default;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile(); // removes the temporary file unless committed

  // Opens "<path>.volgrid-tmp-<pid>" for writing.
  Status open(const std::string& path);
  std::FILE* stream() { return File; }
  // Flushes, closes, checks for write errors and renames the temporary file to the target.
  Status commit();

private:
  std::string Path, TempPath;
  std::FILE* File = nullptr;
  bool Committed = false;
};

// The error for `path`: "cannot <what> '<path>': <strerror(errno)>".
Status fileError(const std::string& what, const std::string& path);

} // namespace volgrid
