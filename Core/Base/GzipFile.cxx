#include "GzipFile.h"

#include <zlib.h>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <limits>
#include <new>

namespace volgrid
{

namespace
{
Status gzipError(const std::string& path, const std::string& what)
{
  return Status::failure(ErrorKind::InvalidOption, path + ": " + what);
}

bool hasGzipMagic(const std::string& data, size_t at)
{
  return data.size() >= at + 2 && static_cast<unsigned char>(data[at]) == 0x1f &&
    static_cast<unsigned char>(data[at + 1]) == 0x8b;
}
bool withinBounds(size_t output, size_t input)
{
  const double out = static_cast<double>(output);
  return out <= kGzipMaxBytes && (out <= kGzipRatioFreeBytes || out <= kGzipMaxRatio * static_cast<double>(input));
}
} // namespace

bool isGzipPath(const std::string& path)
{
  if (path.size() < 3)
  {
    return false;
  }
  std::string tail = path.substr(path.size() - 3);
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return std::tolower(c); });
  return tail == ".gz";
}

std::string stripGzipSuffix(const std::string& path)
{
  return isGzipPath(path) ? path.substr(0, path.size() - 3) : path;
}

Status gunzip(const std::string& compressed, const std::string& path, std::string& text)
{
  text.clear();
  if (!hasGzipMagic(compressed, 0))
  {
    return gzipError(path,
                     compressed.empty()
                       ? "empty file, expected gzip data"
                       : "not gzip data (the file name ends in .gz but the magic bytes 1f 8b are missing)");
  }
  size_t offset = 0;
  int members = 0;
  // zlib counts in uInt: feed the input in chunks so that files over 4 GB work too.
  const size_t chunk = std::numeric_limits<uInt>::max() / 2;
  try
  {
    while (offset < compressed.size())
    {
      if (members > 0 && !hasGzipMagic(compressed, offset))
      {
        // gunzip tolerates zero padding after the last member (tape blocks); anything else is an error.
        if (std::all_of(compressed.begin() + static_cast<std::ptrdiff_t>(offset), compressed.end(),
                        [](char c) { return c == 0; }))
        {
          break;
        }
        return gzipError(path,
                         "unexpected data after the end of the gzip stream (byte " + std::to_string(offset) + ")");
      }
      z_stream zs{};
      if (inflateInit2(&zs, 16 + MAX_WBITS) != Z_OK) // 16: gzip header and CRC-32 trailer only
      {
        return gzipError(path, "zlib could not be initialised");
      }
      char buffer[1 << 16];
      int rc = Z_OK;
      while (rc != Z_STREAM_END)
      {
        if (zs.avail_in == 0 && offset < compressed.size())
        {
          const size_t n = std::min(chunk, compressed.size() - offset);
          zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + offset));
          zs.avail_in = static_cast<uInt>(n);
          offset += n;
        }
        zs.next_out = reinterpret_cast<Bytef*>(buffer);
        zs.avail_out = sizeof(buffer);
        rc = inflate(&zs, Z_NO_FLUSH);
        text.append(buffer, sizeof(buffer) - zs.avail_out);
        if (!withinBounds(text.size(), compressed.size()))
        {
          inflateEnd(&zs);
          return gzipError(
            path,
            "refused: it decompresses to more than " + std::to_string(text.size()) + " bytes from " +
              std::to_string(compressed.size()) + " (limits: " + std::to_string(static_cast<long long>(kGzipMaxRatio)) +
              " times the compressed size past " +
              std::to_string(static_cast<long long>(kGzipRatioFreeBytes / 1048576)) + " MiB, " +
              std::to_string(static_cast<long long>(kGzipMaxBytes / 1073741824)) + " GiB in all; a gzip bomb?)");
        }
        if (rc == Z_STREAM_END)
        {
          break;
        }
        if (rc == Z_BUF_ERROR || (rc == Z_OK && zs.avail_in == 0 && offset >= compressed.size() && zs.avail_out != 0))
        {
          // No progress possible: the input ended inside the stream.
          inflateEnd(&zs);
          return gzipError(path,
                           "truncated gzip data (the stream ends after " + std::to_string(text.size()) +
                             " decompressed bytes without its end marker)");
        }
        if (rc != Z_OK)
        {
          const std::string why = zs.msg ? zs.msg : "error " + std::to_string(rc);
          inflateEnd(&zs);
          return gzipError(
            path, "corrupt gzip data (" + why + ") after " + std::to_string(text.size()) + " decompressed bytes");
        }
      }
      // Bytes of this chunk that belong to the next member.
      offset -= zs.avail_in;
      inflateEnd(&zs);
      ++members;
    }
  }
  catch (const std::bad_alloc&)
  {
    return gzipError(path, "not enough memory to decompress the file");
  }
  return Status::success();
}

Status readGzipFile(const std::string& path, std::string& text)
{
  struct stat st
  {
  };
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
  {
    return gzipError(path, S_ISDIR(st.st_mode) ? "is a directory, not a file" : "is not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return gzipError(path, "cannot open file");
  }
  std::string compressed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
  {
    return gzipError(path, "read error");
  }
  return gunzip(compressed, path, text);
}

} // namespace volgrid
