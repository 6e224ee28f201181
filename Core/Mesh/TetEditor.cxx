#include "TetEditor.h"

#include "CfdQuality.h"
#include "Predicates.h"
#include "PredicatesInline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace volgrid
{

void FaceConstraints::addTriangles(const int32_t* tris, size_t n)
{
  set_.reserve(set_.size() + n);
  for (size_t i = 0; i < n; ++i)
    add(tris[3 * i], tris[3 * i + 1], tris[3 * i + 2]);
}

// ---------------------------------------------------------------------------------------------------------
namespace
{
// What both ways of computing tetSineQuality() start from: the six edge vectors (ab, ac, ad, bc, bd, cd),
// twice the area vectors of the faces opposite a, b, c, d, and det = 6 V.
struct TetFrame
{
  double e[6][3];
  double n[4][3];
  double det;
};

double dot(const double* u, const double* v)
{
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

TetFrame tetFrame(const double* a, const double* b, const double* c, const double* d)
{
  TetFrame f;
  const double* from[6] = { a, a, a, b, b, c };
  const double* to[6] = { b, c, d, c, d, d };
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 3; ++i)
      f.e[k][i] = to[k][i] - from[k][i];
  auto cross = [](const double* u, const double* v, double* w)
  {
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
  };
  const double *ab = f.e[0], *ac = f.e[1], *ad = f.e[2], *bc = f.e[3], *bd = f.e[4];
  cross(bc, bd, f.n[0]);
  cross(ac, ad, f.n[1]);
  cross(ab, ad, f.n[2]);
  cross(ab, ac, f.n[3]);
  f.det = dot(f.n[3], ad);
  return f;
}

// The plain formula with one square root per edge and per face: the fallback of tetSineQuality() when the
// squared products of the fast path would leave the normal double range (coordinates beyond ~1e+-38).
// Out of line and cold: inlined, its five square roots doubled the hot function's code.
[[gnu::noinline, gnu::cold]] double tetSineQualityPlain(const TetFrame& f)
{
  auto norm = [](const double* u) { return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); };
  const double det = f.det;
  double A[4];
  for (int i = 0; i < 4; ++i)
    A[i] = norm(f.n[i]);
  // sin(dihedral at edge e) = 6V |e| / (|n_k| |n_l|), k and l the vertices not on e.
  double L[6];
  for (int k = 0; k < 6; ++k)
    L[k] = norm(f.e[k]);
  // edge (a,b): faces opposite c,d; (a,c): b,d; (a,d): b,c; (b,c): a,d; (b,d): a,c; (c,d): a,b.
  const double P[6] = { A[2] * A[3], A[1] * A[3], A[1] * A[2], A[0] * A[3], A[0] * A[2], A[0] * A[1] };
  double q = 1.0;
  bool degenerate = false;
  for (int e = 0; e < 6; ++e)
  {
    if (!(P[e] > 0))
    {
      degenerate = true;
      continue;
    }
    q = std::min(q, std::fabs(det) * L[e] / P[e]);
  }
  if (degenerate || !(det != 0))
    return det < 0 ? -1e-300 : 0.0;
  return det < 0 ? -q : q;
}
} // namespace

double tetSineQuality(const double* a, const double* b, const double* c, const double* d)
{
  // The hottest function of the quality stages: squared lengths and areas, the smallest squared sine
  // det^2 |e|^2 / (|n_k|^2 |n_l|^2) over the edges by comparison, and a single square root.
  const TetFrame f = tetFrame(a, b, c, d);
  const double det = f.det;
  double A2[4], L2[6];
  for (int i = 0; i < 4; ++i)
    A2[i] = dot(f.n[i], f.n[i]);
  for (int k = 0; k < 6; ++k)
    L2[k] = dot(f.e[k], f.e[k]);
  const double P2[6] = { A2[2] * A2[3], A2[1] * A2[3], A2[1] * A2[2], A2[0] * A2[3], A2[0] * A2[2], A2[0] * A2[1] };
  double r = L2[0] / P2[0];
  bool normal = P2[0] > 1e-280 && P2[0] < 1e280;
  for (int e = 1; e < 6; ++e)
  {
    normal &= P2[e] > 1e-280 && P2[e] < 1e280;
    r = std::min(r, L2[e] / P2[e]);
  }
  if (!normal || !(det != 0))
    return tetSineQualityPlain(f);
  const double q = std::min(1.0, std::fabs(det) * std::sqrt(r));
  return det < 0 ? -q : q;
}

