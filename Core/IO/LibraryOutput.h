// An output file written by a C library that wants a file name (CGNS, Exodus II): the library writes
// AtomicFile's temporary beside the target, and commit() renames it over the target only after the
// library closed it without error. An abandoned write leaves no partial file and the earlier file as it was.
#pragma once

#include "AtomicFile.h"
#include "Status.h"

#include <string>

namespace volgrid
{

class LibraryOutput
{
public:
  // Creates the temporary; `format` names the file kind in errors ("CGNS", "Exodus II").
  Status open(const std::string& target, const char* format);
  // The name the library writes to.
  const std::string& temporaryPath() const { return Atomic.temporaryPath(); }
  // The error for a library failure: "cannot write FORMAT file 'TARGET': REASON".
  Status failure(const std::string& reason) const;
  Status commit();

private:
  std::string Target;
  std::string Format;
  AtomicFile Atomic;
};

} // namespace volgrid
