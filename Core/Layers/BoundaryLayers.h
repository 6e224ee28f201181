// Boundary layers: prisms grown from wall patches along smoothed vertex normals, for viscous CFD.
//
// Every layered vertex carries the same number of layers; layer k of a column is first * ratio^k thick,
// scaled by the column's factor (1 = full height). A column is thinned (its factor halved, and the
// neighbours limited to a smooth variation) when one of its prisms would invert (exact orient3d on every
// tet decomposition, prismIsValid) or when the last layer's surface would cross itself, the walls or
// another patch (the exact self-intersection check of SurfaceChecks). Nothing inverted is ever emitted.
// The last layer's surface plus the untouched patches is `tetBoundary`: the closed boundary of the tet
// region, handed to the conforming mesher (Mesher/LayeredMesher.h), which keeps it exactly.
//
// Where a wall meets a flat non-layered patch (a symmetry plane normal to a coordinate axis), its points
// march in that plane and the plane's triangles are moved with them to the last layer (kept only when
// none flips: exact orient2d; else the column is thinned). A column that would need thinning below
// 1/8 of its height (a knife edge, a needle tip: no direction sees all its faces well) collapses instead:
// its layers shrink onto the wall point, so the cells over its triangles become pyramids (one collapsed
// corner) or tets (two), conformal with the prisms around, and its neighbours keep their height.
// Unless keepWallTriangles, the wall's triangles beside an edge whose prism side faces checkMesh would find
// highly skewed are split first (WallRefinement.h); the wall keeps its shape.
// Limits: any other non-layered patch a wall touches gets a Status naming it and the point; one marching
// direction per vertex (no fans at sharp convex edges); points on a symmetry plane never collapse.
#pragma once

#include "OptionTable.h"
#include "Progress.h"
#include "Status.h"
#include "SurfaceMesh.h"
#include "WallFaceQuality.h"
#include "WallRefinement.h"

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

struct LayerOptions
{
  // Defaults and valid ranges: OptionTable.h's layers, firstHeight, growth, layerThickness rows.
  int layers = static_cast<int>(option::layers.defaultValue); // number of prism layers; 0 = no layers
  double firstHeight = option::firstHeight.defaultValue;      // height of the layer on the wall
  double growth = option::growth.defaultValue;                // ratio between consecutive layer heights
  // Total thickness (0: not given). With firstHeight (or y+) it replaces growth, which is solved for;
  // without, it gives the first height for this growth.
  double thickness = option::layerThickness.defaultValue;
  std::vector<int32_t> patchIds;       // layered patches by id; with patchNames empty too: every wall patch
  std::vector<std::string> patchNames; // layered patches by name
  // Instead of firstHeight: the height of a target y+ at a Reynolds number on a reference length
  // (firstHeightForYPlus).
  double yPlus = 0, reynolds = 0, referenceLength = 0;
  int normalSmoothing = 5;  // Laplacian passes over the vertex normals
  bool splitPrisms = false; // output each prism as 3 tets (min-vertex-index rule)
  // Keep the wall's triangles as they are, even around edges whose prism side faces checkMesh would find
  // highly skewed (by default those are split first: WallRefinement.h).
  bool keepWallTriangles = false;
  bool enabled() const { return layers > 0; }
  double totalThickness() const; // first * (1 + r + ... + r^(layers-1))
  // firstHeight from yPlus when that is given; with a thickness, the growth (or the first height) that
  // makes the layers that thick. Growth 0 when no ratio in [1, 10] does (validateLayerOptions says so).
  LayerOptions resolved() const;
};

// Why a column is thinner than asked.
enum class ThinnedReason : uint8_t
{
  None = 0,
  Inversion = 1, // a prism of the column would have a non-positive tet decomposition
  Collision = 2, // the last layer's surface would cross itself, the walls or another patch
  Neighbour = 3, // limited so that its height varies smoothly from a thinned neighbour
  Collapsed = 4  // no height at all: the layers shrink onto the wall point (pyramids and tets around it)
};
const char* thinnedReasonName(ThinnedReason reason);

struct LayerStatistics
{
  int64_t layeredTriangles = 0;
  int64_t fullTriangles = 0; // layered triangles whose three columns have their full height
  int64_t layeredPoints = 0;
  int64_t thinnedColumns = 0;
  int64_t thinnedBy[5] = { 0, 0, 0, 0, 0 }; // columns per ThinnedReason (Collapsed included)
  int64_t prisms = 0;
  int64_t pyramids = 0;
  int64_t layerTets = 0;
  int iterations = 0;  // thinning rounds
  double minScale = 1; // smallest column factor
  double seconds = 0;
  WallFaceQuality wallFaceQuality; // what the wall triangulation alone implies for checkMesh (WallFaceQuality.h)
  WallRefinement wallRefinement;   // the wall triangles split first around skewed edges (WallRefinement.h)
  int64_t collapsedTriangles = 0; // layered triangles with a collapsed corner: fewer than all the layers
  // Share of layered triangles with their full height (strict; thinned columns count against it).
  double coverage() const { return layeredTriangles ? double(fullTriangles) / double(layeredTriangles) : 0.0; }
  // Share of layered triangles that have every layer, thinned or not (no collapsed corner).
  double allLayersShare() const
  {
    return layeredTriangles ? double(layeredTriangles - collapsedTriangles) / double(layeredTriangles) : 0.0;
  }
};

