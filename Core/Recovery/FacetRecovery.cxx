#include "FacetRecovery.h"

#include "CavityDelaunay.h"
#include "Delaunay.h"
#include "Predicates.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <unordered_set>

namespace volgrid
{

namespace
{

using predicates::orient3d;

// Cavities larger than this are not attempted (the caller falls back to flips and Steiner points).
constexpr size_t kMaxCavityTets = 20000;
// Enlargement rounds per side before giving up.
constexpr int kMaxEnlargeRounds = 40;
// Slab mode's flip repair of a side's local tetrahedralization: size limit and number of flips.
constexpr int32_t kMaxRepairTets = 300;
constexpr int kMaxRepairFlips = 16;
constexpr int32_t kMaxRepairPairTets = 40;

using namespace cavity;

// A face of a cavity's boundary, oriented so that the cavity is on its positive side.
struct BFace
{
  int32_t v[3];
  int32_t outer; // mesh tet outside (-1: none)
  int outerFace; // its face index
};
using FaceMap = std::unordered_map<TriKey, BFace, TriKeyHash>;

class FacetCavity
{
public:
  // corners: the plane and extent of R (the input triangle, or the single subface when `single`). A
  // single-subface region keeps every other constraint, its siblings included.
  FacetCavity(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, const std::vector<int32_t>& subfaces,
              const int32_t* corners, bool single, bool slab = false)
    : ed_(ed)
    , m_(ed.mesh)
    , bc_(bc)
    , parent_(parent)
    , subfaces_(subfaces)
    , single_(single)
    , slab_(slab)
  {
    for (int k = 0; k < 3; ++k)
      abc_[k] = corners[k];
    A_ = m_.point(abc_[0]);
    B_ = m_.point(abc_[1]);
    C_ = m_.point(abc_[2]);
  }

  bool run(std::vector<std::array<int32_t, 3>>& out, FacetCavityStats* st)
  {
    // R's border: the edges used by exactly one subface of the triangle; each must be a mesh edge.
    std::unordered_map<uint64_t, int> uses;
    std::vector<int32_t> borderVerts;
    for (int32_t f : subfaces_)
      for (int i = 0; i < 3; ++i)
      {
        ++uses[edgeKey(bc_.subface(f)[i], bc_.subface(f)[(i + 1) % 3])];
        borderVerts.push_back(bc_.subface(f)[i]);
      }
    for (auto& [k, n] : uses)
      if (n == 1)
      {
        border_.insert(k);
        if (ed_.findEdge(static_cast<int32_t>(k >> 32), static_cast<int32_t>(k & 0xffffffffu)) < 0)
          return false;
      }
    std::sort(borderVerts.begin(), borderVerts.end());
    borderVerts.erase(std::unique(borderVerts.begin(), borderVerts.end()), borderVerts.end());
    if (slab_)
      borderSet_.insert(borderVerts.begin(), borderVerts.end());
    if (!collect(borderVerts))
      return false;
    if (!boundaryFaces())
      return false;
    std::vector<std::array<int32_t, 4>> newTets;
    std::unordered_map<TriKey, std::array<int32_t, 3>, TriKeyHash> tri[2];
    for (int s = 0; s < 2; ++s)
    {
      int round = 0;
      for (;; ++round)
      {
        std::vector<TriKey> missing;
        const size_t before = newTets.size();
        tri[s].clear();
        const int r = solveSide(s, newTets, tri[s], missing);
        if (r < 0)
          return false;
        if (r == 0)
          break;
        if (slab_ && coneSide(s, newTets, tri[s]))
          break;
        newTets.resize(before);
        if (round >= kMaxEnlargeRounds)
          return false;
        for (const TriKey& k : missing)
        {
          if (!faces_[s].count(k))
            continue; // inside a tet added for an earlier missing face
          if (!enlarge(s, k))
            return false;
          if (st)
            ++st->enlargements;
        }
      }
    }
    if (slab_)
    {
      // Each side's triangulation of R is a disk on R's border; the slab between them is filled.
      if (!isDisk(tri[0]) || !isDisk(tri[1]) || !fillSlab(tri, newTets))
        return false;
    }
    else
    {
      // Both sides triangulate R the same way, with opposite orientations.
      if (tri[0].size() != tri[1].size() || tri[0].empty())
        return false;
      for (auto& [k, f] : tri[0])
      {
        auto it = tri[1].find(k);
        if (it == tri[1].end() || orientedKey(f.data()) == orientedKey(it->second.data()))
          return false;
      }
      if (!isDisk(tri[0]))
        return false;
    }
    if (!interiorConstraintsFree() || createsForbiddenEdge(newTets))
      return false;
    std::vector<int32_t> old;
    old.reserve(tetSide_.size());
    for (auto& [t, s] : tetSide_)
      old.push_back(t);
    if (!ed_.replace(old, newTets, nullptr))
      return false;
    out.clear();
    for (auto& [k, f] : tri[0])
      out.push_back(f);
    return true;
  }

private:
  int side(int32_t v)
  {
    if (slab_ && borderSet_.count(v))
      return 0; // R's polygon: its rounded segment points count as on R
    auto it = sideCache_.find(v);
    if (it != sideCache_.end())
      return it->second;
    const int s = orient3d(A_, B_, C_, m_.point(v));
    sideCache_.emplace(v, static_cast<int8_t>(s));
    return s;
  }

