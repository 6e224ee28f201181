// OutputFile: a C stream over AtomicFile's temporary file.
#include "OutputFile.h"

#include <cerrno>
#include <cstring>

namespace volgrid
{

Status fileError(const std::string& what, const std::string& path)
{
  return Status::failure(ErrorKind::InvalidOption, "cannot " + what + " '" + path + "': " + std::strerror(errno));
}

OutputFile::~OutputFile()
{
  if (File)
    std::fclose(File);
}

Status OutputFile::open(const std::string& path)
{
  Path = path;
  std::string error;
  if (!Atomic.open(path, error))
    return Status::failure(ErrorKind::InvalidOption, error);
  File = std::fopen(Atomic.temporaryPath().c_str(), "wb");
  if (!File)
    return fileError("write", path);
  return Status::success();
}

Status OutputFile::commit()
{
  if (!File)
    return Status::failure(ErrorKind::InvalidOption, "cannot write '" + Path + "': not open");
  const bool bad = std::fflush(File) != 0 || std::ferror(File) != 0;
  const int savedErrno = errno;
  const long size = bad ? -1 : std::ftell(File);
  const bool closeFailed = std::fclose(File) != 0;
  File = nullptr;
  if (bad || closeFailed || size < 0)
  {
    errno = bad ? savedErrno : errno;
    return fileError("write", Path);
  }
  std::string error;
  if (!Atomic.commit(error, size))
    return Status::failure(ErrorKind::InvalidOption, error);
  return Status::success();
}

} // namespace volgrid
