#include "OptionValues.h"

namespace volgrid
{

namespace
{
bool setShared(FieldPointOptions& field, OptimizationOptions& optimization, const OptionSpec& spec, double value)
{
  if (&spec == &option::alpha)
    field.alpha = value;
  else if (&spec == &option::beta)
    field.beta = value;
  else if (&spec == &option::targetAngle)
    optimization.targetDegrees = value;
  else if (&spec == &option::passes)
    optimization.maxPasses = static_cast<int>(value);
  else
    return false;
  return true;
}
} // namespace

bool setOption(ImprovementOptions& options, const OptionSpec& spec, double value)
{
  if (setShared(options.fieldPointOptions, options.optimization, spec, value))
    return true;
  if (&spec == &option::sizeScale)
    options.sizing.scale = value;
  else if (&spec == &option::gradation)
    options.sizing.gradation = value;
  else if (&spec == &option::maxEdge)
    options.sizing.maxEdgeLength = value;
  else if (&spec == &option::maxVolume)
    options.fieldPointOptions.maxVolume = value;
  else
    return false;
  return true;
}

bool refinementOption(const OptionSpec& spec)
{
  return &spec == &option::alpha || &spec == &option::beta || &spec == &option::targetAngle || &spec == &option::passes;
}

bool setOption(RefineOptions& options, const OptionSpec& spec, double value)
{
  return setShared(options.fieldPointOptions, options.optimization, spec, value);
}

} // namespace volgrid
