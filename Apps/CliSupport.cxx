#include "CliSupport.h"

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace volgrid
{
namespace cli
{

bool parseLong(const char* command, const char* option, const char* text, long long& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || errno != 0)
  {
    std::fprintf(stderr, "volgrid %s: %s expects an integer, got '%s'\n", command, option, text);
    return false;
  }
  return true;
}

void reportUnknownFlag(const char* command, const std::string& flag)
{
  std::fprintf(stderr, "volgrid %s: unknown option '%s' (see volgrid %s --help)\n", command, flag.c_str(), command);
}

void reportMissingValue(const char* command, const std::string& flag)
{
  std::fprintf(stderr, "volgrid %s: %s needs a value (see volgrid %s --help)\n", command, flag.c_str(), command);
}

bool parseDouble(const char* command, const char* option, const char* text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(value))
  {
    std::fprintf(stderr, "volgrid %s: %s expects a finite number, got '%s'\n", command, option, text);
    return false;
  }
  return true;
}

bool parseOption(const char* command, const OptionSpec& spec, const char* text, double& value)
{
  const std::string flag = std::string("--") + spec.name;
  if (!parseDouble(command, flag.c_str(), text, value))
    return false;
  if (!spec.valid(value))
  {
    std::fprintf(stderr, "volgrid %s: %s is out of range: %s (%s %s; see --help)\n", command, flag.c_str(), text,
                 spec.type == OptionType::Integer ? "an integer in" : "in", spec.rangeText().c_str());
    return false;
  }
  return true;
}

std::string optionUsage(const OptionSpec& spec, const char* metavar)
{
  constexpr size_t kIndent = 23, kWidth = 106;
  std::string out = std::string("  --") + spec.name + " " + metavar;
  out.resize(std::max(out.size() + 1, kIndent), ' ');
  std::stringstream text;
  std::string range = spec.rangeText(); // kept on one line: its space becomes \x01 until the end
  range[range.find(' ')] = '\x01';
  text << spec.doc << " (default " << spec.defaultValue << ", in " << range << ")";
  size_t column = out.size();
  bool lineStart = true;
  std::string word;
  while (text >> word)
  {
    if (!lineStart && column + 1 + word.size() > kWidth)
    {
      out += "\n" + std::string(kIndent, ' ');
      column = kIndent;
      lineStart = true;
    }
    if (!lineStart)
    {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    lineStart = false;
  }
  std::replace(out.begin(), out.end(), '\x01', ' ');
  return out + "\n";
}

double peakResidentMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0; // Linux reports KiB
}

std::string jsonNumber(double v, const char* format)
{
  if (!std::isfinite(v))
    return "null";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::string jsonString(const std::string& s)
{
  std::string out = "\"";
  for (const char c : s)
  {
    switch (c)
    {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
        {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
          out += buffer;
        }
        else
        {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string lowerExtension(const std::string& path)
{
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}
} // namespace cli
} // namespace volgrid
