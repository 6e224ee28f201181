// flipInPlane: the 3D counterpart of a 2D edge flip inside a flat part of the boundary.
//
// Edge xy lies in a plane together with two vertices p and q of its ring (a flat CAD face: x, y, p, q
// exactly coplanar, the quad x-p-y-q convex). Replacing xy by pq is what recovering an input edge of that
// face needs (Sloan's 2D flips), but the edge removal of xy (every new tet has apex x or y) is often
// invalid when the ring has several vertices on a side. Here each side of the plane is re-filled on its
// own: the tets around xy on that side form a polyhedron whose floor is the quad; its floor is
// re-triangulated with pq and the polyhedron is filled by the cone from one of its ring vertices that
// sees every other face, or else by the Delaunay tetrahedralization of its vertices (fillCavityDelaunay).
// Validity is decided by exact orientation tests; on failure the mesh is untouched.
#include "PlanarFlip.h"

#include "FacetRecovery.h"
#include "Predicates.h"
#include "Quality.h"

#include <algorithm>
#include <array>
#include <vector>

namespace volgrid
{

using predicates::orient3d;

namespace
{

using Face = std::array<int32_t, 3>;

// Orients f so that `inside` is on its positive side; false when `inside` is on its plane.
bool orientTowards(const TetMesh& m, Face& f, int32_t inside)
{
  const int o = orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), m.point(inside));
  if (o == 0)
    return false;
  if (o < 0)
    std::swap(f[1], f[2]);
  return true;
}

// Fills the closed polyhedron `faces` (oriented inwards): the cone from one of `apexes` that sees every
// face not through it, else the Delaunay fill.
bool fillSide(const TetMesh& m, const std::vector<Face>& faces, const std::vector<int32_t>& apexes,
              std::vector<std::array<int32_t, 4>>& out)
{
  for (int32_t c : apexes)
  {
    std::vector<std::array<int32_t, 4>> cone;
    bool ok = true;
    for (const Face& f : faces)
    {
      if (f[0] == c || f[1] == c || f[2] == c)
        continue;
      if (orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), m.point(c)) <= 0)
      {
        ok = false;
        break;
      }
      cone.push_back({ { f[0], f[1], f[2], c } });
    }
    if (ok && !cone.empty())
    {
      out.insert(out.end(), cone.begin(), cone.end());
      return true;
    }
  }
  std::vector<std::array<int32_t, 4>> dt;
  if (!fillCavityDelaunay(m, faces, dt))
    return false;
  out.insert(out.end(), dt.begin(), dt.end());
  return true;
}

// A point strictly inside the polyhedron `faces` that sees every face (a Schoenhardt-like side needs
// one, as in TetGen's add_steinerpt_in_schoenhardtpoly). Such a point always exists: the midpoint m of
// xy sees every ring face strictly (each passes through x or y and has the other on its positive side)
// and lies on the floor, so m moved a little towards a ring vertex of this side sees the floor too.
// Candidates: between the centroids of the ring vertices and of the floor, then m moved towards each ring
// vertex by shrinking amounts; each is checked exactly and the best-shaped cone among the valid wins.
bool interiorPoint(const TetMesh& m, const std::vector<Face>& faces, const std::vector<int32_t>& chain,
                   const int32_t floor[4], double* out)
{
  double top[3] = { 0, 0, 0 }, bottom[3] = { 0, 0, 0 }, mid[3];
  for (int32_t c : chain)
    for (int k = 0; k < 3; ++k)
      top[k] += m.point(c)[k] / static_cast<double>(chain.size());
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k)
      bottom[k] += m.point(floor[i])[k] / 4.0;
  for (int k = 0; k < 3; ++k)
    mid[k] = 0.5 * (m.point(floor[0])[k] + m.point(floor[1])[k]);
  std::vector<std::array<double, 3>> cands;
  for (double t : { 0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9, 0.05 })
    cands.push_back({ { bottom[0] + t * (top[0] - bottom[0]), bottom[1] + t * (top[1] - bottom[1]),
                        bottom[2] + t * (top[2] - bottom[2]) } });
  for (int32_t r : chain)
    for (double t : { 0.5, 0.25, 0.1, 0.03, 0.01, 1e-3, 1e-4, 1e-6 })
      cands.push_back({ { mid[0] + t * (m.point(r)[0] - mid[0]), mid[1] + t * (m.point(r)[1] - mid[1]),
                          mid[2] + t * (m.point(r)[2] - mid[2]) } });
  double bestQ = 0;
  bool found = false;
  for (const auto& cand : cands)
  {
    const double* c = cand.data();
    double q = 1e300;
    for (const Face& f : faces)
    {
      const double *A = m.point(f[0]), *B = m.point(f[1]), *C = m.point(f[2]);
      if (orient3d(A, B, C, c) <= 0)
      {
        q = -1;
        break;
      }
      q = std::min(q, quality::tetShapeMeasure(A, B, C, c));
    }
    if (q > bestQ)
    {
      bestQ = q;
      std::copy(c, c + 3, out);
      found = true;
    }
  }
  return found;
}

} // namespace

