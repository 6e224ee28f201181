// OutputFile: temporary file beside the target, renamed over it when complete.
#include "OutputFile.h"

#include <cerrno>
#include <cstring>
#include <unistd.h>

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
  if (!Committed && !TempPath.empty())
    std::remove(TempPath.c_str());
}

Status OutputFile::open(const std::string& path)
{
  Path = path;
  TempPath = path + ".volgrid-tmp-" + std::to_string(static_cast<long>(getpid()));
  File = std::fopen(TempPath.c_str(), "wb");
  if (!File)
  {
    const Status s = fileError("write", path);
    TempPath.clear();
    return s;
  }
  return Status::success();
}

Status OutputFile::commit()
{
  if (!File)
    return Status::failure(ErrorKind::InvalidOption, "cannot write '" + Path + "': not open");
  const bool bad = std::fflush(File) != 0 || std::ferror(File) != 0;
  const int savedErrno = errno;
  const bool closeFailed = std::fclose(File) != 0;
  File = nullptr;
  if (bad || closeFailed)
  {
    errno = bad ? savedErrno : errno;
    return fileError("write", Path);
  }
  if (std::rename(TempPath.c_str(), Path.c_str()) != 0)
    return fileError("rename the temporary file to", Path);
  Committed = true;
  return Status::success();
}

} // namespace volgrid
