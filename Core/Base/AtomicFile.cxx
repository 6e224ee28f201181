#include "AtomicFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace volgrid
{

namespace
{
std::string reason(int err)
{
  return std::strerror(err);
}

std::string directoryOf(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// "dir/.name.volgrid-XXXXXX.ext": hidden, beside the target, with the target's extension.
std::string temporaryTemplate(const std::string& target, size_t& suffixLength)
{
  const size_t slash = target.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : target.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? target : target.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  const std::string ext = dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
  suffixLength = ext.size();
  return dir + "." + name + ".volgrid-XXXXXX" + ext;
}

bool refuseNonRegular(const std::string& target, std::string& error)
{
  struct stat st
  {
  };
  if (::stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
  {
    error = "cannot write '" + target + "': it exists and is not a regular file" +
      (S_ISDIR(st.st_mode) ? " (it is a directory)" : " (a device, pipe or socket)");
    return false;
  }
  return true;
}

// Mode of the new file: the existing target's, else 0666 minus the umask.
mode_t finalMode(const std::string& target)
{
  struct stat st
  {
  };
  if (::stat(target.c_str(), &st) == 0)
    return st.st_mode & 07777;
  const mode_t mask = ::umask(022);
  ::umask(mask);
  return 0666 & ~mask;
}
} // namespace

AtomicFile::~AtomicFile()
{
  if (Fd >= 0)
    ::close(Fd);
  if (!Temporary.empty())
    ::unlink(Temporary.c_str());
}

bool AtomicFile::open(const std::string& target, std::string& error)
{
  if (!refuseNonRegular(target, error))
    return false;
  size_t suffix = 0;
  std::string name = temporaryTemplate(target, suffix);
  const int fd = ::mkstemps(name.data(), static_cast<int>(suffix));
  if (fd < 0)
  {
    error = "cannot write '" + target + "': cannot create a file in '" + directoryOf(target) + "': " + reason(errno);
    return false;
  }
  Target = target;
  Temporary = name;
  Fd = fd;
  return true;
}

bool AtomicFile::write(const char* data, size_t size, std::string& error)
{
  while (size > 0)
  {
    const size_t piece = size < (size_t(1) << 30) ? size : (size_t(1) << 30);
    const ssize_t n = ::write(Fd, data, piece);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
    {
      error =
        "writing '" + Target + "' failed: " + reason(n < 0 ? errno : EIO) + " (the earlier file, if any, is unchanged)";
      return false;
    }
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool AtomicFile::commit(std::string& error, long long expectedSize)
{
  const std::string failed = "writing '" + Target + "' failed: ";
  const std::string kept = " (the earlier file, if any, is unchanged)";
  struct stat st
  {
  };
  if (::fstat(Fd, &st) != 0)
  {
    error = failed + reason(errno) + kept;
    return false;
  }
  if (expectedSize >= 0 && static_cast<long long>(st.st_size) != expectedSize)
  {
    error = failed + "only " + std::to_string(st.st_size) + " of " + std::to_string(expectedSize) +
      " bytes were written (disk full or file size limit?)" + kept;
    return false;
  }
  ::fchmod(Fd, finalMode(Target));
  const bool synced = ::fsync(Fd) == 0 || errno == EINVAL || errno == EROFS;
  const int syncErrno = errno;
  const bool closed = ::close(Fd) == 0;
  const int closeErrno = errno;
  Fd = -1;
  if (!synced || !closed)
  {
    error = failed + reason(!synced ? syncErrno : closeErrno) + kept;
    return false;
  }
  if (::rename(Temporary.c_str(), Target.c_str()) != 0)
  {
    error = "cannot replace '" + Target + "': " + reason(errno) + kept;
    return false;
  }
  Temporary.clear();
  return true;
}

bool writeFileAtomically(const std::string& target, const std::string& bytes, std::string& error)
{
  AtomicFile file;
  return file.open(target, error) && file.write(bytes.data(), bytes.size(), error) && file.commit(error);
}

bool probeWritable(const std::string& target, std::string& error)
{
  AtomicFile probe; // removed again when it goes out of scope
  return probe.open(target, error);
}

} // namespace volgrid