  // Coplanar point u in the closed (strict = open) triangle ABC.
  bool inTriangle(const double* u, bool strict) const
  {
    for (int k = 0; k < 3; ++k)
    {
      const int o = predicates::orient2dProjected(A_, B_, C_, k);
      if (o == 0)
        continue;
      const int o1 = predicates::orient2dProjected(A_, B_, u, k), o2 = predicates::orient2dProjected(B_, C_, u, k),
                o3 = predicates::orient2dProjected(C_, A_, u, k);
      if (strict)
        return o1 * o > 0 && o2 * o > 0 && o3 * o > 0;
      return o1 * o >= 0 && o2 * o >= 0 && o3 * o >= 0;
    }
    return false;
  }

  bool onR(int32_t v)
  {
    if (slab_ && borderSet_.count(v))
      return true;
    auto it = onRCache_.find(v);
    if (it != onRCache_.end())
      return it->second;
    const bool r = side(v) == 0 && inTriangle(m_.point(v), false);
    onRCache_.emplace(v, r);
    return r;
  }

  // 1: t belongs to the cavity, 0: no, -1: a vertex lies inside R (cavity method not applicable).
  int classify(int32_t t)
  {
    const int32_t* v = m_.vertices(t);
    int s[4], zeros = 0;
    bool pos = false, neg = false;
    for (int i = 0; i < 4; ++i)
    {
      s[i] = side(v[i]);
      pos |= s[i] > 0;
      neg |= s[i] < 0;
      if (s[i] == 0)
      {
        ++zeros;
        if (!(slab_ && borderSet_.count(v[i])) && inTriangle(m_.point(v[i]), true))
          return -1;
      }
    }
    if (pos && neg)
    {
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
        {
          if (s[i] * s[j] >= 0)
            continue;
          const double *X = m_.point(v[i]), *Y = m_.point(v[j]);
          const int l1 = orient3d(X, Y, A_, B_), l2 = orient3d(X, Y, B_, C_), l3 = orient3d(X, Y, C_, A_);
          if ((l1 > 0 && l2 > 0 && l3 > 0) || (l1 < 0 && l2 < 0 && l3 < 0))
            return 1;
        }
      return 0;
    }
    if (zeros == 3)
    {
      for (int i = 0; i < 4; ++i)
        if (s[i] == 0 && !onR(v[i]))
          return 0;
      return 1;
    }
    return 0;
  }

  bool collect(const std::vector<int32_t>& borderVerts)
  {
    std::unordered_set<int32_t> tested;
    std::vector<int32_t> star, queue;
    for (int32_t v : borderVerts)
    {
      ed_.star(v, star);
      for (int32_t t : star)
      {
        if (!tested.insert(t).second)
          continue;
        const int c = classify(t);
        if (c < 0)
          return false;
        if (c > 0)
        {
          tetSide_.emplace(t, 2);
          queue.push_back(t);
        }
      }
    }
    for (size_t k = 0; k < queue.size(); ++k)
    {
      if (queue.size() > kMaxCavityTets)
        return false;
      for (int i = 0; i < 4; ++i)
      {
        const int32_t n = m_.neighbor(queue[k], i);
        if (n < 0 || !tested.insert(n).second)
          continue;
        const int c = classify(n);
        if (c < 0)
          return false;
        if (c > 0)
        {
          tetSide_.emplace(n, 2);
          queue.push_back(n);
        }
      }
    }
    return !queue.empty();
  }

