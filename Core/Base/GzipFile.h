// Reading gzip-compressed files (zlib): the surface readers load `name.ext.gz` through this and then
// parse the inner `.ext` format, so every reader gets compressed input without knowing about it.
#pragma once

#include "Status.h"

#include <string>

namespace volgrid
{

// True when the file name ends in ".gz" (case-insensitive).
bool isGzipPath(const std::string& path);

// The name without its trailing ".gz" ("wing.stl.gz" -> "wing.stl"); unchanged when there is none.
std::string stripGzipSuffix(const std::string& path);

// Bounds on decompression, so that a gzip bomb is refused early instead of being inflated whole: past
// kGzipRatioFreeBytes of output, the output may be at most kGzipMaxRatio times the compressed size (real
// surface files compress 3 to 30 times; zeros 1000 times), and never more than kGzipMaxBytes.
constexpr double kGzipRatioFreeBytes = 64.0 * 1024 * 1024;
constexpr double kGzipMaxRatio = 200.0;
constexpr double kGzipMaxBytes = 16.0 * 1024 * 1024 * 1024;

// Decompresses the whole gzip file at `path` into `text` (concatenated gzip members are joined, as
// gunzip does). A file that is not gzip, corrupt data, a bad checksum or a truncated stream give an
// ErrorKind::InvalidOption status naming the file and the problem; `text` is then unspecified.
Status readGzipFile(const std::string& path, std::string& text);

// The same on gzip data already in memory (`path` only names it in messages).
Status gunzip(const std::string& compressed, const std::string& path, std::string& text);

} // namespace volgrid
