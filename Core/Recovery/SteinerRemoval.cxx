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

  bool remove(int32_t p)
  {
    std::vector<int32_t> S;
    ed_.star(p, S);
    if (S.empty())
      return false;
    int32_t f[3];
    // Subfaces around p, grouped by parent.
    std::map<int32_t, std::vector<int32_t>> byParent;
    std::vector<int32_t> subs;
    for (int32_t t : S)
      for (int i = 0; i < 4; ++i)
      {
        if (m_.vertex(t, i) == p)
          continue;
        m_.faceVertices(t, i, f);
        const int32_t sf = bc_.findSubface(f[0], f[1], f[2]);
        if (sf >= 0 && std::find(subs.begin(), subs.end(), sf) == subs.end())
        {
          subs.push_back(sf);
          byParent[bc_.parent[sf]].push_back(sf);
        }
      }
    if (subs.empty())
      return false;
    // New boundary triangles per parent.
    struct Poly
    {
      std::vector<int32_t> v;
      int axis, o;
      int32_t parent;
      bool closed;
    };
    std::vector<Poly> polys;
    std::vector<std::array<int32_t, 3>> newTris;
    std::vector<int32_t> newTriParent;
    for (auto& [par, list] : byParent)
    {
      std::vector<std::pair<int32_t, int32_t>> fan; // (x, y) of (p, x, y)
      double nrm[3] = { 0, 0, 0 };
      for (int32_t sf : list)
      {
        const int32_t* s = bc_.subface(sf);
        int r = 0;
        while (s[r] != p)
          ++r;
        fan.push_back({ s[(r + 1) % 3], s[(r + 2) % 3] });
        const double *P = m_.point(p), *X = m_.point(s[(r + 1) % 3]), *Y = m_.point(s[(r + 2) % 3]);
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
      polys.push_back({ poly, axis, o, par, closed });
    }
    // Sides: components of S across faces containing p that are not subfaces.
    const uint32_t s0 = ed_.newStamp();
    for (int32_t t : S)
      ed_.tetStamp[t] = s0;
    std::vector<int32_t> side(S.size(), -1);
    auto indexOf = [&](int32_t t) { return static_cast<size_t>(std::find(S.begin(), S.end(), t) - S.begin()); };
    int nsides = 0;
    for (size_t k = 0; k < S.size(); ++k)
    {
      if (side[k] >= 0)
        continue;
      std::vector<int32_t> q = { S[k] };
      side[k] = nsides;
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
          if (side[iu] < 0)
          {
            side[iu] = nsides;
            q.push_back(u);
          }
        }
      }
      ++nsides;
    }
    if (nsides > 2)
      return false;
    // Which side of each parent each side lies on: +1 normal side, -1 other side.
    std::vector<std::map<int32_t, int>> sideOfParent(static_cast<size_t>(nsides));
    for (size_t k = 0; k < S.size(); ++k)
    {
      const int32_t t = S[k];
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
        for (int r = 0; r < 3; ++r)
          same = same || (f[0] == s[r] && f[1] == s[(r + 1) % 3] && f[2] == s[(r + 2) % 3]);
        // faceVertices is seen positively from t's vertex i, which is inside t: same order = t on the
        // normal side.
        sideOfParent[side[k]][bc_.parent[sf]] = same ? 1 : -1;
      }
    }
    // Per side: cavity faces and relocated point. Several triangulations of the polygons are tried: the
    // best-ear one, then fans from each polygon vertex.
    std::vector<std::array<int32_t, 4>> newTets;
    std::vector<int> newTetSide;
    std::vector<std::array<double, 3>> sidePoint(static_cast<size_t>(nsides));
    std::vector<int32_t> sideRegion(static_cast<size_t>(nsides), -1);
    std::vector<char> sideFilled(static_cast<size_t>(nsides), 0);
    size_t maxPoly = 3;
    for (auto& pl : polys)
      maxPoly = std::max(maxPoly, pl.v.size());
    bool good = false;
    for (size_t variant = 0; variant <= maxPoly && !good; ++variant)
    {
      newTris.clear();
      newTriParent.clear();
      newTets.clear();
      newTetSide.clear();
      good = true;
      for (auto& pl : polys)
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
          const size_t n = pl.v.size(), r = (variant - 1) % n;
          for (size_t k = 1; k + 1 < n; ++k)
          {
            tris.push_back({ { pl.v[r], pl.v[(r + k) % n], pl.v[(r + k + 1) % n] } });
            if (k + 2 < n && !allowed(pl.v[r], pl.v[(r + k + 1) % n]))
              good = false;
          }
        }
        for (auto& tr : tris)
        {
          newTris.push_back(tr);
          newTriParent.push_back(pl.parent);
        }
      }
      if (!good)
        continue;
      cav = S;
      cavSide = side;
      sideFilled.assign(static_cast<size_t>(nsides), 0);
      for (int sd = 0; sd < nsides && good; ++sd)
      {
        std::vector<std::array<int32_t, 3>> faces;
        for (size_t k = 0; k < S.size(); ++k)
          if (side[k] == sd && region_ && sideRegion[sd] < 0 && static_cast<size_t>(S[k]) < region_->size())
            sideRegion[sd] = (*region_)[S[k]];
        // The cavity of this side: p's star on this side, enlarged by layers of outer tets when no point
        // sees all of its faces (a reflex or flat neighbourhood of p).
        bool found = false, facesValid = false, coned = false;
        std::vector<std::array<int32_t, 4>> cone;
        for (int layer = 0; layer <= kMaxLayers && !found && !coned; ++layer)
        {
          facesValid = false;
          if (layer > 0 && !enlarge(p, sd, newTris))
            break;
          if (!cavityFaces(p, sd, newTris, newTriParent, sideOfParent[sd], faces))
            break;
          facesValid = true;
          found = interiorPoint_.find(p, faces, sidePoint[sd].data());
          // p's star may be flat (p rounded just outside a planar part of the boundary, between two
          // triangulations of it): the cone from one of the cavity's own vertices then fills it, or else a
          // search for a tetrahedralization of a small cavity without a new point.
          coned = !found && ((coneFromVertex(faces, cone) && !foldsSegment(faces, cone)) || carve(faces, cone));
        }
        if (coned)
        {
          sideFilled[static_cast<size_t>(sd)] = 1;
          for (auto& t : cone)
          {
            newTets.push_back(t);
            newTetSide.push_back(sd);
          }
          continue;
        }
        if (!found)
        {
          // No point sees the whole cavity: tetrahedralize it without a point (Delaunay fill).
          std::vector<std::array<int32_t, 4>> fill;
          std::vector<std::array<int32_t, 3>> missing;
          bool filled = false;
          for (int grow = 0; grow <= kMaxFillGrowth && facesValid && !filled; ++grow)
          {
            if (fillCavityDelaunay(m_, faces, fill, &missing))
            {
              if (foldsSegment(faces, fill))
                break;
              filled = true;
              break;
            }
            // Grow the cavity across the faces the Delaunay tetrahedralization lacks (TetGen's approach).
            bool grew = false;
            for (auto& mf : missing)
              grew = growAcross(p, sd, mf) || grew;
            if (!grew || !cavityFaces(p, sd, newTris, newTriParent, sideOfParent[sd], faces))
              break;
          }
          if (filled)
          {
            sideFilled[static_cast<size_t>(sd)] = 1;
            for (auto& t : fill)
            {
              newTets.push_back(t);
              newTetSide.push_back(sd);
            }
            continue;
          }
          good = false;
          break;
        }
        for (auto& fc : faces)
        {
          newTets.push_back({ { fc[0], fc[1], fc[2], -2 - sd } });
          newTetSide.push_back(sd);
        }
      }
    }
    if (!good)
      return false;
    // The relocated points are new vertices (p's id cannot be reused: faces through the old and the new
    // position would have the same ids).
    const int32_t firstNew = m_.numVertices();
    std::vector<int32_t> sideVertex(static_cast<size_t>(nsides), -1);
    int coneSides = 0;
    for (int sd = 0; sd < nsides; ++sd)
    {
      if (sideFilled[static_cast<size_t>(sd)])
        continue;
      sideVertex[static_cast<size_t>(sd)] = m_.addPoint(sidePoint[sd].data());
      kinds_.push_back(VertexKind::SteinerInterior);
      ++coneSides;
    }
    for (auto& t : newTets)
      if (t[3] <= -2)
        t[3] = sideVertex[static_cast<size_t>(-2 - t[3])];
    std::vector<int32_t> created;
    if (!ed_.replace(cav, newTets, &created, true))
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
        (*region_)[created[k]] = sideRegion[newTetSide[k]];
    }
    for (int32_t sf : subs)
      bc_.removeSubface(sf);
    for (size_t k = 0; k < newTris.size(); ++k)
      bc_.addSubface(newTris[k][0], newTris[k][1], newTris[k][2], newTriParent[k]);
    return true;
  }

private:
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
