// FlagParser (FlagParser.h): the one argument scan of the CLI sub-commands.
#include "FlagParser.h"

#include "CliSupport.h"

#include <cstdio>
#include <utility>

namespace volgrid
{
namespace cli
{

FlagParser::FlagParser(const char* command, std::string header, std::string footer)
  : command_(command)
  , header_(std::move(header))
  , footer_(std::move(footer))
{
}

Flag& FlagParser::push(const std::string& name, FlagKind kind, const std::string& help)
{
  flags_.emplace_back();
  Flag& flag = flags_.back();
  flag.name = name;
  flag.kind = kind;
  flag.help = help;
  return flag;
}

Flag& FlagParser::add(const std::string& name, bool& target, bool setTo, const std::string& help)
{
  Flag& flag = push(name, FlagKind::Bool, help);
  flag.boolean = &target;
  flag.setTo = setTo;
  return flag;
}

Flag& FlagParser::add(const std::string& name, long long& target, const std::string& help)
{
  Flag& flag = push(name, FlagKind::Integer, help);
  flag.integer = &target;
  return flag;
}

Flag& FlagParser::add(const std::string& name, double& target, const std::string& help)
{
  Flag& flag = push(name, FlagKind::Real, help);
  flag.real = &target;
  return flag;
}

Flag& FlagParser::add(const std::string& name, std::string& target, const std::string& help)
{
  Flag& flag = push(name, FlagKind::Text, help);
  flag.text = &target;
  return flag;
}

Flag& FlagParser::add(const OptionSpec& spec, const char* metavar, std::function<void(const OptionSpec&, double)> set)
{
  Flag& flag = push(std::string("--") + spec.name, FlagKind::Option, optionUsage(spec, metavar));
  flag.spec = &spec;
  flag.setOption = std::move(set);
  return flag;
}

bool FlagParser::fail(const std::string& problem, bool withUsage) const
{
  std::fprintf(stderr, "volgrid %s: %s\n%s", command_, problem.c_str(), withUsage ? usage().c_str() : "");
  return false;
}

Flag* FlagParser::find(const std::string& name)
{
  for (Flag& flag : flags_)
    if (flag.name == name)
      return &flag;
  return nullptr;
}

std::string FlagParser::usage() const
{
  std::string text = header_;
  for (const Flag& flag : flags_)
    text += flag.help;
  return text + footer_;
}

// The value of `flag` from its text: parsed by its kind, stored, then the command's own check.
bool FlagParser::take(const Flag& flag, const char* text)
{
  switch (flag.kind)
  {
    case FlagKind::Bool:
      *flag.boolean = flag.setTo;
      return true;
    case FlagKind::Integer:
      if (!parseLong(command_, flag.name.c_str(), text, *flag.integer))
        return false;
      break;
    case FlagKind::Real:
      if (!parseDouble(command_, flag.name.c_str(), text, *flag.real))
        return false;
      break;
    case FlagKind::Text:
      *flag.text = text;
      break;
    case FlagKind::Option:
    {
      double x = 0;
      if (!parseOption(command_, *flag.spec, text, x))
        return false;
      flag.setOption(*flag.spec, x);
      break;
    }
  }
  given_[flag.name] = text;
  return !flag.accept || flag.accept(text);
}

FlagParser::Result FlagParser::parse(int argc, char** argv, std::vector<std::string>& positional)
{
  for (int i = 1; i < argc; ++i)
  {
    if (before)
      if (const int taken = before(argc, argv, i))
      {
        if (taken < 0)
          return Result::Error;
        continue;
      }
    const std::string a = argv[i];
    if (a == "--help" || a == "-h")
    {
      std::fputs((usage() + moreHelp).c_str(), stdout);
      return Result::Help;
    }
    const Flag* flag = find(a);
    if (!flag && !a.empty() && a[0] == '-')
    {
      reportUnknownFlag(command_, a);
      return Result::Error;
    }
    if (!flag)
      positional.push_back(a);
    else if (flag->kind == FlagKind::Bool)
      take(*flag, "");
    else if (i + 1 >= argc)
    {
      reportMissingValue(command_, a);
      return Result::Error;
    }
    else if (!take(*flag, argv[++i]))
      return Result::Error;
  }
  return Result::Ok;
}
int FlagParser::scan(int argc, char** argv, std::vector<std::string>& positional)
{
  const Result result = parse(argc, argv, positional);
  return result == Result::Ok ? -1 : result == Result::Help ? 0 : 2;
}
int FlagParser::scan(int argc, char** argv, std::string& file, const char* none, const char* more)
{
  std::vector<std::string> positional;
  const int code = scan(argc, argv, positional);
  if (code < 0 && positional.size() != 1)
    return fail(positional.empty() ? none : more, true), 2;
  if (code < 0)
    file = positional[0];
  return code;
}
} // namespace cli
} // namespace volgrid
