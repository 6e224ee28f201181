#include "Quality.h"

#include "UnionFind.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace volgrid
{
namespace quality
{
namespace
{

constexpr double kDegrees = 57.29577951308232087680; // 180 / pi

struct V3
{
  double x, y, z;
};
inline V3 sub(const double a[3], const double b[3])
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline V3 operator-(const V3& a)
{
  return { -a.x, -a.y, -a.z };
}
inline V3 cross(const V3& a, const V3& b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
inline double dot(const V3& a, const V3& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double norm(const V3& a)
{
  return std::sqrt(dot(a, a));
}

// NaN and infinity (zero denominators) become kMaxRatio; see Quality.h.
inline double clampRatio(double r)
{
  return r < kMaxRatio ? r : kMaxRatio;
}

// Interior angle in degrees between two faces with consistently oriented normals n and m.
inline double dihedral(const V3& n, const V3& m)
{
  return std::atan2(norm(cross(n, m)), -dot(n, m)) * kDegrees;
}

// Everything the metrics share: edge vectors, squared lengths, inward face normals (face k is opposite
// vertex k; |n_k| is twice its area) and the triple product 6V.
struct TetGeometry
{
  V3 e[6]; // p1-p0, p2-p0, p3-p0, p2-p1, p3-p1, p3-p2
  double l2[6];
  V3 n[4];
  double nlen[4];
  double triple;

  TetGeometry(const double p0[3], const double p1[3], const double p2[3], const double p3[3])
  {
    e[0] = sub(p1, p0);
    e[1] = sub(p2, p0);
    e[2] = sub(p3, p0);
    e[3] = sub(p2, p1);
    e[4] = sub(p3, p1);
    e[5] = sub(p3, p2);
    for (int i = 0; i < 6; ++i)
    {
      l2[i] = dot(e[i], e[i]);
    }
    n[3] = cross(e[0], e[1]); // points to p3 when V > 0
    n[2] = cross(e[2], e[0]);
    n[1] = cross(e[1], e[2]);
    n[0] = cross(e[4], e[3]);
    for (int k = 0; k < 4; ++k)
    {
      nlen[k] = norm(n[k]);
    }
    triple = dot(e[0], n[1]); // a.(b x c)
  }

  bool degenerateFace() const { return nlen[0] == 0.0 || nlen[1] == 0.0 || nlen[2] == 0.0 || nlen[3] == 0.0; }

  // Circumradius, possibly inf/NaN for a flat tet (callers clamp).
  double circumradius() const
  {
    const V3 bc = n[1], ca = n[2], ab = n[3];
    const V3 o = { l2[0] * bc.x + l2[1] * ca.x + l2[2] * ab.x, l2[0] * bc.y + l2[1] * ca.y + l2[2] * ab.y,
                   l2[0] * bc.z + l2[1] * ca.z + l2[2] * ab.z };
    return norm(o) / (2.0 * std::fabs(triple));
  }

  // Van Oosterom-Strackee denominators of the four vertices, given the edge lengths.
  void solidAngleDenominators(const double l[6], double d[4]) const
  {
    // vertex 0: a = e0, b = e1, c = e2
    d[0] = l[0] * l[1] * l[2] + dot(e[0], e[1]) * l[2] + dot(e[1], e[2]) * l[0] + dot(e[2], e[0]) * l[1];
    // vertex 1: -e0, e3, e4
    d[1] = l[0] * l[3] * l[4] - dot(e[0], e[3]) * l[4] + dot(e[3], e[4]) * l[0] - dot(e[4], e[0]) * l[3];
    // vertex 2: -e1, -e3, e5
    d[2] = l[1] * l[3] * l[5] + dot(e[1], e[3]) * l[5] - dot(e[3], e[5]) * l[1] - dot(e[5], e[1]) * l[3];
    // vertex 3: -e2, -e4, -e5
    d[3] = l[2] * l[4] * l[5] + dot(e[2], e[4]) * l[5] + dot(e[4], e[5]) * l[2] + dot(e[5], e[2]) * l[4];
  }
};

// Faces meeting at each edge, in the edge order of TetGeometry::e.
constexpr int kEdgeFaces[6][2] = { { 2, 3 }, { 1, 3 }, { 1, 2 }, { 0, 3 }, { 0, 2 }, { 0, 1 } };

// The smallest and largest dihedral angles: the cosine orders the angles; only the two extremes pay for
// an atan2. A degenerate face gives min 0, max 180 (see Quality.h).
void dihedralExtremes(const TetGeometry& g, double& minAngle, double& maxAngle)
{
  if (g.degenerateFace())
  {
    minAngle = 0.0;
    maxAngle = 180.0;
    return;
  }
  const double inv[4] = { 1.0 / g.nlen[0], 1.0 / g.nlen[1], 1.0 / g.nlen[2], 1.0 / g.nlen[3] };
  int emin = 0, emax = 0;
  double cmax = -2.0, cmin = 2.0;
  for (int i = 0; i < 6; ++i)
  {
    const int f = kEdgeFaces[i][0], h = kEdgeFaces[i][1];
    const double c = -dot(g.n[f], g.n[h]) * inv[f] * inv[h];
    if (c > cmax)
    {
      cmax = c;
      emin = i;
    }
    if (c < cmin)
    {
      cmin = c;
      emax = i;
    }
  }
  minAngle = dihedral(g.n[kEdgeFaces[emin][0]], g.n[kEdgeFaces[emin][1]]);
  maxAngle = dihedral(g.n[kEdgeFaces[emax][0]], g.n[kEdgeFaces[emax][1]]);
}

} // namespace

TetMetrics tetMetrics(const double p0[3], const double p1[3], const double p2[3], const double p3[3])
{
  const TetGeometry g(p0, p1, p2, p3);
  TetMetrics m;
  double minL2 = g.l2[0], maxL2 = g.l2[0];
  double l[6];
  for (int i = 0; i < 6; ++i)
  {
    minL2 = std::min(minL2, g.l2[i]);
    maxL2 = std::max(maxL2, g.l2[i]);
    l[i] = std::sqrt(g.l2[i]);
  }
  m.aspectRatio = clampRatio(std::sqrt(maxL2 / minL2));
  m.volume = g.triple / 6.0;

  dihedralExtremes(g, m.minDihedralAngle, m.maxDihedralAngle);

  // Omega = 2 atan2(N, D) decreases with D for a fixed N >= 0: the smallest angle has the largest D.
  double d[4];
  g.solidAngleDenominators(l, d);
  const double dmax = std::max(std::max(d[0], d[1]), std::max(d[2], d[3]));
  m.minSolidAngle = 2.0 * std::atan2(std::fabs(g.triple), dmax);

  const double r = g.circumradius();
  m.radiusEdgeRatio = clampRatio(r / std::sqrt(minL2));
  const double areaSum2 = g.nlen[0] + g.nlen[1] + g.nlen[2] + g.nlen[3]; // twice the surface area
  m.radiusRatio = clampRatio(r * areaSum2 / (3.0 * std::fabs(g.triple)));
  return m;
}

double tetVolume(const double p0[3], const double p1[3], const double p2[3], const double p3[3])
{
  const V3 a = sub(p1, p0), b = sub(p2, p0), c = sub(p3, p0);
  return dot(a, cross(b, c)) / 6.0;
}

double tetAspectRatio(const double p0[3], const double p1[3], const double p2[3], const double p3[3])
{
  return tetMetrics(p0, p1, p2, p3).aspectRatio;
}

void tetDihedralAngles(const double p0[3], const double p1[3], const double p2[3], const double p3[3], double angles[6])
{
  const TetGeometry g(p0, p1, p2, p3);
  const bool degenerate = g.degenerateFace();
  for (int i = 0; i < 6; ++i)
  {
    angles[i] = degenerate ? 0.0 : dihedral(g.n[kEdgeFaces[i][0]], g.n[kEdgeFaces[i][1]]);
  }
  if (degenerate)
  {
    angles[5] = 180.0; // min 0, max 180: see Quality.h
  }
}

void tetDihedralExtremes(const double p0[3], const double p1[3], const double p2[3], const double p3[3],
                         double& minAngle, double& maxAngle)
{
  dihedralExtremes(TetGeometry(p0, p1, p2, p3), minAngle, maxAngle);
}

void tetSolidAngles(const double p0[3], const double p1[3], const double p2[3], const double p3[3], double omega[4])
{
  const TetGeometry g(p0, p1, p2, p3);
  double l[6], d[4];
  for (int i = 0; i < 6; ++i)
  {
    l[i] = std::sqrt(g.l2[i]);
  }
  g.solidAngleDenominators(l, d);
  for (int i = 0; i < 4; ++i)
  {
    omega[i] = 2.0 * std::atan2(std::fabs(g.triple), d[i]);
  }
}

TriangleMetrics triangleMetrics(const double a[3], const double b[3], const double c[3])
{
  const V3 u = sub(b, a), v = sub(c, a), w = sub(c, b);
  const double lu = dot(u, u), lv = dot(v, v), lw = dot(w, w);
  const double minL2 = std::min(lu, std::min(lv, lw));
  const double maxL2 = std::max(lu, std::max(lv, lw));
  const double twiceArea = norm(cross(u, v));
  TriangleMetrics m;
  m.area = 0.5 * twiceArea;
  m.aspectRatio = clampRatio(std::sqrt(maxL2 / minL2));
  if (minL2 == 0.0)
  {
    m.minAngle = 0.0;
    m.maxAngle = 180.0;
    return m;
  }
  const double ta = std::atan2(twiceArea, dot(u, v));
  const double tb = std::atan2(twiceArea, -dot(u, w));
  const double tc = std::atan2(twiceArea, dot(v, w));
  m.minAngle = std::min(ta, std::min(tb, tc)) * kDegrees;
  m.maxAngle = std::max(ta, std::max(tb, tc)) * kDegrees;
  return m;
}

template<typename Id>
void measureTets(const double* points, const Id* tets, int64_t begin, int64_t end, const TetMetricArrays& out)
{
  for (int64_t t = begin; t < end; ++t)
  {
    const Id* v = tets + 4 * t;
    const TetMetrics m = tetMetrics(points + 3 * static_cast<int64_t>(v[0]), points + 3 * static_cast<int64_t>(v[1]),
                                    points + 3 * static_cast<int64_t>(v[2]), points + 3 * static_cast<int64_t>(v[3]));
    if (out.aspectRatio)
      out.aspectRatio[t] = m.aspectRatio;
    if (out.minDihedralAngle)
      out.minDihedralAngle[t] = m.minDihedralAngle;
    if (out.maxDihedralAngle)
      out.maxDihedralAngle[t] = m.maxDihedralAngle;
    if (out.minSolidAngle)
      out.minSolidAngle[t] = m.minSolidAngle;
    if (out.volume)
      out.volume[t] = m.volume;
    if (out.radiusEdgeRatio)
      out.radiusEdgeRatio[t] = m.radiusEdgeRatio;
    if (out.radiusRatio)
      out.radiusRatio[t] = m.radiusRatio;
  }
}

void PointTets::reset(int64_t numPoints, int64_t numTets)
{
  NumPoints = numPoints;
  NumTets = numTets;
  Offsets.assign(static_cast<size_t>(numPoints) + 1, 0);
  Cursor.clear();
  Items.reset();
}

template<typename Id>
void PointTets::count(const Id* tets, int64_t pointBegin, int64_t pointEnd)
{
  int64_t* counts = Offsets.data() + 1;
  for (int64_t i = 0; i < 4 * NumTets; ++i)
  {
    const int64_t p = static_cast<int64_t>(tets[i]);
    if (p >= pointBegin && p < pointEnd)
    {
      ++counts[p];
    }
  }
}

void PointTets::finishCounts()
{
  std::partial_sum(Offsets.begin(), Offsets.end(), Offsets.begin());
  Cursor.assign(Offsets.begin(), Offsets.end() - 1);
  Items.reset(new int64_t[static_cast<size_t>(4 * NumTets)]);
}

template<typename Id>
void PointTets::fill(const Id* tets, int64_t pointBegin, int64_t pointEnd)
{
  for (int64_t i = 0; i < 4 * NumTets; ++i)
  {
    const int64_t p = static_cast<int64_t>(tets[i]);
    if (p >= pointBegin && p < pointEnd)
    {
      Items[Cursor[p]++] = i / 4;
    }
  }
}

namespace
{
template<typename Id>
inline bool holds(const Id* w, Id p)
{
  return w[0] == p || w[1] == p || w[2] == p || w[3] == p;
}
} // namespace

template<typename Id>
void volumeGradient(const Id* tets, const double* volumes, const PointTets& incidence, int64_t begin, int64_t end,
                    double* gradient)
{
  // The face neighbours of t are the tets other than t that share three of its points. Those sharing the
  // three faces through v0 are in v0's row and hold two of v1, v2, v3; those sharing the face opposite v0
  // are in v1's row and hold v2 and v3 but not v0 (holding all four, they would be t or a duplicate of t).
  for (int64_t t = begin; t < end; ++t)
  {
    const Id* v = tets + 4 * t;
    const double vt = volumes[t];
    double g = 0.0;
    for (const int64_t* it = incidence.begin(v[0]); it != incidence.end(v[0]); ++it)
    {
      const Id* w = tets + 4 * *it;
      const bool h1 = holds(w, v[1]), h2 = holds(w, v[2]);
      if (h1 && h2 ? !holds(w, v[3]) : (h1 || h2) && holds(w, v[3]))
      {
        g = std::max(g, std::fabs(vt - volumes[*it]));
      }
    }
    for (const int64_t* it = incidence.begin(v[1]); it != incidence.end(v[1]); ++it)
    {
      const Id* w = tets + 4 * *it;
      if (holds(w, v[2]) && holds(w, v[3]) && !holds(w, v[0]))
      {
        g = std::max(g, std::fabs(vt - volumes[*it]));
      }
    }
    gradient[t] = g;
  }
}

#define VOLGRID_QUALITY_INSTANTIATE(Id)                                                                                \
  template void measureTets<Id>(const double*, const Id*, int64_t, int64_t, const TetMetricArrays&);                   \
  template void PointTets::count<Id>(const Id*, int64_t, int64_t);                                                     \
  template void PointTets::fill<Id>(const Id*, int64_t, int64_t);                                                      \
  template void volumeGradient<Id>(const Id*, const double*, const PointTets&, int64_t, int64_t, double*);
VOLGRID_QUALITY_INSTANTIATE(int)
VOLGRID_QUALITY_INSTANTIATE(long)
VOLGRID_QUALITY_INSTANTIATE(long long)
#undef VOLGRID_QUALITY_INSTANTIATE

// ---- Surface-wide properties ----------------------------------------------------------------------

namespace
{
struct HalfEdge
{
  int64_t lo, hi, tri;
  bool forward; // lo -> hi in the triangle's orientation
  bool operator<(const HalfEdge& o) const { return lo != o.lo ? lo < o.lo : (hi != o.hi ? hi < o.hi : tri < o.tri); }
};
} // namespace

SurfaceSummary surfaceSummary(const double* points, int64_t numPoints, const int64_t* tris, int64_t numTris)
{
  SurfaceSummary s;
  s.elements = numTris;
  std::vector<HalfEdge> edges;
  edges.reserve(static_cast<size_t>(3 * numTris));
  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::max() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  for (int64_t t = 0; t < numTris; ++t)
  {
    const int64_t* v = tris + 3 * t;
    s.area += triangleMetrics(points + 3 * v[0], points + 3 * v[1], points + 3 * v[2]).area;
    for (int k = 0; k < 3; ++k)
    {
      const int64_t a = v[k], b = v[(k + 1) % 3];
      edges.push_back({ std::min(a, b), std::max(a, b), t, a < b });
      for (int j = 0; j < 3; ++j)
      {
        lo[j] = std::min(lo[j], points[3 * a + j]);
        hi[j] = std::max(hi[j], points[3 * a + j]);
      }
    }
  }
  std::sort(edges.begin(), edges.end());

  UnionFind<int64_t> triangles(static_cast<size_t>(numTris)), vertices(static_cast<size_t>(numPoints));
  std::vector<char> onBoundary(static_cast<size_t>(numPoints), 0);
  bool oriented = true;
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi)
    {
      triangles.unite(edges[i].tri, edges[j].tri);
      ++j;
    }
    const size_t uses = j - i;
    if (uses == 1)
    {
      ++s.boundaryEdges;
      vertices.unite(edges[i].lo, edges[i].hi);
      onBoundary[edges[i].lo] = onBoundary[edges[i].hi] = 1;
    }
    else if (uses == 2)
    {
      oriented = oriented && edges[i].forward != edges[i + 1].forward;
    }
    else
    {
      ++s.nonManifoldEdges;
      oriented = false;
    }
    i = j;
  }
  for (int64_t t = 0; t < numTris; ++t)
  {
    s.shells += triangles.find(t) == t;
  }
  for (int64_t p = 0; p < numPoints; ++p)
  {
    s.boundaryLoops += onBoundary[p] && vertices.find(p) == p;
  }
  s.closed = numTris > 0 && s.boundaryEdges == 0 && s.nonManifoldEdges == 0;
  s.consistentlyOriented = numTris > 0 && oriented;
  if (s.closed && s.consistentlyOriented)
  {
    // Sum of signed tets from the box centre: smaller terms and less cancellation than from the origin.
    const double r[3] = { 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
    double volume = 0.0;
    for (int64_t t = 0; t < numTris; ++t)
    {
      const int64_t* v = tris + 3 * t;
      volume += tetVolume(r, points + 3 * v[0], points + 3 * v[1], points + 3 * v[2]);
    }
    s.enclosedVolume = volume;
  }
  else
  {
    s.enclosedVolume = std::numeric_limits<double>::quiet_NaN();
  }
  return s;
}

} // namespace quality
double quality::tetShapeMeasure(const double* a, const double* b, const double* c, const double* d)
{
  double e[3][3];
  for (int i = 0; i < 3; ++i)
  {
    e[0][i] = b[i] - a[i];
    e[1][i] = c[i] - a[i];
    e[2][i] = d[i] - a[i];
  }
  const double vol = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
    e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  double s = 0;
  const double* p[4] = { a, b, c, d };
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      for (int k = 0; k < 3; ++k)
        s += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
  return s > 0 ? vol / (s * std::sqrt(s)) : 0;
}

} // namespace volgrid