  // Splits the cavity's outer faces into the upper (side 0) and lower (side 1) boundaries.
  bool boundaryFaces()
  {
    int32_t f[3];
    for (auto& [t, s] : tetSide_)
      for (int i = 0; i < 4; ++i)
      {
        const int32_t n = m_.neighbor(t, i);
        m_.faceVertices(t, i, f);
        if (n >= 0 && tetSide_.count(n))
          continue;
        bool pos = false, neg = false;
        for (int k = 0; k < 3; ++k)
        {
          const int sv = side(f[k]);
          pos |= sv > 0;
          neg |= sv < 0;
        }
        if (pos == neg)
          return false; // in the plane or crossing it: not the configuration the method relies on
        faces_[pos ? 0 : 1].emplace(TriKey(f[0], f[1], f[2]), BFace{ { f[0], f[1], f[2] }, n, m_.mirrorFace(t, i) });
      }
    return true;
  }

  // Grow side s's cavity by the tet outside its boundary face k.
  bool enlarge(int s, const TriKey& k)
  {
    auto it = faces_[s].find(k);
    if (it == faces_[s].end())
      return false;
    const BFace bf = it->second;
    const int32_t x = bf.outer;
    if (x < 0 || tetSide_.count(x) || bc_.findSubface(bf.v[0], bf.v[1], bf.v[2]) >= 0)
      return false;
    if (tetSide_.size() >= kMaxCavityTets)
      return false;
    faces_[s].erase(it);
    tetSide_.emplace(x, s);
    int32_t g[3];
    for (int j = 0; j < 4; ++j)
    {
      if (j == bf.outerFace)
        continue;
      m_.faceVertices(x, j, g);
      const TriKey gk(g[0], g[1], g[2]);
      const int32_t n = m_.neighbor(x, j);
      if (n >= 0 && tetSide_.count(n))
      {
        auto jt = faces_[s].find(gk);
        if (jt == faces_[s].end())
          return false; // touches the other side's cavity
        faces_[s].erase(jt);
        continue;
      }
      faces_[s].emplace(gk, BFace{ { g[0], g[1], g[2] }, n, m_.mirrorFace(x, j) });
    }
    return true;
  }

  // Delaunay tetrahedralization of side s's cavity. 0: done (tets appended to newTets, the faces in R
  // to tri), 1: boundary faces missing (listed), -1: failure.
  int solveSide(int s, std::vector<std::array<int32_t, 4>>& newTets,
                std::unordered_map<TriKey, std::array<int32_t, 3>, TriKeyHash>& tri, std::vector<TriKey>& missing)
  {
    const FaceMap& fm = faces_[s];
    if (fm.empty())
      return -1;
    std::vector<int32_t> verts;
    for (auto& [k, bf] : fm)
      verts.insert(verts.end(), bf.v, bf.v + 3);
    TetMesh lm; // local ids in global order: both sides break ties the same way
    if (!localDelaunay(m_, verts, lm))
      return -1;
    if (slab_)
      repairByFlips(lm, verts, fm);
    const std::unordered_map<OKey, int32_t, OKeyHash> owners = faceOwners(lm, verts);
    std::vector<int32_t> seeds;
    for (auto& [k, bf] : fm)
    {
      auto it = owners.find(orientedKey(bf.v));
      if (it == owners.end())
        missing.push_back(k);
      else
        seeds.push_back(it->second);
    }
    if (!missing.empty())
      return 1;
    const int want = s == 0 ? 1 : -1;
    // The fill stops at the cavity's boundary (reached from inside) and at faces in R (the apex on side s).
    auto step = [&](int32_t t, int i, const int32_t* f)
    {
      const TriKey k(f[0], f[1], f[2]);
      auto bt = fm.find(k);
      if (bt != fm.end())
        return orientedKey(bt->second.v) == orientedKey(f) ? FaceStep::Stop : FaceStep::Fail;
      if (!(onR(f[0]) && onR(f[1]) && onR(f[2])))
        return FaceStep::Cross;
      const int32_t apex = verts[static_cast<size_t>(lm.vertex(t, i))];
      if (side(apex) != want)
        return FaceStep::Fail;
      tri.emplace(k, std::array<int32_t, 3>{ { f[0], f[1], f[2] } });
      apex_[s][k] = apex;
      return FaceStep::Stop;
    };
    return floodFill(lm, verts, seeds, step, newTets) ? 0 : -1;
  }

