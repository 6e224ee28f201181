// OBJ groups as boundary patches for the CLI: vtkOBJReader numbers the faces' groups (cell array GroupIds,
// one new id per `g` statement, in file order) but keeps no names. This re-reads the `g` statements and
// turns GroupIds into PatchId, one patch per distinct group name (in order of first appearance), with the
// names in the PatchNames field data.
#pragma once

#include <string>

class vtkPolyData;

namespace volgrid
{
// `path` is the OBJ file vtkOBJReader read into `obj`. Does nothing when `obj` has no GroupIds.
void objGroupsToPatches(const std::string& path, vtkPolyData* obj);
} // namespace volgrid
