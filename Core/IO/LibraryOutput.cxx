// Atomic output for the library-written solver formats (see LibraryOutput.h).
#include "LibraryOutput.h"

namespace volgrid
{

Status LibraryOutput::open(const std::string& target, const char* format)
{
  Target = target;
  Format = format;
  std::string error;
  if (!Atomic.open(target, error))
    return Status::failure(ErrorKind::InvalidOption, error);
  return Status::success();
}

Status LibraryOutput::failure(const std::string& reason) const
{
  return Status::failure(ErrorKind::InvalidOption, "cannot write " + Format + " file '" + Target + "': " + reason);
}

Status LibraryOutput::commit()
{
  std::string error;
  if (!Atomic.commit(error))
    return Status::failure(ErrorKind::InvalidOption, error);
  return Status::success();
}

} // namespace volgrid