  // A new edge (not on the cavity's boundary) running along a split segment
  // (BoundaryConstraints::forbiddenEdge).
  bool createsForbiddenEdge(const std::vector<std::array<int32_t, 4>>& newTets)
  {
    std::unordered_set<uint64_t> kept;
    for (int s = 0; s < 2; ++s)
      for (auto& [k, bf] : faces_[s])
        for (int i = 0; i < 3; ++i)
          kept.insert(edgeKey(bf.v[i], bf.v[(i + 1) % 3]));
    static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (auto& q : newTets)
      for (auto& e : kEdge)
        if (!kept.count(edgeKey(q[e[0]], q[e[1]])) && bc_.forbiddenEdge(q[e[0]], q[e[1]]))
          return true;
    return false;
  }

  // The removed tets' interior faces and edges must not be constraints of another triangle.
  bool interiorConstraintsFree()
  {
    std::unordered_set<uint64_t> bedges;
    for (int s = 0; s < 2; ++s)
      for (auto& [k, bf] : faces_[s])
        for (int i = 0; i < 3; ++i)
          bedges.insert(edgeKey(bf.v[i], bf.v[(i + 1) % 3]));
    static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    int32_t f[3];
    for (auto& [t, s] : tetSide_)
    {
      const int32_t* v = m_.vertices(t);
      for (auto& e : kEdge)
      {
        if (bedges.count(edgeKey(v[e[0]], v[e[1]])))
          continue;
        const std::array<int32_t, 2>* ef = bc_.edgeFaces(v[e[0]], v[e[1]]);
        if (!ef)
          continue;
        for (int32_t sf : *ef)
          if (sf >= 0 && (single_ || bc_.parent[sf] != parent_))
            return false;
      }
      for (int i = 0; i < 4; ++i)
      {
        m_.faceVertices(t, i, f);
        const TriKey k(f[0], f[1], f[2]);
        if (faces_[0].count(k) || faces_[1].count(k))
          continue;
        const int32_t sf = bc_.findSubface(f[0], f[1], f[2]);
        if (sf >= 0 && (single_ || bc_.parent[sf] != parent_))
          return false;
      }
    }
    return true;
  }

  // Slab mode: at a rounded border point the side may be reflex (a neighbour's constraint face meets R
  // there), so its Delaunay tetrahedralization lacks boundary faces that the cavity cannot grow across.
  // Flips of the local tetrahedralization (2-3, edge removal) are kept while they reduce the missing
  // boundary faces and their missing edges; small ones also try pairs of flips.
  void repairByFlips(TetMesh& lm, const std::vector<int32_t>& verts, const FaceMap& fm) const
  {
    if (lm.tetCapacity() > kMaxRepairTets)
      return;
    auto local = [&](int32_t g)
    { return static_cast<int32_t>(std::lower_bound(verts.begin(), verts.end(), g) - verts.begin()); };
    std::vector<std::array<int32_t, 3>> want;
    for (auto& [k, bf] : fm)
      want.push_back({ { local(bf.v[0]), local(bf.v[1]), local(bf.v[2]) } });
    auto score = [&](TetMesh& mesh)
    {
      MeshEditor e(mesh);
      int sc = 0;
      for (auto& f : want)
      {
        if (e.findFace(f[0], f[1], f[2]) >= 0)
          continue;
        sc += 4;
        for (int i = 0; i < 3; ++i)
          sc += e.findEdge(f[i], f[(i + 1) % 3]) < 0 ? 1 : 0;
      }
      return sc;
    };
    // Every mesh one flip away from `from`.
    auto neighbours = [](const TetMesh& from, std::vector<TetMesh>& out)
    {
      static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
      out.clear();
      for (int32_t t = 0; t < from.tetCapacity(); ++t)
      {
        if (from.isFree(t))
          continue;
        for (int op = 0; op < 10; ++op)
        {
          TetMesh trial = from;
          MeshEditor e(trial);
          bool ok;
          if (op < 4)
            ok = trial.neighbor(t, op) >= 0 && e.flip23(t, op, nullptr);
          else
          {
            const int32_t* v = trial.vertices(t);
            ok = e.removeEdge(t, v[kEdge[op - 4][0]], v[kEdge[op - 4][1]], nullptr);
          }
          if (ok)
            out.push_back(std::move(trial));
        }
      }
    };
    int best = score(lm);
    // Moves the first of `candidates` that scores better than `best` into lm.
    auto takeBetter = [&](std::vector<TetMesh>& candidates)
    {
      for (TetMesh& n : candidates)
      {
        const int sc = score(n);
        if (sc < best)
        {
          best = sc;
          lm = std::move(n);
          return true;
        }
      }
      return false;
    };
    std::vector<TetMesh> one, two;
    for (int pass = 0; pass < kMaxRepairFlips && best > 0; ++pass)
    {
      neighbours(lm, one);
      bool improved = takeBetter(one);
      if (!improved && lm.numTets() <= kMaxRepairPairTets)
        for (size_t i = 0; i < one.size() && !improved; ++i)
        {
          neighbours(one[i], two);
          improved = takeBetter(two);
        }
      if (!improved)
        break;
    }
  }

