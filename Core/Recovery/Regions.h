// Exterior removal and region labelling (paper 7.4).
//
// After boundary recovery every boundary (sub)face is a face of the mesh. The tets are grouped into
// components by a flood fill across faces that are NOT boundary faces. The component touching the hull
// (the far box) is the unbounded exterior. Crossing a boundary face changes the nesting depth by one;
// depths are found by a breadth-first search over the component graph starting at the exterior (0).
// Which components form the domain:
//   EvenOdd (default)  odd depth: inside the outermost shells, outside the bodies they contain, inside
//                      bodies inside those, ... Independent of the input orientation.
//   Orientation        the paper's rule: facet normals point away from the domain. A component is kept
//                      when every boundary face around it has its normal pointing away from it; a
//                      component whose faces disagree is an error (InvalidOption, inconsistent input).
//   KeepAll            every bounded component, each with its own label.
// Kept components get labels 0..numRegions-1 in order of first tet; the other tets are deleted and
// their neighbours' faces become kNoNeighbor.
#pragma once

#include "BoundaryRecovery.h"
#include "Progress.h"
#include "Status.h"
#include "TetMesh.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

enum class RegionRule
{
  EvenOdd,
  Orientation,
  KeepAll
};

const char* regionRuleName(RegionRule rule);

struct RegionResult
{
  int32_t numComponents = 0;            // all components, the exterior included
  std::vector<int32_t> componentDepth;  // nesting depth (0 = exterior)
  std::vector<int32_t> componentRegion; // region label of each component, -1 = removed
  int32_t numRegions = 0;
  std::vector<int32_t> tetRegion; // per tet slot: region label of a kept tet, -1 otherwise
  int64_t removedTets = 0;
};

// Classify and delete the tets outside the domain. Boundary faces are the live subfaces of `bc`.
Status removeExterior(MeshEditor& editor, const BoundaryConstraints& bc, RegionRule rule, RegionResult& result,
                      Progress* progress = nullptr);

} // namespace volgrid
