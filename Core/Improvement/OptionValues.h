// Where each option of the table (OptionTable.h) lives in the options structs: one setter for the CLI
// and the filter instead of one per option and per caller.
#pragma once

#include "MeshImprovement.h"
#include "OptionTable.h"

namespace volgrid
{

// Sets the member of `options` that `spec` names. The value is taken as given (check spec.valid first).
// False when the option has no member there.
bool setOption(ImprovementOptions& options, const OptionSpec& spec, double value);
// Refinement has alpha, beta, the target angle and the pass limit (its gradation means something else:
// RefineOptions::gradation): refinementOption says which.
bool refinementOption(const OptionSpec& spec);
bool setOption(RefineOptions& options, const OptionSpec& spec, double value);

} // namespace volgrid
