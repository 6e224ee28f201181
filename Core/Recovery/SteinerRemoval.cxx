#include "SteinerRemoval.h"

#include "Quality.h"

#include "CavityCarving.h"
#include "CavityInteriorPoint.h"
#include "FacetRecovery.h"

#include "Predicates.h"
#include "StarFlips.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace volgrid
{

using predicates::orient3d;

namespace
{

// Ear clipping of a polygon (point ids, counter-clockwise in the parent's orientation) in the projection
// that drops `axis`; `o` is the sign of a counter-clockwise turn in that projection.
// `allowed(a, c)` says whether diagonal ac may be created (not along a split segment).
template<class Allowed>
bool triangulatePolygon3(const TetMesh& m, std::vector<int32_t> poly, int axis, int o,
                         std::vector<std::array<int32_t, 3>>& out, const Allowed& allowed)
{
  while (poly.size() > 3)
  {
    const size_t n = poly.size();
    int bestI = -1;
    double bestQ = -1;
    for (size_t i = 0; i < n; ++i)
    {
      const int32_t a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
      const double *A = m.point(a), *B = m.point(b), *C = m.point(c);
      if (predicates::orient2dProjected(A, B, C, axis) != o || (n > 3 && !allowed(a, c)))
        continue;
      bool empty = true;
      for (size_t k = 0; k < n && empty; ++k)
      {
        const int32_t w = poly[k];
        if (w == a || w == b || w == c)
          continue;
        const double* W = m.point(w);
        if (predicates::orient2dProjected(A, B, W, axis) * o >= 0 &&
            predicates::orient2dProjected(B, C, W, axis) * o >= 0 &&
            predicates::orient2dProjected(C, A, W, axis) * o >= 0)
          empty = false;
      }
      if (!empty)
        continue;
      // Quality: smallest angle (approximate; only chooses among valid ears).
      double q = 1e300;
      const double* P[3] = { A, B, C };
      for (int k = 0; k < 3; ++k)
      {
        const double *U = P[k], *V = P[(k + 1) % 3], *W = P[(k + 2) % 3];
        double d1[3], d2[3], dot = 0, l1 = 0, l2 = 0;
        for (int j = 0; j < 3; ++j)
        {
          d1[j] = V[j] - U[j];
          d2[j] = W[j] - U[j];
          dot += d1[j] * d2[j];
          l1 += d1[j] * d1[j];
          l2 += d2[j] * d2[j];
        }
        q = std::min(q, dot / std::sqrt(std::max(l1 * l2, 1e-300)));
      }
      q = -q; // larger = bigger smallest angle (smaller max cosine)
      if (bestI < 0 || q > bestQ)
      {
        bestI = static_cast<int>(i);
        bestQ = q;
      }
    }
    if (bestI < 0)
      return false;
    const size_t i = static_cast<size_t>(bestI);
    out.push_back({ { poly[(i + n - 1) % n], poly[i], poly[(i + 1) % n] } });
    poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
  }
  if (poly.size() == 3)
    out.push_back({ { poly[0], poly[1], poly[2] } });
  return poly.size() == 3;
}

class Remover
{
public:
  Remover(MeshEditor& ed, BoundaryConstraints& bc, std::vector<VertexKind>& kinds, std::vector<int32_t>* region)
    : ed_(ed)
    , m_(ed.mesh)
    , bc_(bc)
    , kinds_(kinds)
    , region_(region)
  {
  }

  int64_t addedInterior = 0;

  // Removes boundary Steiner point p: its subfaces are replaced by a triangulation of the polygon they
  // leave on each parent facet, and each side of the boundary gets a new interior point (or a fill
  // without one). False, with the mesh and the constraints unchanged, when that is not possible.
  bool remove(int32_t p)
  {
    Removal r;
    ed_.star(p, r.S);
    if (r.S.empty())
      return false;
    collectSubfaces(p, r);
    if (r.subs.empty() || !boundaryPolygons(p, r))
      return false;
    findSides(p, r);
    if (r.nsides > 2)
      return false;
    orientSides(p, r);
    // Several triangulations of the polygons are tried: the best-ear one, then fans from each polygon
    // vertex.
    const size_t nsides = static_cast<size_t>(r.nsides);
    r.sidePoint.resize(nsides);
    r.sideRegion.assign(nsides, -1);
    r.sideFilled.assign(nsides, 0);
    size_t maxPoly = 3;
    for (auto& pl : r.polys)
      maxPoly = std::max(maxPoly, pl.v.size());
    bool good = false;
    for (size_t variant = 0; variant <= maxPoly && !good; ++variant)
    {
      r.newTets.clear();
      r.newTetSide.clear();
      good = triangulatePolygons(variant, r);
      if (!good)
        continue;
      cav = r.S;
      cavSide = r.side;
      r.sideFilled.assign(nsides, 0);
      for (int sd = 0; sd < r.nsides && good; ++sd)
        good = fillSide(p, sd, r);
    }
    return good && commit(p, r);
  }

private:
  // A polygon left on parent facet `parent` by the removal of p: its subfaces around p form a fan whose
  // outer edges make a closed polygon (p inside the facet) or an open chain (p on a segment).
  struct Polygon
  {
    std::vector<int32_t> v; // counter-clockwise in the parent's orientation
    int axis, o;            // the projection drops `axis`; o is the sign of a counter-clockwise turn in it
    int32_t parent;
    bool closed;
  };
  // One removal in progress (remove()).
  struct Removal
  {
    std::vector<int32_t> S;                           // p's star
    std::vector<int32_t> subs;                        // p's subfaces, in the order met
    std::map<int32_t, std::vector<int32_t>> byParent; // the same, by parent facet
    std::vector<Polygon> polys;
    std::vector<int32_t> side; // per tet of S: its side (component of S across non-subface faces)
    int nsides = 0;
    std::vector<std::map<int32_t, int>> sideOfParent; // per side: parent -> +1 normal side, -1 other
    std::vector<std::array<int32_t, 3>> newTris;      // the polygons' triangulation
    std::vector<int32_t> newTriParent;
    std::vector<std::array<int32_t, 4>> newTets; // fourth vertex -2 - sd: side sd's new point
    std::vector<int> newTetSide;
    std::vector<std::array<double, 3>> sidePoint; // the new point of each side
    std::vector<int32_t> sideRegion;              // the region of each side's tets (-1 unknown)
    std::vector<char> sideFilled;                 // side filled without a new point
  };

  // r.subs and r.byParent: the subfaces of p's star (faces of r.S not containing p).
  void collectSubfaces(int32_t p, Removal& r)
  {
    int32_t f[3];
    for (int32_t t : r.S)
      for (int i = 0; i < 4; ++i)
      {
        if (m_.vertex(t, i) == p)
          continue;
        m_.faceVertices(t, i, f);
        const int32_t sf = bc_.findSubface(f[0], f[1], f[2]);
        if (sf >= 0 && std::find(r.subs.begin(), r.subs.end(), sf) == r.subs.end())
        {
          r.subs.push_back(sf);
          r.byParent[bc_.parent[sf]].push_back(sf);
        }
      }
  }

  // r.polys: per parent, the polygon its fan around p leaves, with the projection of the parent's
  // (area-weighted) normal. False when a fan is not one chain, or closes around fewer than 3 vertices.
  bool boundaryPolygons(int32_t p, Removal& r)
  {
    for (auto& [par, list] : r.byParent)
    {
      std::vector<std::pair<int32_t, int32_t>> fan; // (x, y) of (p, x, y)
      double nrm[3] = { 0, 0, 0 };
      for (int32_t sf : list)
      {
        const int32_t* s = bc_.subface(sf);
        int k0 = 0;
        while (s[k0] != p)
          ++k0;
        fan.push_back({ s[(k0 + 1) % 3], s[(k0 + 2) % 3] });
        const double *P = m_.point(p), *X = m_.point(s[(k0 + 1) % 3]), *Y = m_.point(s[(k0 + 2) % 3]);
        double u[3], v[3];
        for (int k = 0; k < 3; ++k)
        {
          u[k] = X[k] - P[k];
          v[k] = Y[k] - P[k];
        }
        nrm[0] += u[1] * v[2] - u[2] * v[1];
        nrm[1] += u[2] * v[0] - u[0] * v[2];
        nrm[2] += u[0] * v[1] - u[1] * v[0];
      }
      int32_t start = fan[0].first;
      for (auto& e : fan)
      {
        bool isY = false;
        for (auto& g : fan)
          isY = isY || g.second == e.first;
        if (!isY)
          start = e.first;
      }
      std::vector<int32_t> poly = { start };
      int32_t cur = start;
      for (size_t guard = 0; guard <= fan.size(); ++guard)
      {
        int32_t nxt = -1;
        for (auto& e : fan)
          if (e.first == cur)
            nxt = e.second;
        if (nxt < 0 || nxt == start)
          break;
        poly.push_back(nxt);
        cur = nxt;
      }
      const bool closed = poly.size() == fan.size();
      if (!closed && poly.size() != fan.size() + 1)
        return false;
      if (poly.size() < 3)
      {
        if (closed)
          return false;
        continue; // a single (sliver) subface with p on its third edge: it simply disappears
      }
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (std::fabs(nrm[k]) > std::fabs(nrm[axis]))
          axis = k;
      // Sign of a counter-clockwise turn when dropping `axis` (right-handed cyclic order).
      const int o = nrm[axis] > 0 ? 1 : -1;
      r.polys.push_back({ poly, axis, o, par, closed });
    }
    return true;
  }

  // r.side and r.nsides: the components of p's star across the faces containing p that are not subfaces.
  void findSides(int32_t p, Removal& r)
  {
    const std::vector<int32_t>& S = r.S;
    const uint32_t s0 = ed_.newStamp();
    for (int32_t t : S)
      ed_.tetStamp[t] = s0;
    r.side.assign(S.size(), -1);
    auto indexOf = [&](int32_t t) { return static_cast<size_t>(std::find(S.begin(), S.end(), t) - S.begin()); };
    int32_t f[3];
    for (size_t k = 0; k < S.size(); ++k)
    {
      if (r.side[k] >= 0)
        continue;
      std::vector<int32_t> q = { S[k] };
      r.side[k] = r.nsides;
      for (size_t h = 0; h < q.size(); ++h)
      {
        const int32_t t = q[h];
        for (int i = 0; i < 4; ++i)
        {
          if (m_.vertex(t, i) == p)
            continue;
          const int32_t u = m_.neighbor(t, i);
          if (u < 0 || ed_.tetStamp[u] != s0)
            continue;
          m_.faceVertices(t, i, f);
          if (bc_.findSubface(f[0], f[1], f[2]) >= 0)
            continue;
          const size_t iu = indexOf(u);
          if (r.side[iu] < 0)
          {
            r.side[iu] = r.nsides;
            q.push_back(u);
          }
        }
      }
      ++r.nsides;
    }
  }

  // r.sideOfParent: which side of each parent facet each side lies on.
  void orientSides(int32_t p, Removal& r)
  {
    r.sideOfParent.assign(static_cast<size_t>(r.nsides), {});
    int32_t f[3];
    for (size_t k = 0; k < r.S.size(); ++k)
    {
      const int32_t t = r.S[k];
      for (int i = 0; i < 4; ++i)
      {
        if (m_.vertex(t, i) == p)
          continue;
        m_.faceVertices(t, i, f);
        const int32_t sf = bc_.findSubface(f[0], f[1], f[2]);
        if (sf < 0)
          continue;
        const int32_t* s = bc_.subface(sf);
        bool same = false;
        for (int j = 0; j < 3; ++j)
          same = same || (f[0] == s[j] && f[1] == s[(j + 1) % 3] && f[2] == s[(j + 2) % 3]);
        // faceVertices is seen positively from t's vertex i, which is inside t: same order = t on the
        // normal side.
        r.sideOfParent[r.side[k]][bc_.parent[sf]] = same ? 1 : -1;
      }
    }
  }

  // r.newTris and r.newTriParent: triangulation `variant` of the polygons (0: best ears; v > 0: the fan
  // from each polygon's vertex (v - 1) mod its size). False when it needs a forbidden edge.
  bool triangulatePolygons(size_t variant, Removal& r)
  {
    r.newTris.clear();
    r.newTriParent.clear();
    bool good = true;
    for (auto& pl : r.polys)
    {
      // New edges may not run along a split segment, except the piece that replaces p's two pieces
      // (the ends of an open polygon).
      auto allowed = [&](int32_t a, int32_t c)
      {
        if (!pl.closed && edgeKey(a, c) == edgeKey(pl.v.front(), pl.v.back()))
          return true;
        return !bc_.forbiddenEdge(a, c);
      };
      std::vector<std::array<int32_t, 3>> tris;
      if (variant == 0 || pl.v.size() == 3)
      {
        if (!triangulatePolygon3(m_, pl.v, pl.axis, pl.o, tris, allowed))
          good = false;
      }
      else
      {
        const size_t n = pl.v.size(), k0 = (variant - 1) % n;
        for (size_t k = 1; k + 1 < n; ++k)
        {
          tris.push_back({ { pl.v[k0], pl.v[(k0 + k) % n], pl.v[(k0 + k + 1) % n] } });
          if (k + 2 < n && !allowed(pl.v[k0], pl.v[(k0 + k + 1) % n]))
            good = false;
        }
      }
      for (auto& tr : tris)
      {
        r.newTris.push_back(tr);
        r.newTriParent.push_back(pl.parent);
      }
    }
    return good;
  }

  // Side sd's tets into r.newTets: its cavity (p's star on this side, enlarged by layers of outer tets
  // when no point sees all of its faces: a reflex or flat neighbourhood of p) coned from a new interior
  // point, else from one of its own vertices or carved, else filled without a point. False when none works.
  bool fillSide(int32_t p, int sd, Removal& r)
  {
    const std::vector<int32_t>& S = r.S;
    std::vector<std::array<int32_t, 3>> faces;
    for (size_t k = 0; k < S.size(); ++k)
      if (r.side[k] == sd && region_ && r.sideRegion[sd] < 0 && static_cast<size_t>(S[k]) < region_->size())
        r.sideRegion[sd] = (*region_)[S[k]];
    bool found = false, facesValid = false, coned = false;
    std::vector<std::array<int32_t, 4>> cone;
    for (int layer = 0; layer <= kMaxLayers && !found && !coned; ++layer)
    {
      facesValid = false;
      if (layer > 0 && !enlarge(p, sd, r.newTris))
        break;
      if (!cavityFaces(p, sd, r.newTris, r.newTriParent, r.sideOfParent[sd], faces))
        break;
      facesValid = true;
      found = interiorPoint_.find(p, faces, r.sidePoint[sd].data());
      // p's star may be flat (p rounded just outside a planar part of the boundary, between two
      // triangulations of it): the cone from one of the cavity's own vertices then fills it, or else a
      // search for a tetrahedralization of a small cavity without a new point.
      coned = !found && ((coneFromVertex(faces, cone) && !foldsSegment(faces, cone)) || carve(faces, cone));
    }
    if (found)
    {
      for (auto& fc : faces)
      {
        r.newTets.push_back({ { fc[0], fc[1], fc[2], -2 - sd } });
        r.newTetSide.push_back(sd);
      }
      return true;
    }
    std::vector<std::array<int32_t, 4>> fill;
    if (!coned && !(facesValid && fillWithoutPoint(p, sd, r, faces, fill)))
      return false;
    r.sideFilled[static_cast<size_t>(sd)] = 1;
    for (auto& t : coned ? cone : fill)
    {
      r.newTets.push_back(t);
      r.newTetSide.push_back(sd);
    }
    return true;
  }

  // No point sees the whole cavity of side sd (its faces in `faces`): a Delaunay tetrahedralization of
  // it without a point into `fill`, the cavity grown across the faces it lacks (TetGen's approach).
  bool fillWithoutPoint(int32_t p, int sd, Removal& r, std::vector<std::array<int32_t, 3>>& faces,
                        std::vector<std::array<int32_t, 4>>& fill)
  {
    std::vector<std::array<int32_t, 3>> missing;
    for (int grow = 0; grow <= kMaxFillGrowth; ++grow)
    {
      if (fillCavityDelaunay(m_, faces, fill, &missing))
        return !foldsSegment(faces, fill);
      bool grew = false;
      for (auto& mf : missing)
        grew = growAcross(p, sd, mf) || grew;
      if (!grew || !cavityFaces(p, sd, r.newTris, r.newTriParent, r.sideOfParent[sd], faces))
        return false;
    }
    return false;
  }

  // Applies a removal whose sides are all filled: the new points (p's id cannot be reused: faces through
  // the old and the new position would have the same ids), the tets, their regions, the subfaces. False,
  // with nothing changed, when the mesh refuses the tets.
  bool commit(int32_t p, Removal& r)
  {
    const int32_t firstNew = m_.numVertices();
    std::vector<int32_t> sideVertex(static_cast<size_t>(r.nsides), -1);
    int coneSides = 0;
    for (int sd = 0; sd < r.nsides; ++sd)
    {
      if (r.sideFilled[static_cast<size_t>(sd)])
        continue;
      sideVertex[static_cast<size_t>(sd)] = m_.addPoint(r.sidePoint[sd].data());
      kinds_.push_back(VertexKind::SteinerInterior);
      ++coneSides;
    }
    for (auto& t : r.newTets)
      if (t[3] <= -2)
        t[3] = sideVertex[static_cast<size_t>(-2 - t[3])];
    std::vector<int32_t> created;
    if (!ed_.replace(cav, r.newTets, &created, true))
    {
      m_.points.resize(3 * static_cast<size_t>(firstNew));
      kinds_.resize(static_cast<size_t>(firstNew));
      return false;
    }
    addedInterior += std::max(0, coneSides - 1);
    kinds_[p] = VertexKind::Unused;
    if (region_)
    {
      if (region_->size() < static_cast<size_t>(m_.tetCapacity()))
        region_->resize(static_cast<size_t>(m_.tetCapacity()), -1);
      for (int32_t t : cav)
        if (m_.isFree(t))
          (*region_)[t] = -1;
      for (size_t k = 0; k < created.size(); ++k)
        (*region_)[created[k]] = r.sideRegion[r.newTetSide[k]];
    }
    for (int32_t sf : r.subs)
      bc_.removeSubface(sf);
    for (size_t k = 0; k < r.newTris.size(); ++k)
      bc_.addSubface(r.newTris[k][0], r.newTris[k][1], r.newTris[k][2], r.newTriParent[k]);
    return true;
  }

  static constexpr int kMaxLayers = 3;
  static constexpr int kMaxFillGrowth = 16;
  static constexpr size_t kMaxCarveFaces = 32;
  static constexpr int64_t kMaxCarveSteps = 200;
  // Cavity size limit: the growth checks are quadratic in it, and larger cavities do not succeed.
  static constexpr size_t kMaxCavity = 400;

  // Add to side sd's cavity the tet beyond its face f (oriented with the cavity on its positive side):
  // never across a constraint, never a tet of the cavity, never swallowing a vertex.
  bool growAcross(int32_t p, int sd, const std::array<int32_t, 3>& f)
  {
    if (bc_.findSubface(f[0], f[1], f[2]) >= 0)
      return false;
    int face = -1;
    int32_t x = ed_.findFace(f[0], f[1], f[2], &face);
    if (x < 0)
      return false;
    if (cav.size() >= kMaxCavity)
      return false;
    auto inCav = [&](int32_t t) { return std::find(cav.begin(), cav.end(), t) != cav.end(); };
    if (inCav(x))
      x = m_.neighbor(x, face);
    if (x < 0 || inCav(x))
      return false;
    cav.push_back(x);
    cavSide.push_back(sd);
    if (!vertexOnBoundary(p, sd))
    {
      cav.pop_back();
      cavSide.pop_back();
      return false;
    }
    return true;
  }
  std::vector<int32_t> cav; // cavity tets: p's star, then enlargement layers
  std::vector<int32_t> cavSide;

  // Faces of side sd's cavity, each seen positively from inside: the faces of its tets that are not
  // shared with another tet of the side and do not contain p (those containing p are p's subfaces), and
  // the new boundary triangles, oriented towards the side. A face present twice with opposite
  // orientations (an empty part of the cavity) cancels. False when a new triangle has no orientation for
  // this side or a vertex of the cavity would end up strictly inside it.
  bool cavityFaces(int32_t p, int sd, const std::vector<std::array<int32_t, 3>>& newTris,
                   const std::vector<int32_t>& newTriParent, const std::map<int32_t, int>& sideOf,
                   std::vector<std::array<int32_t, 3>>& faces)
  {
    faces.clear();
    const uint32_t s = ed_.newStamp();
    for (size_t k = 0; k < cav.size(); ++k)
      if (cavSide[k] == sd)
        ed_.tetStamp[cav[k]] = s;
    int32_t f[3];
    verts_.clear();
    for (size_t k = 0; k < cav.size(); ++k)
    {
      if (cavSide[k] != sd)
        continue;
      const int32_t t = cav[k];
      for (int i = 0; i < 4; ++i)
      {
        if (m_.vertex(t, i) != p)
          verts_.push_back(m_.vertex(t, i));
        const int32_t u = m_.neighbor(t, i);
        if (u >= 0 && ed_.tetStamp[u] == s)
          continue;
        m_.faceVertices(t, i, f);
        if (f[0] == p || f[1] == p || f[2] == p)
          continue;
        faces.push_back({ { f[0], f[1], f[2] } });
      }
    }
    for (size_t k = 0; k < newTris.size(); ++k)
    {
      auto it = sideOf.find(newTriParent[k]);
      if (it == sideOf.end())
        return false;
      const auto& tr = newTris[k];
      if (it->second > 0)
        faces.push_back(tr);
      else
        faces.push_back({ { tr[0], tr[2], tr[1] } });
    }
    for (size_t a = 0; a < faces.size(); ++a)
      for (size_t b = a + 1; b < faces.size(); ++b)
        if (faces[a][0] >= 0 && faces[b][0] >= 0 &&
            TriKey(faces[a][0], faces[a][1], faces[a][2]) == TriKey(faces[b][0], faces[b][1], faces[b][2]))
        {
          faces[a][0] = -1;
          faces[b][0] = -1;
        }
    faces.erase(std::remove_if(faces.begin(), faces.end(), [](const std::array<int32_t, 3>& x) { return x[0] < 0; }),
                faces.end());
    // No vertex may become interior (it would be lost).
    for (int32_t v : verts_)
    {
      bool on = false;
      for (size_t a = 0; a < faces.size() && !on; ++a)
        on = faces[a][0] == v || faces[a][1] == v || faces[a][2] == v;
      if (!on)
        return false;
    }
    return !faces.empty();
  }

  // Adds to side sd's cavity the tets across its faces that are neither constraints nor new boundary
  // triangles, except those that would make a vertex interior. False when nothing could be added.
  bool enlarge(int32_t p, int sd, const std::vector<std::array<int32_t, 3>>& newTris)
  {
    const uint32_t s = ed_.newStamp();
    for (int32_t t : cav)
      ed_.tetStamp[t] = s;
    int32_t f[3];
    std::vector<int32_t> layer;
    const size_t n0 = cav.size();
    for (size_t k = 0; k < n0; ++k)
    {
      if (cavSide[k] != sd)
        continue;
      const int32_t t = cav[k];
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = m_.neighbor(t, i);
        if (u < 0 || ed_.tetStamp[u] == s)
          continue;
        m_.faceVertices(t, i, f);
        if (f[0] == p || f[1] == p || f[2] == p || bc_.findSubface(f[0], f[1], f[2]) >= 0)
          continue;
        bool isNew = false;
        for (auto& tr : newTris)
          isNew = isNew || TriKey(tr[0], tr[1], tr[2]) == TriKey(f[0], f[1], f[2]);
        if (isNew)
          continue;
        ed_.tetStamp[u] = s;
        layer.push_back(u);
      }
    }
    if (layer.empty())
      return false;
    // Add one tet at a time, keeping only those that leave every vertex on the cavity's boundary.
    bool any = false;
    for (int32_t u : layer)
    {
      if (cav.size() >= kMaxCavity)
        break;
      cav.push_back(u);
      cavSide.push_back(sd);
      if (!vertexOnBoundary(p, sd))
      {
        cav.pop_back();
        cavSide.pop_back();
        continue;
      }
      any = true;
    }
    return any;
  }

  // After adding tet u to side sd's cavity (whose vertices were all on its boundary before): u's vertices
  // other than p are still on a face of the cavity's boundary (only u's vertices can have lost one).
  bool vertexOnBoundary(int32_t p, int sd)
  {
    const int32_t u = cav.back();
    // Own marks: star() reuses the editor's stamps.
    if (mark_.size() < static_cast<size_t>(m_.tetCapacity()))
      mark_.resize(static_cast<size_t>(m_.tetCapacity()) + 1024, 0);
    if (++markStamp_ == 0)
    {
      std::fill(mark_.begin(), mark_.end(), 0);
      markStamp_ = 1;
    }
    const uint32_t s = markStamp_;
    for (size_t k = 0; k < cav.size(); ++k)
      if (cavSide[k] == sd)
        mark_[cav[k]] = s;
    for (int j = 0; j < 4; ++j)
    {
      const int32_t w = m_.vertex(u, j);
      if (w == p)
        continue;
      ed_.star(w, star_);
      bool on = false;
      for (size_t k = 0; k < star_.size() && !on; ++k)
      {
        const int32_t t = star_[k];
        if (mark_[t] != s)
          continue;
        const int lw = m_.localIndex(t, w);
        for (int i = 0; i < 4 && !on; ++i)
        {
          if (i == lw)
            continue;
          const int32_t n = m_.neighbor(t, i);
          on = n < 0 || mark_[n] != s;
        }
      }
      if (!on)
        return false;
    }
    return true;
  }
  std::vector<int32_t> star_;
  std::vector<uint32_t> mark_;
  uint32_t markStamp_ = 0;

  std::vector<int32_t> verts_;

  // A tet of `tets` has an edge, not on the cavity's boundary `faces`, that runs along a split input
  // segment (BoundaryConstraints::forbiddenEdge).
  bool foldsSegment(const std::vector<std::array<int32_t, 3>>& faces, const std::vector<std::array<int32_t, 4>>& tets)
  {
    std::unordered_set<uint64_t> kept;
    for (auto& fc : faces)
      for (int i = 0; i < 3; ++i)
        kept.insert(edgeKey(fc[i], fc[(i + 1) % 3]));
    static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (auto& q : tets)
      for (auto& e : kEdge)
        if (!kept.count(edgeKey(q[e[0]], q[e[1]])) && bc_.forbiddenEdge(q[e[0]], q[e[1]]))
          return true;
    return false;
  }

  // The cavity bounded by `faces` (each seen positively from inside) is star-shaped from one of its
  // vertices v: v sees every face not containing it strictly. The cone of those faces from v then fills
  // it (p collapsed onto v; the faces through v are matched by the cone's sides). The vertex giving the
  // best-shaped tets is chosen.
  bool coneFromVertex(const std::vector<std::array<int32_t, 3>>& faces, std::vector<std::array<int32_t, 4>>& tets)
  {
    std::vector<int32_t> verts;
    for (auto& fc : faces)
      verts.insert(verts.end(), fc.begin(), fc.end());
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    // The cone must close up: each cavity face once, every other face of its tets twice (a cavity whose
    // boundary is not a simple surface, e.g. with zero-volume parts, fails this).
    auto closes = [&](int32_t v)
    {
      std::unordered_map<TriKey, int, TriKeyHash> count;
      for (auto& fc : faces)
      {
        if (fc[0] == v || fc[1] == v || fc[2] == v)
          continue;
        ++count[TriKey(fc[0], fc[1], fc[2])];
        ++count[TriKey(fc[0], fc[1], v)];
        ++count[TriKey(fc[1], fc[2], v)];
        ++count[TriKey(fc[2], fc[0], v)];
      }
      for (auto& fc : faces)
      {
        auto it = count.find(TriKey(fc[0], fc[1], fc[2]));
        if (it == count.end() || it->second != 1)
          return false;
        it->second = 2;
      }
      for (auto& [k, n] : count)
        if (n != 2)
          return false;
      return true;
    };
    int32_t best = -1;
    double bestQ = 0;
    for (int32_t v : verts)
    {
      const double* V = m_.point(v);
      double q = 1e300;
      for (auto& fc : faces)
      {
        if (fc[0] == v || fc[1] == v || fc[2] == v)
          continue;
        const double *A = m_.point(fc[0]), *B = m_.point(fc[1]), *C = m_.point(fc[2]);
        if (orient3d(A, B, C, V) <= 0)
        {
          q = -1;
          break;
        }
        q = std::min(q, quality::tetShapeMeasure(A, B, C, V));
      }
      if (q >= 0 && (best < 0 || q > bestQ) && closes(v))
      {
        bestQ = q;
        best = v;
      }
    }
    if (best < 0)
      return false;
    tets.clear();
    for (auto& fc : faces)
      if (fc[0] != best && fc[1] != best && fc[2] != best)
        tets.push_back({ { fc[0], fc[1], fc[2], best } });
    return !tets.empty();
  }

  // The cavity tetrahedralized by a bounded search (CavityCarving.h), for small cavities only.
  bool carve(const std::vector<std::array<int32_t, 3>>& faces, std::vector<std::array<int32_t, 4>>& tets)
  {
    if (faces.size() > kMaxCarveFaces)
      return false;
    return carveCavity(
      m_, faces, [&](int32_t u, int32_t v) { return !bc_.forbiddenEdge(u, v); }, kMaxCarveSteps, tets);
  }

  MeshEditor& ed_;
  TetMesh& m_;
  BoundaryConstraints& bc_;
  std::vector<VertexKind>& kinds_;
  std::vector<int32_t>* region_;
  CavityInteriorPoint interiorPoint_{ m_ };
};

} // namespace

