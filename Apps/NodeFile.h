// Reader for TetGen .node point files ("<n> <dim=3> <#attributes> <markers 0|1>", then "<id> x y z ...").
#pragma once

#include "Status.h"

#include <string>
#include <vector>

namespace volgrid
{
// Reads the points of a .node file into xyz (3 per point), in file order. Comments start with '#'.
Status readNodeFile(const std::string& path, std::vector<double>& xyz);
}