double sineQualityToDegrees(double q)
{
  if (!(q > 0))
    return 0.0;
  return std::asin(std::min(1.0, q)) * 180.0 / 3.14159265358979323846;
}

// ---------------------------------------------------------------------------------------------------------
TetEditor::TetEditor(TetMesh& m, const FaceConstraints* c, std::vector<int32_t>* l, VertexMap map)
  : MeshNavigator(m, StaleEntries::Trust, map)
  , constraints(c)
{
  labels = l;
}

std::vector<uint8_t> TetEditor::lockedVertices() const
{
  std::vector<uint8_t> locked(static_cast<size_t>(mesh.numVertices()), 0);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (mappedTet(v) < 0)
      locked[v] = 1;
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        if (isConstrainedFace(t, i))
        {
          int32_t f[3];
          mesh.faceVertices(t, i, f);
          for (int k = 0; k < 3; ++k)
            if (f[k] >= 0)
              locked[f[k]] = 1;
        }
    });
  return locked;
}

void TetEditor::neighbors(int32_t v, const std::vector<int32_t>& starTets, std::vector<int32_t>& out)
{
  out.clear();
  for (int32_t t : starTets)
  {
    const int32_t* w = mesh.vertices(t);
    for (int i = 0; i < 4; ++i)
      if (w[i] != v)
        out.push_back(w[i]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

bool TetEditor::edgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring, std::vector<int32_t>& tets,
                         int maxRing) const
{
  return walkEdgeRing(t, x, y, ring, tets, maxRing, [this](int32_t c, int f) { return isConstrainedFace(c, f); });
}

bool TetEditor::replace(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets,
                        std::vector<int32_t>* created)
{
  lastReplaceDeferred = false;
  if (oldTets.empty())
    return false;
  bool outside = false;
  if (regionLimit)
    for (int32_t t : oldTets)
      outside = outside || !regionLimit->owns(mesh.vertices(t));
  if (outside ||
      (slotPool && slotPool->available() + static_cast<int64_t>(oldTets.size()) < static_cast<int64_t>(newTets.size())))
  {
    lastReplaceDeferred = true;
    return false;
  }
  if (!replaceTets(oldTets, newTets, created, false))
    return false;
  ++replacements;
  return true;
}

int32_t TetEditor::locate(const double* p, int32_t start) const
{
  return walk(p, start, WalkOrder::Random);
}

int32_t TetEditor::locateRobust(const double* p, int32_t start) const
{
  int32_t t = locate(p, start);
  if (t >= 0)
    return t;
  const int32_t n = mesh.tetCapacity();
  for (int32_t u = 0; u < n; ++u)
  {
    if (mesh.isFree(u))
      continue;
    bool inside = true;
    for (int i = 0; i < 4 && inside; ++i)
    {
      int32_t f[3];
      mesh.faceVertices(u, i, f);
      inside = predicates::orient3dInline(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p) >= 0;
    }
    if (inside)
      return u;
  }
  return -1;
}

namespace
{
// TetEditor's cavity rule (ConflictCavity.h): every constrained face (hull or listed) stops growth and
// bounds the cavity, the SoS insphere decides conflicts (ties broken by vertex id, v the newest), and no
// tet whose closure holds p may go.
struct ConstrainedCavityRule
{
  const TetEditor& editor;
  const double* p;
  int32_t v;
  static constexpr bool kBlocksAreWalls = true;
  // With editor.regionLimit: set when a tet outside the region is in conflict (it is left out of the cavity).
  bool outsideRegion = false;

  bool wall(int32_t t, int i) const { return editor.isConstrainedFace(t, i); }
  bool blocks(int32_t t, int i) const { return wall(t, i); }
  bool conflicts(int32_t u)
  {
    const TetMesh& mesh = editor.mesh;
    const int32_t* w = mesh.vertices(u);
    const bool inSphere = predicates::insphereSoSInline(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]),
                                                        mesh.point(w[3]), p, w[0], w[1], w[2], w[3], v) > 0;
    if (inSphere && editor.regionLimit && !editor.regionLimit->owns(w))
    {
      outsideRegion = true;
      return false;
    }
    return inSphere;
  }
  int faceSide(int32_t t, int i) const
  {
    const TetMesh& mesh = editor.mesh;
    int32_t f[3];
    mesh.faceVertices(t, i, f);
    return predicates::orient3dInline(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p);
  }
  bool mustKeep(int32_t t) const
  {
    for (int i = 0; i < 4; ++i)
      if (faceSide(t, i) < 0)
        return false;
    return true;
  }
};

// Whether p (the rule's point) lies in the closure of `start` but on none of its constrained faces.
bool interiorStart(const ConstrainedCavityRule& rule, int32_t start)
{
  if (!rule.mustKeep(start))
    return false;
  for (int i = 0; i < 4; ++i)
    if (rule.faceSide(start, i) == 0 && rule.editor.isConstrainedFace(start, i))
      return false;
  return true;
}
} // namespace

