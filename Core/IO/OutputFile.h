// An output file written through a C stream that appears only when complete: the stream fills
// AtomicFile's temporary beside the target, and commit() checks every write, then renames it over the
// target. A failed or abandoned write leaves no partial file and the earlier file untouched; errors name
// the path and the operating system's reason. For writers that print text (the solver formats).
#pragma once

#include "AtomicFile.h"
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
  ~OutputFile(); // closes the stream; AtomicFile removes the temporary unless committed

  Status open(const std::string& path);
  std::FILE* stream() { return File; }
  // Flushes and closes the stream (checking both), then commits the temporary (size checked).
  Status commit();

private:
  std::string Path;
  AtomicFile Atomic;
  std::FILE* File = nullptr;
};

// The error for `path`: "cannot <what> '<path>': <strerror(errno)>".
Status fileError(const std::string& what, const std::string& path);

} // namespace volgrid
