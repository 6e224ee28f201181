// Element quality of tetrahedral and triangle grids: the analysis of the VolGrid paper, section 8.2.
// Pure functions on coordinates and flat connectivity; no VTK. vtkVolGridQuality and `volgrid quality`
// call these, so the GUI, pvpython and the CLI report the same numbers.
//
// Definitions (paper section 8.2, made precise):
// - AspectRatio: longest edge / shortest edge. 1 for the regular tetrahedron or equilateral triangle.
// - Dihedral angles (degrees): the interior angle between the two faces meeting at each of the six edges,
//   computed as atan2(|n1 x n2|, -n1.n2) from the outward face normals (stable near 0 and 180 degrees).
//   They describe the shape only: an inverted (negatively oriented) tet has the same angles as its mirror.
// - MinSolidAngle (steradians): paper eq. 7 is the Van Oosterom-Strackee formula with unit edge vectors
//   a, b, c at a vertex; its right-hand side is tan(Omega/2), i.e. the paper's theta is half the solid
//   angle and the plain arctangent takes the wrong branch when the denominator is negative (Omega > pi).
//   We therefore compute Omega = 2 atan2(|a.(b x c)|, |a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|), which is
//   eq. 7 multiplied through by |a||b||c| (no normalisation, no division) and is exact in the limit
//   cases. The absolute value makes it orientation-independent. Regular tet: acos(23/27) = 0.5513 sr.
// - Volume: paper eq. 8, V = a.(b x c) / 6 with a = p1-p0, b = p2-p0, c = p3-p0: signed, positive for
//   VTK's tetra orientation (p3 on the side (p1-p0) x (p2-p0) points to), negative for inverted tets.
// - RadiusEdgeRatio: circumradius / shortest edge (sqrt(6)/4 = 0.6124 for the regular tet).
// - RadiusRatio: circumradius / (3 inradius), 1 for the regular tet; the same definition as
//   vtkMeshQuality's tet RADIUS_RATIO, used to cross-check.
// - Triangle MinAngle and MaxAngle (degrees) by atan2(|u x v|, u.v); Area = |(b-a) x (c-a)| / 2.
//
// Degenerate elements never produce NaN (NaN in the filters means "not measured": a skipped cell):
// - Ratios (AspectRatio, RadiusEdgeRatio, RadiusRatio) are clamped to kMaxRatio = 1e30, Verdict's
//   convention; that is their value when the denominator is zero (coincident points, flat tet).
// - If a face (triangle) has zero area because of coincident or collinear points, its normal is undefined:
//   the element's min angle is 0 and its max angle is 180 degrees. Flat tets with non-degenerate faces
//   get their true angles (0 and 180) from the formula.
// - MinSolidAngle is 0 for flat tets and for tets with coincident points (atan2(0, d) with d >= 0).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace volgrid
{
namespace quality
{

constexpr double kMaxRatio = 1e30;

struct TetMetrics
{
  double aspectRatio;
  double minDihedralAngle; // degrees
  double maxDihedralAngle; // degrees
  double minSolidAngle;    // steradians
  double volume;           // signed
  double radiusEdgeRatio;
  double radiusRatio;
};

struct TriangleMetrics
{
  double aspectRatio;
  double area;
  double minAngle; // degrees
  double maxAngle; // degrees
};

// All tet metrics at once (shares the edge vectors and face normals); p0..p3 are xyz triples.
TetMetrics tetMetrics(const double p0[3], const double p1[3], const double p2[3], const double p3[3]);
TriangleMetrics triangleMetrics(const double a[3], const double b[3], const double c[3]);

// Single metrics, for callers that need only one (same values as tetMetrics()).
double tetVolume(const double p0[3], const double p1[3], const double p2[3], const double p3[3]);
double tetAspectRatio(const double p0[3], const double p1[3], const double p2[3], const double p3[3]);
// A cheap shape measure used to choose between candidate tets (recovery, Steiner removal): six times the
// signed volume over (sum of squared edge lengths)^(3/2); largest for the regular tet, <= 0 when flat or
// inverted. Only ranks candidates: validity is always decided by the exact predicates.
double tetShapeMeasure(const double p0[3], const double p1[3], const double p2[3], const double p3[3]);
// The six dihedral angles in degrees, for edges (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
void tetDihedralAngles(const double p0[3], const double p1[3], const double p2[3], const double p3[3],
                       double angles[6]);
// The smallest and largest of the six dihedral angles in degrees (the same values as tetMetrics(); two
// atan2 instead of six: the angles are ranked by their cosines).
void tetDihedralExtremes(const double p0[3], const double p1[3], const double p2[3], const double p3[3],
                         double& minAngle, double& maxAngle);
// The solid angle at each vertex in steradians.
void tetSolidAngles(const double p0[3], const double p1[3], const double p2[3], const double p3[3], double omega[4]);

// Measures tets [begin, end) of a flat connectivity (4 point ids per tet) over flat xyz points and writes
// each metric into its array at the tet's index (any output pointer may be null). Safe to call
// concurrently on disjoint ranges; the values do not depend on how the range is split.
struct TetMetricArrays
{
  double* aspectRatio = nullptr;
  double* minDihedralAngle = nullptr;
  double* maxDihedralAngle = nullptr;
  double* minSolidAngle = nullptr;
  double* volume = nullptr;
  double* radiusEdgeRatio = nullptr;
  double* radiusRatio = nullptr;
};
template<typename Id>
void measureTets(const double* points, const Id* tets, int64_t begin, int64_t end, const TetMetricArrays& out);

// Surface-wide properties of a triangle surface (paper 8.2).
struct SurfaceSummary
{
  int64_t elements = 0;              // triangles
  double area = 0.0;                 // sum of triangle areas
  bool closed = false;               // every edge used by exactly two triangles
  bool consistentlyOriented = false; // every interior edge used once in each direction
  double enclosedVolume = 0.0;       // signed (positive for outward normals); NaN unless closed and oriented
  int64_t boundaryEdges = 0;         // edges used by one triangle
  int64_t boundaryLoops = 0;         // connected components of the boundary-edge graph
  int64_t nonManifoldEdges = 0;      // edges used by three or more triangles
  int64_t shells = 0;                // components of triangles connected through shared edges
};
// points: flat xyz; tris: 3 point ids per triangle. Ids must be in [0, numPoints).
SurfaceSummary surfaceSummary(const double* points, int64_t numPoints, const int64_t* tris, int64_t numTris);

// Face adjacency for the VolumeGradient: the tets incident to each point, in compressed rows, each row in
// increasing tet order. build() does it serially. A threaded caller runs reset(), then count() for
// disjoint point ranges concurrently, finishCounts(), then fill() for disjoint point ranges concurrently:
// every call reads all the tets but touches only its own points' rows, so there is no shared write and the
// rows are the same whatever the split.
class PointTets
{
public:
  template<typename Id>
  void build(const Id* tets, int64_t numTets, int64_t numPoints)
  {
    reset(numPoints, numTets);
    count(tets, 0, numPoints);
    finishCounts();
    fill(tets, 0, numPoints);
  }
  void reset(int64_t numPoints, int64_t numTets);
  template<typename Id>
  void count(const Id* tets, int64_t pointBegin, int64_t pointEnd);
  void finishCounts();
  template<typename Id>
  void fill(const Id* tets, int64_t pointBegin, int64_t pointEnd);

  const int64_t* begin(int64_t point) const { return Items.get() + Offsets[point]; }
  const int64_t* end(int64_t point) const { return Items.get() + Offsets[point + 1]; }

private:
  int64_t NumPoints = 0;
  int64_t NumTets = 0;
  std::vector<int64_t> Offsets; // counts shifted by one, then row starts
  std::vector<int64_t> Cursor;  // insertion positions during fill()
  std::unique_ptr<int64_t[]> Items;
};

// VolumeGradient (paper 8.2) of tets [begin, end): the largest |V(t) - V(n)| over the tets n that share a
// face with t (all of them if a face is shared by more than two); 0 for a tet without face neighbours.
// A duplicate of t (the same four points) is not a face neighbour. Safe to call concurrently on disjoint
// ranges; the result is exact, so it does not depend on the split or on the order within the rows.
template<typename Id>
void volumeGradient(const Id* tets, const double* volumes, const PointTets& incidence, int64_t begin, int64_t end,
                    double* gradient);

} // namespace quality
} // namespace volgrid
