// Streaming a writer's output into an atomically replaced file (Core/Base/AtomicFile.h), for writers that
// want a std::ostream (VTK's XML and legacy writers): nothing is held in memory, and the target is replaced
// only when every byte reached the disk.
//
// LatchedFileBuffer: a seekable output stream buffer over a file descriptor that never reports a failed
// write to its stream: the first error (errno) is latched, later bytes are dropped, and the owner asks
// afterwards. Why: VTK 9.2's XML writers crash on their own error path in inline mode (a write that fails
// part-way, e.g. past `ulimit -f`, ends in a free() of position arrays that inline mode never allocated).
// With this buffer VTK always sees success, and one clear message reports the failure.
#ifndef volgrid_cli_AtomicStream_h
#define volgrid_cli_AtomicStream_h

#include <functional>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace volgrid
{
namespace cli
{
class LatchedFileBuffer : public std::streambuf
{
public:
  // fd: open for writing, positioned anywhere (pwrite is used); not closed here.
  explicit LatchedFileBuffer(int fd);
  ~LatchedFileBuffer() override;

  // Writes the buffered bytes. Returns the latched errno, 0 when every byte so far reached the file.
  int finish();
  // The file's size as written: one past the furthest byte.
  long long size() const { return Size; }

protected:
  int_type overflow(int_type c) override;
  int sync() override;
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode which) override;
  pos_type seekpos(pos_type pos, std::ios_base::openmode which) override;

private:
  void flushBuffer();

  int Fd;
  int Error = 0;
  long long Base = 0; // file offset of the buffer's first byte
  long long Size = 0;
  std::vector<char> Buffer;
};

// Opens the temporary beside `path`, calls write(stream, temporaryPath) (false: the writer failed, with its
// reason in `writerError`), and renames the temporary over `path` only when the writer succeeded and every
// byte was written. On failure `error` names `path` and the reason; the earlier file is unchanged.
bool writeStreamAtomically(const std::string& path,
                           const std::function<bool(std::ostream&, const std::string&, std::string&)>& write,
                           std::string& error);
} // namespace cli
} // namespace volgrid

#endif