bool TetEditor::buildCone(int32_t v, const double* p)
{
  ConstrainedCavityRule rule{ *this, p, v };
  coneTets_.clear();
  return cavity_.forBoundaryFaces(rule,
                                  [&](int32_t t, int i)
                                  {
                                    if (p && rule.faceSide(t, i) <= 0)
                                      return false;
                                    const int32_t* w = mesh.vertices(t);
                                    std::array<int32_t, 4> q = { w[0], w[1], w[2], w[3] };
                                    q[i] = v;
                                    coneTets_.add(q, mesh.neighborCode(t, i), i);
                                    return true;
                                  });
}

TetEditor::InsertStatus TetEditor::checkCavityVertices(int32_t v, const double* p, double minDistance, double* nearest)
{
  if (vstamp_.size() < static_cast<size_t>(mesh.numVertices()))
    vstamp_.resize(static_cast<size_t>(mesh.numVertices()) + 256, 0);
  // Mark the cone's base vertices (1), then look for an unmarked cavity vertex and the nearest one to p
  // (2: distance taken).
  for (const auto& q : coneTets_.tets)
    for (int k = 0; k < 4; ++k)
      if (q[k] != v)
        vstamp_[q[k]] = 1;
  bool lost = false;
  double best = 1e300;
  for (int32_t t : cavity_.tets)
  {
    const int32_t* w = mesh.vertices(t);
    for (int i = 0; i < 4; ++i)
    {
      int32_t& mark = vstamp_[w[i]];
      if (mark == 2)
        continue;
      if (mark == 1)
        mark = 2;
      else
        lost = true;
      const double* q = mesh.point(w[i]);
      const double d2 = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]);
      best = std::min(best, d2);
    }
  }
  for (const auto& q : coneTets_.tets)
    for (int k = 0; k < 4; ++k)
      if (q[k] != v)
        vstamp_[q[k]] = 0;
  best = std::sqrt(best);
  if (nearest)
    *nearest = best;
  if (lost)
    return InsertStatus::NoCavity;
  if (best < minDistance || best == 0)
    return InsertStatus::TooClose;
  return InsertStatus::Inserted;
}

