// A tetrahedral mesh as a solver receives it: points, tets with a region label, and the boundary
// triangles with a patch label, each label with a name. The currency of the solver writers
// (MeshWriter.h) and their readers. Labels are positive and dense after normalizeLabels() (gmsh
// physical tags, Medit refs and TetGen markers must be > 0).
#pragma once

#include "PatchNames.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace volgrid
{

struct SolverMesh
{
  std::vector<double> points;         // 3 per point
  std::vector<int32_t> tets;          // 4 per tet, positive volume ((b-a)x(c-a).(d-a) > 0)
  std::vector<int32_t> tetRegion;     // one per tet
  std::vector<int32_t> triangles;     // boundary triangles, 3 each
  std::vector<int32_t> trianglePatch; // one per boundary triangle
  // Boundary-layer prisms (Layers/BoundaryLayers.h): 6 per prism, base a,b,c whose normal points to the top
  // a',b',c' (gmsh's order), with a region label each; boundary quads (prism sides on a symmetry plane),
  // 4 per quad, with a patch label each. Only the writers of writesPrisms (MeshWriter.h) take them.
  std::vector<int32_t> prisms;
  std::vector<int32_t> prismRegion;
  std::vector<int32_t> quads;
  std::vector<int32_t> quadPatch;
  // Pyramids where a layer column collapsed: 5 each, quad then apex, the quad turning towards the apex
  // (gmsh's and VTK's order), with a region label each. Only the gmsh writers take them too.
  std::vector<int32_t> pyramids;
  std::vector<int32_t> pyramidRegion;
  NameTable patchNames;  // patch label -> name
  NameTable regionNames; // region label -> name
  // Point fields by name, one value per point (a solver's target size, ...): kept by the formats that
  // hold them (Exodus II nodal variables), ignored by the others.
  std::map<std::string, std::vector<double>> pointData;

  int64_t numberOfPoints() const { return static_cast<int64_t>(points.size() / 3); }
  int64_t numberOfTets() const { return static_cast<int64_t>(tets.size() / 4); }
  int64_t numberOfTriangles() const { return static_cast<int64_t>(triangles.size() / 3); }
};

// Whether the mesh has cells of boundary layers (prisms or pyramids).
bool hasLayerCells(const SolverMesh& mesh);

// What a reader does last: quads are boundary faces of prisms and pyramids only, so a mesh without those
// drops them (a tet mesh's file may list surface quads, as before); a mesh needs some volume cell.
// False when it has none.
bool finishReadCells(SolverMesh& mesh);

// The distinct labels in ascending order.
std::vector<int32_t> distinctLabels(const std::vector<int32_t>& labels);

// Renumbers patch and region labels densely to 1..k in ascending order of the old label; each label
// keeps its name, or gets "patch<old>" / "region<old>" when it had none. Idempotent.
void normalizeLabels(SolverMesh& mesh);

// Number of triangles carrying each label, in distinctLabels order.
std::vector<int64_t> labelCounts(const std::vector<int32_t>& labels, const std::vector<int32_t>& distinct);

} // namespace volgrid
