// Writing a file without ever leaving a half-written or clobbered target: the bytes go to a temporary
// file beside the target (same directory, so the final rename is atomic), every write() is looped and
// checked, the data is flushed to disk and the file closed with its result checked, and only then is the
// temporary renamed over the target. On any failure the temporary is removed, the target is left as it
// was, and `error` says which path failed and the operating system's reason ("No space left on device").
//
// Writers of any format use it: either hand over the bytes (writeFileAtomically), or let a writer that
// wants a file name write the temporary (AtomicFile::temporaryPath) and then commit().
#pragma once

#include <string>

namespace volgrid
{

class AtomicFile
{
public:
  AtomicFile() = default;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile(); // removes the temporary unless commit() succeeded

  // Creates the temporary beside `target` (a hidden name keeping the target's extension). Refuses a target
  // that exists and is not a regular file (a directory, /dev/full, a pipe): renaming over it would replace it.
  bool open(const std::string& target, std::string& error);
  const std::string& temporaryPath() const { return Temporary; }

  // Appends bytes (write() looped until all are written). The temporary is open from open() to commit().
  bool write(const char* data, size_t size, std::string& error);

  // Flushes, closes (checking both) and renames the temporary over the target. When a writer filled the
  // temporary by name, `expectedSize` (if >= 0) is compared with the file's size to catch silent truncation.
  bool commit(std::string& error, long long expectedSize = -1);

private:
  std::string Target;
  std::string Temporary;
  int Fd = -1;
};

// The whole file at once.
bool writeFileAtomically(const std::string& target, const std::string& bytes, std::string& error);

// Checks, before any work, that `target` could be written: the directory exists and accepts a new file (a
// probe file is created and removed), and the target is not an existing non-regular file.
bool probeWritable(const std::string& target, std::string& error);

} // namespace volgrid
