// MeshEditor (BoundaryRecovery.h): local edits of a tet mesh without ghosts (replace, flips, edge
// removal, constrained vertex insertion, point location), shared by recovery and Steiner removal.
#include "MeshEditor.h"

#include "Predicates.h"
#include "Quality.h"
#include "RingTriangulation.h"

#include <algorithm>
#include <limits>

namespace volgrid
{

using predicates::orient3d;

MeshEditor::MeshEditor(TetMesh& m)
  : MeshNavigator(m, StaleEntries::Rescan)
{
}

bool MeshEditor::edgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring, std::vector<int32_t>& tets)
{
  constexpr int kMaxRingTets = 4096; // a guard against a broken adjacency, not a limit met in practice
  return walkEdgeRing(t, x, y, ring, tets, kMaxRingTets, [this](int32_t c, int f) { return mesh.neighbor(c, f) < 0; });
}

bool MeshEditor::replace(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets,
                         std::vector<int32_t>* created, bool allowOpen)
{
  if (!replaceTets(oldTets, newTets, created, allowOpen))
    return false;
  ++edits;
  return true;
}

bool MeshEditor::flip23(int32_t t, int face, const BoundaryConstraints* bc, std::vector<int32_t>* created)
{
  const int32_t u = mesh.neighbor(t, face);
  if (u < 0)
    return false;
  int32_t f[3];
  mesh.faceVertices(t, face, f);
  if (bc && bc->findSubface(f[0], f[1], f[2]) >= 0)
    return false;
  const int32_t p = mesh.vertex(t, face);
  const int32_t q = mesh.vertex(u, mesh.mirrorFace(t, face));
  if (bc && bc->forbiddenEdge(p, q))
    return false;
  const double *P = mesh.point(p), *Q = mesh.point(q), *A = mesh.point(f[0]), *B = mesh.point(f[1]),
               *C = mesh.point(f[2]);
  if (orient3d(Q, B, C, P) <= 0 || orient3d(A, Q, C, P) <= 0 || orient3d(A, B, Q, P) <= 0)
    return false;
  tmpNew_.clear();
  tmpNew_.push_back({ { q, f[1], f[2], p } });
  tmpNew_.push_back({ { f[0], q, f[2], p } });
  tmpNew_.push_back({ { f[0], f[1], q, p } });
  lastRemoved.clear();
  lastRemoved.push_back({ { mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2), mesh.vertex(t, 3) } });
  lastRemoved.push_back({ { mesh.vertex(u, 0), mesh.vertex(u, 1), mesh.vertex(u, 2), mesh.vertex(u, 3) } });
  std::vector<int32_t> old = { t, u };
  if (!replace(old, tmpNew_, created))
    return false;
  lastRemovedIds = old;
  ++flips23;
  return true;
}

bool MeshEditor::removeEdge(int32_t t, int32_t x, int32_t y, const BoundaryConstraints* bc,
                            std::vector<int32_t>* created, std::array<int32_t, 2> chord)
{
  if (bc && bc->isEdge(x, y))
    return false;
  ++removalAttempts;
  std::vector<int32_t>& ring = tmpRing_;
  std::vector<int32_t> tets;
  if (!edgeRing(t, x, y, ring, tets))
    return false;
  const int n = static_cast<int>(ring.size());
  if (n < 3 || n > 48)
    return false;
  const double* X = mesh.point(x);
  const double* Y = mesh.point(y);
  const double kInvalid = -std::numeric_limits<double>::infinity();
  auto chordOk = [&](int i, int j)
  { return j == i + 1 || (i == 0 && j == n - 1) || !bc->forbiddenEdge(ring[i], ring[j]); };
  // A required chord (positions ci < cj in the ring): no chord of the triangulation may cross it.
  int ci = -1, cj = -1;
  if (chord[0] >= 0)
  {
    for (int i = 0; i < n; ++i)
    {
      if (ring[i] == chord[0] || ring[i] == chord[1])
        (ci < 0 ? ci : cj) = i;
    }
    if (cj < 0)
      return false;
  }
  auto crossesChord = [&](int i, int j) { // i < j
    if (ci < 0)
      return false;
    const bool inI = i < ci && ci < j, inJ = i < cj && cj < j;
    const bool atI = i == ci || j == ci, atJ = i == cj || j == cj;
    return !atI && !atJ && inI != inJ;
  };
  auto triQ = [&](int i, int k, int j, double) -> double
  {
    if (bc && (!chordOk(i, k) || !chordOk(k, j) || !chordOk(i, j)))
      return kInvalid;
    if (crossesChord(i, k) || crossesChord(k, j) || crossesChord(i, j))
      return kInvalid;
    const double *A = mesh.point(ring[i]), *B = mesh.point(ring[k]), *C = mesh.point(ring[j]);
    if (orient3d(A, B, C, Y) <= 0 || orient3d(A, C, B, X) <= 0)
      return kInvalid;
    return std::min(quality::tetShapeMeasure(A, B, C, Y), quality::tetShapeMeasure(A, C, B, X));
  };
  std::vector<double> best;
  std::vector<int> choice;
  if (!maxMinTriangulation(n, kInvalid, best, choice, triQ))
    return false;
  tmpNew_.clear();
  appendRingTets(choice, ring, x, y, ChordOrder::PieceAfterApexFirst, tmpNew_);
  lastRemoved.clear();
  for (int32_t u : tets)
    lastRemoved.push_back({ { mesh.vertex(u, 0), mesh.vertex(u, 1), mesh.vertex(u, 2), mesh.vertex(u, 3) } });
  if (!replace(tets, tmpNew_, created))
    return false;
  lastRemovedIds = tets;
  if (n == 3)
    ++flips32;
  else
    ++flipsEdgeRemoval;
  return true;
}