TetEditor::InsertStatus TetEditor::insertPoint(int32_t v, int32_t start, double minDistance, double* nearest,
                                               std::vector<int32_t>* created)
{
  const double* p = mesh.point(v);
  if (start < 0 || mesh.isFree(start))
    return InsertStatus::NotInside;
  if (regionLimit && !regionLimit->owns(mesh.vertices(start)))
    return InsertStatus::Deferred;
  ConstrainedCavityRule rule{ *this, p, v };
  if (!interiorStart(rule, start))
    return InsertStatus::NotInside;
  // Conflict region not crossing constrained faces (nor, with a region limit, leaving the region), shrunk
  // until strictly star-shaped from p.
  cavity_.start(&start, 1);
  cavity_.grow(rule, SIZE_MAX);
  if (rule.outsideRegion)
  {
    cavity_.release();
    return InsertStatus::Deferred;
  }
  if (!cavity_.shrinkToStar(p, rule, &start, 1, 64))
    return InsertStatus::NoCavity;
  if (!buildCone(v, cavity_.starShaped() ? nullptr : p))
  {
    cavity_.release();
    return InsertStatus::NoCavity;
  }
  InsertStatus status = checkCavityVertices(v, p, minDistance, nearest);
  if (status == InsertStatus::Inserted && slotPool &&
      slotPool->available() + static_cast<int64_t>(cavity_.tets.size()) < static_cast<int64_t>(coneTets_.tets.size()))
    status = InsertStatus::Deferred;
  if (status != InsertStatus::Inserted)
  {
    cavity_.release();
    return status;
  }
  replaceByCone(cavity_.tets, coneTets_, created);
  ++replacements;
  return InsertStatus::Inserted;
}

bool TetEditor::seedQualityCavity(int32_t start, int32_t mustReplace)
{
  if (mustReplace < 0 || mustReplace == start)
  {
    cavity_.start(&start, 1);
    return true;
  }
  // Breadth first across unconstrained faces, at most 4 levels, remembering each tet's parent.
  const uint32_t seen = newStamp();
  bfsTets_.assign(1, { start, -1 });
  tetStamp[start] = seen;
  int32_t found = -1;
  for (size_t k = 0, levelEnd = 1, depth = 0; k < bfsTets_.size() && found < 0; ++k)
  {
    if (k == levelEnd)
    {
      levelEnd = bfsTets_.size();
      if (++depth == 4)
        break;
    }
    const int32_t t = bfsTets_[k].first;
    for (int i = 0; i < 4 && found < 0; ++i)
    {
      if (isConstrainedFace(t, i))
        continue;
      const int32_t u = mesh.neighbor(t, i);
      if (tetStamp[u] == seen)
        continue;
      tetStamp[u] = seen;
      bfsTets_.push_back({ u, static_cast<int32_t>(k) });
      if (u == mustReplace)
        found = static_cast<int32_t>(bfsTets_.size() - 1);
    }
  }
  if (found < 0)
    return false;
  seed_.clear();
  for (int32_t k = found; k >= 0; k = bfsTets_[k].second)
    seed_.push_back(bfsTets_[k].first);
  cavity_.start(seed_.data(), seed_.size());
  return true;
}

void TetEditor::addConeFaces(int32_t v, int32_t t)
{
  const int32_t* w = mesh.vertices(t);
  for (int i = 0; i < 4; ++i)
  {
    const bool constrained = isConstrainedFace(t, i);
    if (!constrained && cavity_.contains(mesh.neighbor(t, i)))
      continue;
    std::array<int32_t, 4> q = { w[0], w[1], w[2], w[3] };
    q[i] = v;
    double qc = -1; // not strictly positive: the cavity is not star-shaped from v
    if (predicates::orient3dInline(mesh.point(q[0]), mesh.point(q[1]), mesh.point(q[2]), mesh.point(q[3])) > 0)
    {
      qc = tetSineQuality(mesh.point(q[0]), mesh.point(q[1]), mesh.point(q[2]), mesh.point(q[3]));
      if (coneScore)
        qc = (*coneScore)(q.data(), qc);
    }
    cone_.push_back({ t, i, constrained, qc });
  }
}

