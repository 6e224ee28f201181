// Filling a cavity with the Delaunay tetrahedralization of its boundary's vertices: the pieces shared by
// fillCavityDelaunay and the two-sided facet cavities of FacetRecovery.cxx (local Delaunay of a vertex
// set, the local tet behind each oriented face, and the flood fill from the boundary faces inward).
#pragma once

#include "TetMesh.h"
#include "VertexKeys.h"

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace volgrid
{

namespace cavity
{
// A triangle with its orientation: rotated so that the smallest id comes first.
struct OKey
{
  int32_t v[3];
  bool operator==(const OKey& o) const { return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2]; }
};
OKey orientedKey(const int32_t* f);
struct OKeyHash
{
  size_t operator()(const OKey& k) const;
};

// The Delaunay tetrahedralization `local` of the points `verts` (sorted and made unique here) of `mesh`,
// with local ids in global order so that Simulation of Simplicity breaks ties as it would in `mesh`.
// False for fewer than four vertices or when a point would be merged.
bool localDelaunay(const TetMesh& mesh, std::vector<int32_t>& verts, TetMesh& local);

// Every oriented face of `local` (global ids) to the local tet it bounds.
std::unordered_map<OKey, int32_t, OKeyHash> faceOwners(const TetMesh& local, const std::vector<int32_t>& verts);

enum class FaceStep
{
  Cross, // into the neighbouring local tet
  Stop,  // the fill's border
  Fail   // give up
};

// Flood fill of `local` from the tets `seeds` (in order; repeats ignored): every face of a reached tet (as
// global ids) is given to `step`; crossing out of the local mesh fails. On success the reached tets are
// appended to `tets` (global ids) in the order reached.
bool floodFill(const TetMesh& local, const std::vector<int32_t>& verts, const std::vector<int32_t>& seeds,
               const std::function<FaceStep(int32_t tet, int face, const int32_t* f)>& step,
               std::vector<std::array<int32_t, 4>>& tets);
} // namespace cavity

// Tetrahedralize a closed cavity given by its boundary faces, each oriented with the cavity on its
// positive side (orient3d(f0,f1,f2,x) > 0 for x inside), every cavity vertex being a vertex of some
// face: the Delaunay tetrahedralization of the face vertices must contain every face, and the tets
// reached from the faces' inner sides without crossing a face must close up. False when it does not
// work (no Steiner point is added). Used by Steiner removal when no single point sees the whole cavity.
// `missing` (optional) receives the faces absent from the Delaunay tetrahedralization (as given), so
// that the caller can grow the cavity across them and retry.
bool fillCavityDelaunay(const TetMesh& mesh, const std::vector<std::array<int32_t, 3>>& faces,
                        std::vector<std::array<int32_t, 4>>& tets,
                        std::vector<std::array<int32_t, 3>>* missing = nullptr);

} // namespace volgrid