bool MeshEditor::removeEdgeDeep(int32_t t, int32_t x, int32_t y, const BoundaryConstraints* bc,
                                std::vector<int32_t>* created, int depth, std::array<int32_t, 2> chord)
{
  if (removeEdge(t, x, y, bc, created, chord))
    return true;
  if (depth <= 0 || (bc && bc->isEdge(x, y)))
    return false;
  std::vector<int32_t> ring, tets;
  if (!edgeRing(t, x, y, ring, tets) || ring.size() <= 3 || ring.size() > 16)
    return false;
  for (size_t i = 0; i < ring.size(); ++i)
    for (int32_t e : { x, y })
    {
      const int32_t r = ring[i];
      if (bc && bc->isEdge(e, r))
        continue;
      const int32_t tt = findEdge(e, r);
      if (tt < 0)
        continue;
      std::vector<int32_t> sub;
      if (!removeEdgeDeep(tt, e, r, bc, &sub, depth - 1))
        continue;
      std::vector<std::array<int32_t, 4>> orig = lastRemoved;
      std::vector<int32_t> current = sub;
      const int32_t t2 = findEdge(x, y);
      std::vector<int32_t> fin;
      if (t2 >= 0 && removeEdge(t2, x, y, bc, &fin, chord))
      {
        // Compose: what the two flips removed from the original mesh, and what now covers it.
        for (size_t k = 0; k < lastRemovedIds.size(); ++k)
        {
          auto it = std::find(current.begin(), current.end(), lastRemovedIds[k]);
          if (it != current.end())
            current.erase(it);
          else
            orig.push_back(lastRemoved[k]);
        }
        // Ids recycled by the second flip may coincide with ids left in `current`: those are new tets.
        for (int32_t c : fin)
        {
          auto it = std::find(current.begin(), current.end(), c);
          if (it == current.end())
            current.push_back(c);
        }
        lastRemoved = orig;
        if (created)
          *created = current;
        return true;
      }
      // Undo the ring reduction.
      replace(sub, orig, nullptr);
    }
  return false;
}

int32_t MeshEditor::locate(const double* p, int32_t start)
{
  return walk(p, start, WalkOrder::Rotating);
}

// The tets whose closure contains the point of v, from t0 across the faces it lies on. False when the
// insertion must be refused: the point outside t0's closure (locate() inconsistent), v already a vertex
// there, the point on a hull or constraint face, or a vertex already at the point.
bool MeshEditor::insertionRoots(int32_t v, int32_t t0, const BoundaryConstraints* bc, std::vector<int32_t>& roots)
{
  const double* p = mesh.point(v);
  int32_t f[3];
  roots.assign(1, t0);
  const uint32_t sRoot = newStamp();
  tetStamp[t0] = sRoot;
  for (size_t k = 0; k < roots.size(); ++k)
  {
    const int32_t t = roots[k];
    for (int i = 0; i < 4; ++i)
    {
      mesh.faceVertices(t, i, f);
      const int o = orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p);
      if (o < 0)
        return false; // not in the closure: locate() is inconsistent
      if (o > 0)
        continue;
      if (f[0] == v || f[1] == v || f[2] == v)
        return false;
      // p on this face: the tet beyond must be split too.
      const int32_t u = mesh.neighbor(t, i);
      if (u < 0 || (bc && bc->findSubface(f[0], f[1], f[2]) >= 0))
        return false;
      if (tetStamp[u] != sRoot)
      {
        tetStamp[u] = sRoot;
        roots.push_back(u);
      }
    }
  }
  // A vertex at p already?
  for (int32_t t : roots)
    for (int i = 0; i < 4; ++i)
    {
      const double* q = mesh.point(mesh.vertex(t, i));
      if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2])
        return false;
    }
  return true;
}

