// The size limit a run is checked against before any work (SizeEstimate.h): --max-tets N, or by default
// as many tets as the memory this process can still get (Core/Base/AvailableMemory.h).
#pragma once

#include "SizeEstimate.h"

#include <string>

namespace volgrid
{
namespace cli
{
// Parses --max-tets (a positive integer); prints the message and returns false when malformed.
bool parseMaxTets(const char* command, const char* text, long long& maxTets);

// When the estimate exceeds the limit (maxTets > 0: that many tets; else the available memory), prints
// "volgrid COMMAND: CAUSE would make about N tets ... refused before any work" and returns true.
// `cause` names the option and value that drive the size ("--max-edge 1e-09").
bool refuseIfTooLarge(const char* command, const SizeEstimate& estimate, long long maxTets, const std::string& cause);

// "1.5 GiB", "12 MiB" ... ("1.2e+12 TiB" past that).
std::string humanBytes(double bytes);
} // namespace cli
} // namespace volgrid