struct LayerResult
{
  // The input surface's points (after exact merging: point i of the merged surface) first, then the
  // points the wall refinement added (stats.wallRefinement.splitEdges of them), then per
  // layered point that did not collapse its `layers` offset points (layer 0 nearest the wall).
  std::vector<double> points;
  int32_t numSurfacePoints = 0;
  std::vector<int32_t> prisms;        // 6 per prism: base a,b,c then top a',b',c' (a' above a)
  std::vector<int32_t> prismLayer;    // 0 at the wall
  std::vector<int32_t> prismTriangle; // merged input triangle the prism stands on
  std::vector<uint8_t> prismReason;   // ThinnedReason of the column (the worst of its three points)
  // Over triangles with collapsed corners: pyramids (5 ids: the quad, then the apex: the collapsed wall
  // point; oriented as a positive tet: orient3d(q0, q1, q2, apex) > 0) and tets (4 ids, positive), with
  // the same per-cell arrays as the prisms.
  std::vector<int32_t> pyramids;
  std::vector<int32_t> pyramidLayer;
  std::vector<uint8_t> pyramidReason;
  std::vector<int32_t> tets;
  std::vector<int32_t> tetLayer;
  std::vector<uint8_t> tetReason;
  std::vector<double> pointScale;        // per surface point: column factor (1 = full; 0 = not layered)
  std::vector<uint8_t> pointReason;      // per surface point: ThinnedReason
  std::vector<int32_t> wallTriangles;    // layered triangles, 3 each, as in the input (orientation kept)
  std::vector<int32_t> wallPatch;        // their patch ids
  std::vector<int32_t> sideQuads;        // 4 per prism side face on a symmetry plane (boundary faces)
  std::vector<int32_t> sidePatch;        // their patch ids
  SurfaceMesh tetBoundary;               // last layer's surface (patch interfacePatch) + the other triangles
  std::vector<int32_t> tetBoundaryPoint; // tetBoundary point -> index into points
  int32_t interfacePatch = -1;
  LayerStatistics stats;
};

// First-layer height for a target y+ on a flat plate (turbulent skin friction of White / Schlichting):
// Cf = 0.026 / Re^(1/7), u_tau / U = sqrt(Cf / 2), so y = yPlus * length / (Re * sqrt(Cf / 2)), with
// Re = U * length / nu. A first estimate, as in the usual y+ calculators; 0 for non-positive input.
double firstHeightForYPlus(double yPlus, double reynolds, double length);

// Adds the comma-separated patches of `list` to `options`: an entry of digits is a patch id (Medit
// reference, gmsh tag), any other entry a patch name. The CLI's --layer-patches and the filter's LayerPatches.
void addLayerPatches(const std::string& list, LayerOptions& options);

// Checks the numbers (not the surface): layers >= 1, first height > 0 and finite (or y+, Reynolds number and
// reference length, not both), growth >= 1.
Status validateLayerOptions(const LayerOptions& options);

// Grows the layers on `surface` (closed shells, as the mesher takes them; region rule even-odd decides on
// which side of each shell the domain is). On failure the result is empty and the Status says why.
Status growLayers(const SurfaceMesh& surface, const LayerOptions& options, LayerResult& result,
                  Progress* progress = nullptr);

// True when every tet of every decomposition of the prism (base a,b,c; top d,e,f above them) has
// positive orientation, with the base (a,b,c) counter-clockwise seen from the top (exact).
bool prismIsValid(const double* a, const double* b, const double* c, const double* d, const double* e, const double* f);

// A prism whose top points may repeat base points (a collapsed column: v[i] == v[i + 3]) is valid when every
// tet of every decomposition of the prism with four distinct points is positive: the prism itself, a
// pyramid under both diagonals of its quad, or a tet. All three collapsed: no cell, valid.
bool layerCellIsValid(const int32_t v[6], const double* points);

// The two tets of pyramid v[5] (quad v0..v3, apex v4; orient3d(v0, v1, v2, v4) > 0), the quad cut through
// its smallest id as splitPrism cuts it, so that the pyramid and a prism sharing the quad agree.
void splitPyramid(const int32_t v[5], int32_t tets[8]);

// The three tets of prism v[6] (base v0..v2, top v3..v5) by the minimum-vertex-index rule: each quad face
// is cut through its smallest id, so two prisms sharing a quad cut it alike. Tets are positively oriented
// when the prism is valid (points: xyz per id).
void splitPrism(const int32_t v[6], const double* points, int32_t tets[12]);

} // namespace volgrid