bool flipInPlane(MeshEditor& ed, int32_t t, int32_t x, int32_t y, int32_t p, int32_t q, const BoundaryConstraints* bc,
                 std::vector<int32_t>* created, std::vector<VertexKind>* kinds)
{
  if (bc && (bc->isEdge(x, y) || bc->forbiddenEdge(p, q)))
    return false;
  std::vector<int32_t> ring, tets;
  if (!ed.edgeRing(t, x, y, ring, tets))
    return false;
  const int n = static_cast<int>(ring.size());
  const int ip = static_cast<int>(std::find(ring.begin(), ring.end(), p) - ring.begin());
  const int iq = static_cast<int>(std::find(ring.begin(), ring.end(), q) - ring.begin());
  if (ip >= n || iq >= n)
    return false;
  if (orient3d(ed.mesh.point(x), ed.mesh.point(y), ed.mesh.point(p), ed.mesh.point(q)) != 0)
    return false;
  // The quad x-p-y-q must be strictly convex (pq crosses xy): tested against an off-plane ring vertex u.
  {
    int32_t u = -1;
    for (int32_t r : ring)
      if (r != p && r != q && orient3d(ed.mesh.point(x), ed.mesh.point(y), ed.mesh.point(p), ed.mesh.point(r)) != 0)
      {
        u = r;
        break;
      }
    if (u < 0)
      return false;
    const double *X = ed.mesh.point(x), *Y = ed.mesh.point(y), *P = ed.mesh.point(p), *Q = ed.mesh.point(q),
                 *U = ed.mesh.point(u);
    if (orient3d(P, Q, U, X) * orient3d(P, Q, U, Y) >= 0 || orient3d(X, Y, U, P) * orient3d(X, Y, U, Q) >= 0)
      return false;
  }
  std::vector<std::array<int32_t, 4>> fresh;
  // The two sides: ring positions ip..iq and iq..ip (cyclic); tet k spans ring[k], ring[k+1].
  for (int side = 0; side < 2; ++side)
  {
    const int from = side == 0 ? ip : iq, to = side == 0 ? iq : ip;
    std::vector<int32_t> chain; // ring vertices strictly between p and q on this side
    std::vector<Face> faces;
    int sign = 0;
    for (int k = from; k != to; k = (k + 1) % n)
    {
      const int32_t r0 = ring[k], r1 = ring[(k + 1) % n];
      if (r1 != (side == 0 ? q : p))
      {
        // (no cached coordinate pointers: the first side may have added a point)
        const int o = orient3d(ed.mesh.point(x), ed.mesh.point(y), ed.mesh.point(p), ed.mesh.point(r1));
        if (o == 0 || (sign != 0 && o != sign))
          return false; // a ring vertex in the plane, or the side crosses it
        sign = o;
        chain.push_back(r1);
      }
      // Tet {x, y, r0, r1}: its faces not through both x and y bound this side.
      for (int32_t apex : { x, y })
      {
        Face f = { { apex, r0, r1 } };
        if (!orientTowards(ed.mesh, f, apex == x ? y : x))
          return false;
        faces.push_back(f);
      }
    }
    if (chain.empty())
      return false; // a face of the quad's plane only: the plane is not crossed here
    for (int32_t apex : { x, y })
    {
      Face f = { { p, q, apex } };
      if (!orientTowards(ed.mesh, f, chain.front()))
        return false;
      faces.push_back(f);
    }
    if (fillSide(ed.mesh, faces, chain, fresh))
      continue;
    const int32_t floor[4] = { x, y, p, q };
    double c[3];
    if (!kinds || !interiorPoint(ed.mesh, faces, chain, floor, c))
      return false;
    const int32_t v = ed.mesh.addPoint(c);
    kinds->resize(static_cast<size_t>(ed.mesh.numVertices()), VertexKind::Unused);
    (*kinds)[static_cast<size_t>(v)] = VertexKind::SteinerInterior;
    for (const Face& f : faces)
      fresh.push_back({ { f[0], f[1], f[2], v } });
  }
  if (bc)
  {
    static const int kE[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (const auto& tet : fresh)
      for (const auto& e : kE)
        if (bc->forbiddenEdge(tet[e[0]], tet[e[1]]))
          return false;
  }
  ed.lastRemoved.clear();
  for (int32_t u : tets)
    ed.lastRemoved.push_back(
      { { ed.mesh.vertex(u, 0), ed.mesh.vertex(u, 1), ed.mesh.vertex(u, 2), ed.mesh.vertex(u, 3) } });
  if (!ed.replace(tets, fresh, created))
    return false;
  ed.lastRemovedIds = tets;
  ++ed.flipsEdgeRemoval;
  return true;
}

} // namespace volgrid