// Edge removals tried around one point that could not be removed.
constexpr size_t kMaxStarFlips = 200;

Status removeBoundarySteinerPoints(MeshEditor& ed, BoundaryConstraints& bc, std::vector<VertexKind>& kinds,
                                   std::vector<int32_t>* tetRegion, Progress* progress, SteinerRemovalReport* report)
{
  SilentProgress silent;
  Progress* pr = progress ? progress : &silent;
  SteinerRemovalReport rep;
  std::vector<int32_t> todo;
  for (int32_t v = 0; v < static_cast<int32_t>(kinds.size()); ++v)
    if ((kinds[v] == VertexKind::SteinerSegment || kinds[v] == VertexKind::SteinerFacet) && ed.tetOf(v) >= 0)
      todo.push_back(v);
  rep.boundaryBefore = static_cast<int64_t>(todo.size());
  Remover rem(ed, bc, kinds, tetRegion);
  // Facet points first (their polygons are closed), then segment points; retry what failed while the
  // neighbourhood keeps changing.
  std::stable_sort(todo.begin(), todo.end(),
                   [&](int32_t a, int32_t b)
                   { return kinds[a] == VertexKind::SteinerFacet && kinds[b] != VertexKind::SteinerFacet; });
  for (int pass = 0; pass < 4 && !todo.empty(); ++pass)
  {
    std::vector<int32_t> failed;
    size_t done = 0;
    for (int32_t v : todo)
    {
      if (++done % 64 == 0)
      {
        pr->report(static_cast<double>(done) / todo.size(), "Removing boundary Steiner points");
        if (pr->cancelled())
          return Status::failure(ErrorKind::Cancelled, "Steiner point removal was cancelled.");
      }
      if (rem.remove(v))
        ++rep.removed;
      else
        failed.push_back(v);
    }
    if (failed.size() == todo.size())
    {
      todo = failed;
      break;
    }
    todo = failed;
  }
  // What is left: reshape each point's neighbourhood by interior edge removals (StarFlips.h), retrying
  // the removal after each flip; a removal may unlock another point, hence the rounds.
  for (int round = 0; round < 3 && !todo.empty(); ++round)
  {
    std::vector<int32_t> failed;
    std::vector<std::pair<int32_t, int32_t>> edges;
    for (int32_t v : todo)
    {
      if (pr->cancelled())
        return Status::failure(ErrorKind::Cancelled, "Steiner point removal was cancelled.");
      bool removed = rem.remove(v);
      // The candidates are listed again after a round of flips (the star has changed).
      for (int attempt = 0; attempt < 4 && !removed; ++attempt)
      {
        starFlipCandidates(ed, bc, v, edges);
        int flipped = 0;
        for (size_t k = 0; k < edges.size() && k < kMaxStarFlips && !removed; ++k)
          if (removeEdgeKeepingRegion(ed, bc, edges[k].first, edges[k].second, tetRegion))
          {
            ++flipped;
            removed = rem.remove(v);
          }
        if (!flipped)
          break;
      }
      if (removed)
        ++rep.removed;
      else
        failed.push_back(v);
    }
    const bool progress = failed.size() < todo.size();
    todo = failed;
    if (!progress)
      break;
  }
  rep.remaining = static_cast<int64_t>(todo.size());
  for (size_t i = 0; i < todo.size() && i < 8; ++i)
    rep.firstRemaining.push_back(todo[i]);
  rep.addedInterior = rem.addedInterior;
  if (report)
    *report = rep;
  if (rep.remaining > 0)
    return Status::failure(ErrorKind::RecoveryFailed,
                           std::to_string(rep.remaining) +
                             " Steiner point(s) added on the boundary during recovery could not be "
                             "removed; the boundary would not equal the input (first vertex ids listed).",
                           std::vector<int64_t>(rep.firstRemaining.begin(), rep.firstRemaining.end()));
  return Status::success();
}

} // namespace volgrid
