// Small helpers shared by the CLI sub-commands: argument scanning, timing, memory, JSON strings.
#pragma once

#include "OptionTable.h"
#include "Progress.h"

#include <algorithm>
#include <chrono>
#include <string>

namespace volgrid
{
namespace cli
{
// Parses a number argument; prints "volgrid CMD: OPTION expects ..." and returns false when malformed.
bool parseLong(const char* command, const char* option, const char* text, long long& value);
bool parseDouble(const char* command, const char* option, const char* text, double& value);
// The one wording of the two scan errors of every sub-command (FlagParser, and the scans of the export and
// layer flags that run before it): "volgrid CMD: unknown option '--x' (see volgrid CMD --help)" and
// "volgrid CMD: --x needs a value (see volgrid CMD --help)".
void reportUnknownFlag(const char* command, const std::string& flag);
void reportMissingValue(const char* command, const std::string& flag);
// The value of an option of Core's table (OptionTable.h): a finite number (an integer for an integer
// option) in the option's valid range; otherwise a message naming the range, and false.
bool parseOption(const char* command, const OptionSpec& spec, const char* text, double& value);
// The usage lines of an option of the table: flag, metavar, its doc, default and valid range, wrapped.
std::string optionUsage(const OptionSpec& spec, const char* metavar);

// The extension of a file name, lower case, without the dot ("" when there is none): "A/b.STL" -> "stl".
std::string lowerExtension(const std::string& path);

// Peak resident memory of this process so far, in MiB.
double peakResidentMiB();

// A JSON number printed with `format` ("%.17g", "%.4f" ...), or null when v is NaN or infinite (JSON has no
// spelling for those).
std::string jsonNumber(double v, const char* format = "%.17g");

// A JSON string literal for s (quotes and escapes included).
std::string jsonString(const std::string& s);

class Stopwatch
{
public:
  Stopwatch()
    : start_(std::chrono::steady_clock::now())
  {
  }
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
  std::chrono::steady_clock::time_point start_;
};

// A Progress that never stops the run and measures how long a user's stop would wait: the longest time
// between two questions (cancelled()), from construction to finish(). The filter's abort is honoured at
// the next question, so this is the worst delay of an abort in the run (--json: longest_abort_gap_seconds).
class AbortGapWatch final : public Progress
{
public:
  void report(double, const char*) override {}
  bool cancelled() override
  {
    lap();
    return false;
  }
  // The gap from the last question to the end of the run.
  void finish() { lap(); }
  double longestGapSeconds() const { return longest_; }

private:
  void lap()
  {
    const auto now = std::chrono::steady_clock::now();
    longest_ = std::max(longest_, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  double longest_ = 0;
};
} // namespace cli
} // namespace volgrid
