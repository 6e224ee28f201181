#include "AtomicStream.h"

#include "AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace volgrid
{
namespace cli
{
LatchedFileBuffer::LatchedFileBuffer(int fd)
  : Fd(fd)
  , Buffer(1 << 20)
{
  setp(Buffer.data(), Buffer.data() + Buffer.size());
}

LatchedFileBuffer::~LatchedFileBuffer()
{
  flushBuffer();
}

void LatchedFileBuffer::flushBuffer()
{
  const char* data = pbase();
  size_t left = static_cast<size_t>(pptr() - pbase());
  long long offset = Base;
  while (left > 0 && Error == 0)
  {
    const ssize_t written = ::pwrite(Fd, data, left, offset);
    if (written < 0 && errno == EINTR)
      continue;
    if (written <= 0)
    {
      Error = written < 0 ? errno : EIO;
      break;
    }
    data += written;
    left -= static_cast<size_t>(written);
    offset += written;
  }
  const long long end = Base + (pptr() - pbase());
  if (end > Size)
    Size = end;
  Base = end;
  setp(Buffer.data(), Buffer.data() + Buffer.size());
}

LatchedFileBuffer::int_type LatchedFileBuffer::overflow(int_type c)
{
  flushBuffer();
  if (!traits_type::eq_int_type(c, traits_type::eof()))
  {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int LatchedFileBuffer::sync()
{
  flushBuffer();
  return 0;
}

LatchedFileBuffer::pos_type LatchedFileBuffer::seekoff(off_type off, std::ios_base::seekdir dir,
                                                       std::ios_base::openmode which)
{
  flushBuffer();
  long long target = off;
  if (dir == std::ios_base::cur)
    target = Base + off;
  else if (dir == std::ios_base::end)
    target = Size + off;
  if (target < 0 || !(which & std::ios_base::out))
    return pos_type(off_type(-1));
  Base = target;
  return pos_type(target);
}

LatchedFileBuffer::pos_type LatchedFileBuffer::seekpos(pos_type pos, std::ios_base::openmode which)
{
  return seekoff(off_type(pos), std::ios_base::beg, which);
}

int LatchedFileBuffer::finish()
{
  flushBuffer();
  return Error;
}

bool writeStreamAtomically(const std::string& path,
                           const std::function<bool(std::ostream&, const std::string&, std::string&)>& write,
                           std::string& error)
{
  AtomicFile file;
  if (!file.open(path, error))
    return false;
  const std::string failed = "writing '" + path + "' failed: ";
  const std::string kept = " (the earlier file, if any, is unchanged)";
  const int fd = ::open(file.temporaryPath().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0)
  {
    error = failed + std::strerror(errno) + kept;
    return false;
  }
  LatchedFileBuffer buffer(fd);
  std::ostream stream(&buffer);
  std::string writerError;
  const bool written = write(stream, file.temporaryPath(), writerError);
  const int writeError = buffer.finish();
  ::close(fd); // AtomicFile's own descriptor is the one whose fsync and close commit() checks
  if (writeError != 0 || !written)
  {
    error = failed + (writeError != 0 ? std::string(std::strerror(writeError)) : writerError) + kept;
    return false;
  }
  return file.commit(error, buffer.size());
}
} // namespace cli
} // namespace volgrid
