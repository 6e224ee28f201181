#include "OptionTable.h"

#include <cmath>
#include <sstream>

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

} // namespace volgrid