  // Slab mode, when side s's Delaunay tetrahedralization lacks boundary faces (the side is reflex at a
  // rounded border point): if some vertex off R sees every other face of the side strictly (its boundary
  // faces and R's current subfaces), the side is the cone of those faces from it.
  bool coneSide(int s, std::vector<std::array<int32_t, 4>>& newTets,
                std::unordered_map<TriKey, std::array<int32_t, 3>, TriKeyHash>& tri)
  {
    std::vector<std::array<int32_t, 3>> faces;
    std::vector<int32_t> cand;
    for (auto& [k, bf] : faces_[s])
    {
      faces.push_back({ { bf.v[0], bf.v[1], bf.v[2] } });
      for (int32_t v : bf.v)
        if (side(v) != 0)
          cand.push_back(v);
    }
    // R's subfaces, oriented with side s on their positive side (side 0 is where ABC turns positively).
    int axis = -1, o = 0;
    for (int k = 0; k < 3 && o == 0; ++k)
      if ((o = predicates::orient2dProjected(A_, B_, C_, k)) != 0)
        axis = k;
    if (axis < 0)
      return false;
    const size_t nBoundary = faces.size();
    for (int32_t f : subfaces_)
    {
      std::array<int32_t, 3> g = { { bc_.subface(f)[0], bc_.subface(f)[1], bc_.subface(f)[2] } };
      const int po = predicates::orient2dProjected(m_.point(g[0]), m_.point(g[1]), m_.point(g[2]), axis);
      if (po == 0)
        return false;
      if ((po == o) != (s == 0))
        std::swap(g[1], g[2]);
      faces.push_back(g);
    }
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    for (int32_t w : cand)
    {
      bool sees = true;
      for (auto& f : faces)
        if (f[0] != w && f[1] != w && f[2] != w &&
            orient3d(m_.point(f[0]), m_.point(f[1]), m_.point(f[2]), m_.point(w)) <= 0)
        {
          sees = false;
          break;
        }
      if (!sees)
        continue;
      for (auto& f : faces)
        if (f[0] != w && f[1] != w && f[2] != w)
          newTets.push_back({ { f[0], f[1], f[2], w } });
      tri.clear();
      for (size_t i = nBoundary; i < faces.size(); ++i)
      {
        const TriKey k(faces[i][0], faces[i][1], faces[i][2]);
        tri.emplace(k, faces[i]);
        apex_[s][k] = w;
      }
      return true;
    }
    return false;
  }

  // T (one side's triangulation of R) is a disk whose border is R's border.
  bool isDisk(const std::unordered_map<TriKey, std::array<int32_t, 3>, TriKeyHash>& t) const
  {
    if (t.empty())
      return false;
    std::unordered_map<uint64_t, int> uses;
    for (auto& [k, f] : t)
      for (int i = 0; i < 3; ++i)
        ++uses[edgeKey(f[i], f[(i + 1) % 3])];
    size_t seen = 0;
    for (auto& [k, n] : uses)
    {
      if (n == 1)
      {
        if (!border_.count(k))
          return false;
        ++seen;
      }
      else if (n != 2)
        return false;
    }
    return seen == border_.size();
  }

