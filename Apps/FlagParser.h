// One argument parser for the CLI sub-commands. A command declares its flags (name, kind, where the value
// goes, its lines of the usage text); parse() then does the lookup, the missing values, the numbers
// (cli::parseLong / parseDouble messages), the rows of Core's option table (cli::parseOption: the table's
// range and message), unknown flags (cli::reportUnknownFlag) and --help, so every command words these the
// same way.
#pragma once

#include "OptionTable.h"

#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace volgrid
{
namespace cli
{
enum class FlagKind
{
  Bool,    // no value: *boolean = setTo
  Integer, // a whole number (parseLong) into *integer
  Real,    // a finite number (parseDouble) into *real
  Text,    // any text (a name, a file path, a choice) into *text
  Option   // a row of OptionTable.h (parseOption), handed to setOption
};

struct Flag
{
  std::string name; // "--threads"
  FlagKind kind = FlagKind::Bool;
  bool* boolean = nullptr;
  bool setTo = true;
  long long* integer = nullptr;
  double* real = nullptr;
  std::string* text = nullptr;
  const OptionSpec* spec = nullptr;
  std::function<void(const OptionSpec&, double)> setOption;
  // After the value is stored: the command's own check of it (range, choice), given the text as typed;
  // prints its message (FlagParser::fail) and returns false to stop with exit code 2.
  std::function<bool(const char* text)> accept;
  std::string help; // its lines of the usage text, newlines included ("" when the synopsis names it)
};

class FlagParser
{
public:
  enum class Result
  {
    Ok,
    Help, // --help or -h: the help text is printed, the command exits 0
    Error // the message is printed, the command exits 2
  };

  // `command` names the sub-command in messages ("volgrid mesh: ..."); the usage text is `header`, the
  // flags' help lines in the order they were added, then `footer`.
  FlagParser(const char* command, std::string header, std::string footer = std::string());

  Flag& add(const std::string& name, bool& target, bool setTo, const std::string& help = std::string());
  Flag& add(const std::string& name, long long& target, const std::string& help = std::string());
  Flag& add(const std::string& name, double& target, const std::string& help = std::string());
  Flag& add(const std::string& name, std::string& target, const std::string& help = std::string());
  // --NAME for the table's row `spec` (usage lines from optionUsage with `metavar`).
  Flag& add(const OptionSpec& spec, const char* metavar, std::function<void(const OptionSpec&, double)> set);

  // Lines after the usage text on --help only (the errors print the usage text alone).
  std::string moreHelp;
  // Tried before the flags at argv[i]: 1 taken (i advanced past its value), 0 not its flag, -1 error.
  std::function<int(int argc, char** argv, int& i)> before;

  // Scans argv[1..argc) in order: the declared flags; any other argument starting with '-' is unknown;
  // the rest is appended to `positional`. A flag given twice keeps its last value.
  Result parse(int argc, char** argv, std::vector<std::string>& positional);
  // parse() as a command's exit code: -1 to go on, 0 after --help, 2 after the error message.
  int scan(int argc, char** argv, std::vector<std::string>& positional);
  // scan() for a command that takes exactly one file argument, into `file`; none or several are an error
  // (exit code 2) with the message `none` or `more` and the usage text.
  int scan(int argc, char** argv, std::string& file, const char* none, const char* more);

  // "volgrid COMMAND: PROBLEM\n", then the usage text when withUsage. Returns false (for accept).
  bool fail(const std::string& problem, bool withUsage = false) const;

  // The flag named `name` ("--axis"), or nullptr.
  Flag* find(const std::string& name);

  std::string usage() const;
  const char* command() const { return command_; }
  // The flags given with their text as typed ("--max-edge" -> "1e-9"), to name them in later messages.
  const std::map<std::string, std::string>& given() const { return given_; }

private:
  Flag& push(const std::string& name, FlagKind kind, const std::string& help);
  bool take(const Flag& flag, const char* text);

  const char* command_;
  std::string header_, footer_;
  std::deque<Flag> flags_; // a deque: add() hands out references that must stay valid
  std::map<std::string, std::string> given_;
};
} // namespace cli
} // namespace volgrid