bool TetEditor::coneKeepsCavityVertices()
{
  for (const ConeFace& f : cone_)
  {
    const int32_t* w = mesh.vertices(f.tet);
    for (int m = 0; m < 4; ++m)
      if (m != f.face)
        vstamp_[w[m]] = 1;
  }
  bool kept = true;
  for (int32_t t : cavity_.tets)
  {
    const int32_t* w = mesh.vertices(t);
    for (int m = 0; m < 4; ++m)
      kept &= vstamp_[w[m]] == 1;
  }
  for (int32_t t : cavity_.tets)
  {
    const int32_t* w = mesh.vertices(t);
    for (int m = 0; m < 4; ++m)
      vstamp_[w[m]] = 0;
  }
  return kept;
}

void TetEditor::growCavity(int32_t u)
{
  cavity_.add(u);
  size_t kept = 0;
  for (size_t k = 0; k < cone_.size(); ++k)
    if (cone_[k].constrained || !cavity_.contains(mesh.neighbor(cone_[k].tet, cone_[k].face)))
      cone_[kept++] = cone_[k];
  cone_.resize(kept);
}

double TetEditor::growByQuality(int32_t v, int maxCavity, double mustBeat)
{
  cone_.clear();
  for (int32_t t : cavity_.tets)
    addConeFaces(v, t);
  double bestQ = -3;
  for (int step = 0; step < maxCavity; ++step)
  {
    // Its worst tet, whether it is star-shaped, and the unconstrained face with the worst tet.
    double qMin = 2, qGrow = 3, qConstrained = 2;
    int growK = -1;
    bool valid = true;
    for (size_t k = 0; k < cone_.size(); ++k)
    {
      const ConeFace& f = cone_[k];
      qMin = std::min(qMin, f.quality);
      valid &= f.quality > -1;
      if (f.constrained)
        qConstrained = std::min(qConstrained, f.quality);
      else if (f.quality < qGrow)
      {
        qGrow = f.quality;
        growK = static_cast<int>(k);
      }
    }
    if (valid && qMin > std::max(bestQ, mustBeat) && coneKeepsCavityVertices())
    {
      bestQ = qMin;
      bestCavity_ = cavity_.tets;
    }
    // Constrained faces stay on the boundary of every larger cavity: no growth can beat their worst tet.
    if (growK < 0 || qConstrained <= std::max(bestQ, mustBeat))
      break;
    const int32_t u = mesh.neighbor(cone_[growK].tet, cone_[growK].face);
    growCavity(u);
    addConeFaces(v, u);
  }
  cavity_.release();
  return bestQ;
}

namespace
{
void tetCentroid(const TetMesh& m, const int32_t* w, double c[3])
{
  for (int k = 0; k < 3; ++k)
    c[k] = (m.point(w[0])[k] + m.point(w[1])[k] + m.point(w[2])[k] + m.point(w[3])[k]) / 4;
}

// Whether the triangle (a, b, c) between cells centred at c1 and c2 is further from orthogonal than
// severeCosine allows.
bool severeFace(const double* a, const double* b, const double* c, const double* c1, const double* c2,
                double severeCosine)
{
  return quality::triangleLineCosine(a, b, c, c1, c2) < severeCosine;
}
} // namespace

void TetEditor::countBelowInLastCavity(int32_t v, double q, int& newBelow, int& oldBelow)
{
  auto quality = [&](const int32_t* w)
  { return tetSineQuality(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3])); };
  oldBelow = 0;
  for (int32_t t : bestCavity_)
    oldBelow += quality(mesh.vertices(t)) < q;
  cavity_.start(bestCavity_.data(), bestCavity_.size());
  buildCone(v, nullptr);
  cavity_.release();
  newBelow = 0;
  for (const auto& c : coneTets_.tets)
    newBelow += quality(c.data()) < q;
}