  // The rounded polygon of R is not planar, so the two sides may triangulate it differently: the thin
  // slab between the two triangulations (all its vertices on R's border) is filled by the Delaunay
  // tetrahedralization of its faces, and the upper triangulation becomes R's subfaces.
  bool fillSlab(const std::unordered_map<TriKey, std::array<int32_t, 3>, TriKeyHash> (&tri)[2],
                std::vector<std::array<int32_t, 4>>& newTets)
  {
    std::vector<std::array<int32_t, 3>> faces;
    for (int s = 0; s < 2; ++s)
      for (auto& [k, f] : tri[s])
      {
        if (tri[1 - s].count(k))
          continue;
        std::array<int32_t, 3> g = f;
        // The side's apex is outside the slab: orient the face away from it.
        if (orient3d(m_.point(g[0]), m_.point(g[1]), m_.point(g[2]), m_.point(apex_[s].at(k))) > 0)
          std::swap(g[1], g[2]);
        faces.push_back(g);
      }
    if (faces.empty())
      return true;
    std::vector<std::array<int32_t, 4>> tets;
    if (!fillCavityDelaunay(m_, faces, tets))
      return false;
    newTets.insert(newTets.end(), tets.begin(), tets.end());
    return true;
  }

  MeshEditor& ed_;
  TetMesh& m_;
  BoundaryConstraints& bc_;
  const int32_t parent_;
  const std::vector<int32_t>& subfaces_;
  const bool single_;
  const bool slab_;
  std::unordered_set<int32_t> borderSet_;
  std::unordered_map<TriKey, int32_t, TriKeyHash> apex_[2]; // side's tet apex over each face of T
  int32_t abc_[3];
  const double *A_, *B_, *C_;
  std::unordered_set<uint64_t> border_;
  std::unordered_map<int32_t, int8_t> sideCache_;
  std::unordered_map<int32_t, bool> onRCache_;
  std::unordered_map<int32_t, int> tetSide_; // removed tets: 2 = initial cavity, 0/1 = grown side
  FaceMap faces_[2];
};

// The whole-triangle cavity (slab: R's border vertices counted as on R); on success the subfaces of
// `parent` are replaced by the triangulation of R the cavity produced.
bool recoverWholeFacet(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, std::vector<int32_t>& subfaces,
                       FacetCavityStats* stats, bool slab)
{
  if (stats)
    ++stats->attempts;
  if (subfaces.empty())
    return false;
  std::vector<std::array<int32_t, 3>> tri;
  {
    FacetCavity fc(ed, bc, parent, subfaces, bc.verts.data() + 3 * static_cast<size_t>(parent), false, slab);
    if (!fc.run(tri, stats))
      return false;
  }
  for (int32_t f : subfaces)
    bc.removeSubface(f);
  subfaces.clear();
  for (auto& t : tri)
    subfaces.push_back(bc.addSubface(t[0], t[1], t[2], parent));
  if (stats)
    ++stats->successes;
  return true;
}

} // namespace

bool recoverFacetByCavity(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, std::vector<int32_t>& subfaces,
                          FacetCavityStats* stats)
{
  return recoverWholeFacet(ed, bc, parent, subfaces, stats, false);
}

bool recoverFacetBySlab(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, std::vector<int32_t>& subfaces,
                        FacetCavityStats* stats)
{
  return recoverWholeFacet(ed, bc, parent, subfaces, stats, true);
}

bool recoverSubfaceByCavity(MeshEditor& ed, BoundaryConstraints& bc, int32_t subface, FacetCavityStats* stats)
{
  if (stats)
    ++stats->attempts;
  if (!bc.alive(subface))
    return false;
  const int32_t* s = bc.subface(subface);
  if (ed.findFace(s[0], s[1], s[2]) >= 0)
    return true;
  const int32_t corners[3] = { s[0], s[1], s[2] };
  const std::vector<int32_t> one = { subface };
  std::vector<std::array<int32_t, 3>> tri;
  FacetCavity fc(ed, bc, bc.parent[subface], one, corners, true);
  if (!fc.run(tri, stats) || tri.size() != 1)
    return false;
  if (stats)
    ++stats->successes;
  return true;
}

} // namespace volgrid
