#include "LatchedFileBuffer.h"

#include <cerrno>
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
} // namespace cli
} // namespace volgrid