namespace
{
// MeshEditor's cavity rule (ConflictCavity.h): growth stops at hull faces and boundary subfaces, the plain
// exact insphere decides conflicts (a cospherical tet stays out), only hull faces bound the cavity, and the
// roots (the tets whose closure holds p) must stay.
struct RecoveryCavityRule
{
  const TetMesh& mesh;
  const BoundaryConstraints* bc;
  const double* p;
  const std::vector<int32_t>& roots;
  static constexpr bool kBlocksAreWalls = false;

  bool wall(int32_t t, int i) const { return mesh.neighbor(t, i) < 0; }
  bool blocks(int32_t t, int i) const
  {
    if (wall(t, i))
      return true;
    if (!bc)
      return false;
    int32_t f[3];
    mesh.faceVertices(t, i, f);
    return bc->findSubface(f[0], f[1], f[2]) >= 0;
  }
  bool conflicts(int32_t u) const
  {
    const int32_t* w = mesh.vertices(u);
    return predicates::insphere(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]), p) > 0;
  }
  bool mustKeep(int32_t t) const { return std::find(roots.begin(), roots.end(), t) != roots.end(); }
};
} // namespace

// Whether the grown cavity holds every tet around a recovered boundary edge (it would delete the edge).
bool MeshEditor::cavityKillsBoundaryEdge(const BoundaryConstraints& bc)
{
  std::vector<int32_t> ring, rtets;
  static const int kE[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
  for (int32_t t : cavity_.tets)
  {
    const int32_t* w = mesh.vertices(t);
    for (auto& e : kE)
    {
      if (!bc.isEdge(w[e[0]], w[e[1]]) || !edgeRing(t, w[e[0]], w[e[1]], ring, rtets))
        continue;
      bool all = true;
      for (int32_t u : rtets)
        all = all && cavity_.contains(u);
      if (all)
        return true;
    }
  }
  return false;
}

bool MeshEditor::insertVertex(int32_t v, int32_t start, const BoundaryConstraints* bc)
{
  const double* p = mesh.point(v);
  const int32_t t0 = locate(p, start);
  if (t0 < 0)
    return false;
  std::vector<int32_t>& roots = roots_;
  if (!insertionRoots(v, t0, bc, roots))
    return false;
  // The cavity: the roots grown by Bowyer-Watson up to 4096 tets (insphere only sizes it), then made
  // star-shaped from p exactly. When growth would delete a recovered boundary edge the cavity falls back
  // to the roots (1-4, 2-6 or n-2n split, the paper's "connect the intersection point to the polyhedron").
  RecoveryCavityRule rule{ mesh, bc, p, roots };
  cavity_.start(roots.data(), roots.size());
  cavity_.grow(rule, 4096);
  if (bc && cavity_.tets.size() > roots.size() && cavityKillsBoundaryEdge(*bc))
    cavity_.start(roots.data(), roots.size());
  if (!cavity_.shrinkToStar(p, rule, roots.data(), roots.size(), 1000))
    return false;
  // The cone (v last: its face 3 is the boundary face), validated unless the shrink's last pass did.
  cone_.clear();
  const bool checked = cavity_.starShaped();
  const bool starShaped =
    cavity_.forBoundaryFaces(rule,
                             [&](int32_t t, int i)
                             {
                               int32_t f[3];
                               mesh.faceVertices(t, i, f);
                               if (!checked && orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p) <= 0)
                                 return false;
                               cone_.add({ { f[0], f[1], f[2], v } }, mesh.neighborCode(t, i), 3);
                               return true;
                             });
  if (!starShaped)
  {
    cavity_.release();
    return false;
  }
  replaceByCone(cavity_.tets, cone_, nullptr);
  ++edits;
  return true;
}

} // namespace volgrid
