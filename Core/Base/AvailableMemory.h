// How much memory this process can still get, for size checks before work (SizeEstimate.h): the smallest of
// the system's MemAvailable, the cgroup's memory.max minus memory.current (containers, CI runners), and the
// address-space and data limits (ulimit -v / -d). Linux; elsewhere only the limits apply.
#pragma once

namespace volgrid
{
// Bytes; infinity when nothing limits it.
double availableMemoryBytes();
} // namespace volgrid
