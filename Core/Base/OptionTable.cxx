#include "OptionTable.h"

#include <cmath>
#include <iomanip>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

namespace volgrid
{

namespace
{
std::string number(double x)
{
  if (std::isinf(x))
    return "inf";
  std::ostringstream os;
  os << x;
  return os.str();
}

// The shortest decimal that reads back as exactly x (0.4, not 0.40000000000000002).
std::string exactNumber(double x)
{
  if (x == std::floor(x) && std::fabs(x) < 1e15)
    return std::to_string(static_cast<long long>(x)); // 60, not 6e+01
  for (int digits = 1;; ++digits)
  {
    std::ostringstream os;
    os << std::setprecision(digits) << x;
    if (digits >= 17 || std::stod(os.str()) == x)
      return os.str();
  }
}

// Every placeholder's text, keyed by its name between the @s.
std::map<std::string, std::string> placeholderValues()
{
  std::map<std::string, std::string> values;
  std::vector<const OptionSpec*> rows(std::begin(option::table), std::end(option::table));
  rows.insert(rows.end(), std::begin(option::layerTable), std::end(option::layerTable));
  for (const OptionSpec* spec : rows)
  {
    const std::string stem = std::string("VOLGRID_OPTION_") + spec->property;
    values[stem + "_DEFAULT"] = exactNumber(spec->defaultValue);
    std::string range = "min=\"" + exactNumber(spec->sliderMin) + "\"";
    if (!std::isinf(spec->sliderMax))
      range += " max=\"" + exactNumber(spec->sliderMax) + "\"";
    values[stem + "_RANGE"] = range;
  }
  return values;
}
} // namespace

std::string OptionSpec::rangeText() const
{
  return (minimumIncluded ? "[" : "(") + number(minimum) + ", " + number(maximum) + (maximumIncluded ? "]" : ")");
}

const OptionSpec* findOption(const std::string& name)
{
  for (const OptionSpec* spec : option::table)
    if (name == spec->name)
      return spec;
  return nullptr;
}

const OptionSpec* findOptionByProperty(const std::string& property)
{
  for (const OptionSpec* spec : option::table)
    if (property == spec->property)
      return spec;
  return nullptr;
}

Status fillOptionPlaceholders(const std::string& text, std::string& filled)
{
  const std::string prefix = "@VOLGRID_OPTION_";
  std::map<std::string, std::string> values = placeholderValues();
  std::map<std::string, int> uses;
  filled.clear();
  size_t from = 0;
  for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, from))
  {
    const size_t end = text.find('@', at + 1);
    if (end == std::string::npos)
      return Status::failure(ErrorKind::InvalidOption,
                             "Unterminated option placeholder at byte " + std::to_string(at) + ".");
    const std::string name = text.substr(at + 1, end - at - 1);
    const auto value = values.find(name);
    if (value == values.end())
      return Status::failure(ErrorKind::InvalidOption,
                             "Placeholder @" + name + "@ names no option of Core/Base/OptionTable.h.");
    filled.append(text, from, at - from).append(value->second);
    ++uses[name];
    from = end + 1;
  }
  filled.append(text, from, std::string::npos);
  for (const auto& entry : values)
    if (!uses.count(entry.first))
      return Status::failure(ErrorKind::InvalidOption,
                             "The template has no @" + entry.first + "@: it would keep a value of its own.");
  return Status::success();
}

} // namespace volgrid