int TetEditor::severeChangeOfLastCavity(int32_t v, double severeCosine)
{
  auto inCavity = [&](int32_t u) { return std::find(bestCavity_.begin(), bestCavity_.end(), u) != bestCavity_.end(); };
  int before = 0;
  for (int32_t t : bestCavity_)
  {
    double ct[3], cu[3];
    tetCentroid(mesh, mesh.vertices(t), ct);
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = mesh.neighbor(t, i);
      if (u < 0 || (u < t && inCavity(u))) // a face between two cavity tets counts once
        continue;
      tetCentroid(mesh, mesh.vertices(u), cu);
      int32_t f[3];
      mesh.faceVertices(t, i, f);
      before += severeFace(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), ct, cu, severeCosine);
    }
  }
  // The cone: each tet's base is a cavity boundary face, towards the tet beyond; its three sides through v
  // pair up at the cavity's boundary edges (the cavity is star-shaped from v, its boundary a sphere).
  cavity_.start(bestCavity_.data(), bestCavity_.size());
  buildCone(v, nullptr);
  cavity_.release();
  const size_t n = coneTets_.tets.size();
  coneCentroids_.resize(n);
  coneSides_.clear();
  int after = 0;
  for (size_t k = 0; k < n; ++k)
  {
    const std::array<int32_t, 4>& q = coneTets_.tets[k];
    tetCentroid(mesh, q.data(), coneCentroids_[k].data());
    int32_t base[3];
    for (int j = 0, m = 0; j < 4; ++j)
      if (j != coneTets_.apexAt[k])
        base[m++] = q[static_cast<size_t>(j)];
    const int32_t code = coneTets_.outerCode[k];
    if (code >= 0)
    {
      double cu[3];
      tetCentroid(mesh, mesh.vertices(code >> 2), cu);
      after += severeFace(mesh.point(base[0]), mesh.point(base[1]), mesh.point(base[2]), coneCentroids_[k].data(), cu,
                          severeCosine);
    }
    for (int e = 0; e < 3; ++e)
    {
      const int32_t a = std::min(base[e], base[(e + 1) % 3]), b = std::max(base[e], base[(e + 1) % 3]);
      coneSides_.emplace_back((static_cast<int64_t>(a) << 32) | static_cast<uint32_t>(b), static_cast<int32_t>(k));
    }
  }
  std::sort(coneSides_.begin(), coneSides_.end());
  for (size_t i = 0; i + 1 < coneSides_.size(); ++i)
    if (coneSides_[i].first == coneSides_[i + 1].first)
    {
      const auto a = static_cast<int32_t>(coneSides_[i].first >> 32);
      const auto b = static_cast<int32_t>(coneSides_[i].first & 0xffffffff);
      after += severeFace(mesh.point(v), mesh.point(a), mesh.point(b), coneCentroids_[coneSides_[i].second].data(),
                          coneCentroids_[coneSides_[i + 1].second].data(), severeCosine);
      ++i;
    }
  return after - before;
}

double TetEditor::qualityInsertion(int32_t v, int32_t start, int32_t mustReplace, double* replacedQuality, bool commit,
                                   std::vector<int32_t>* created, int maxCavity, double mustBeat)
{
  if (start < 0 || mesh.isFree(start))
    return -3;
  if (vstamp_.size() < static_cast<size_t>(mesh.numVertices()))
    vstamp_.resize(static_cast<size_t>(mesh.numVertices()) + 256, 0);
  if (!seedQualityCavity(start, mustReplace))
    return -3;
  const double bestQ = growByQuality(v, maxCavity, mustBeat);
  if (bestQ == -3)
    return -3;
  double qOld = 2;
  bool replaces = mustReplace < 0;
  for (int32_t t : bestCavity_)
  {
    const int32_t* w = mesh.vertices(t);
    qOld = std::min(qOld, tetSineQuality(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3])));
    replaces |= t == mustReplace;
  }
  if (!replaces)
    return -3;
  if (replacedQuality)
    *replacedQuality = qOld;
  if (commit)
  {
    cavity_.start(bestCavity_.data(), bestCavity_.size());
    buildCone(v, nullptr);
    replaceByCone(cavity_.tets, coneTets_, created);
    ++replacements;
  }
  return bestQ;
}

} // namespace volgrid
