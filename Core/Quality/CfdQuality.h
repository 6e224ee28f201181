// CFD cell metrics of a tet mesh or of a mixed one (tets, boundary-layer prisms, pyramids), defined as
// OpenFOAM's checkMesh defines them, so that VolGrid Quality and checkMesh report the same figures for the
// same mesh (the tests compare them):
// - Cell centre: the tet's centroid (checkMesh's face-pyramid centre reduces to it for a tet). Other cells:
//   checkMesh's, the volume-weighted centroid of the pyramids that join each face to the mean of the
//   face centres; the cell volume is their sum.
// - Face centre and area vector: a triangle's centroid and half its cross product; a quad's (checkMesh's):
//   fanned into four triangles about the mean of its corners, the area-weighted mean of their centroids
//   and the sum of their area vectors (so a warped quad is measured as checkMesh measures it).
// - Face non-orthogonality (internal faces, degrees): the angle between the face's area vector S and the
//   vector d from the owner's centre to the neighbour's, acos(min(1, d.S / (|d| |S|))). Boundary faces
//   have none. checkMesh counts faces above 70 degrees as severely non-orthogonal.
// - Face skewness: |sv| / fd, with sv = Cpf - (S.Cpf / S.d) d the distance from the face centre to where the
//   owner-neighbour line crosses the face plane (Cpf = face centre - owner centre), and fd the larger of
//   0.2 |d| and the extent of the face's points from its centre along sv. A boundary face is measured
//   against the owner's mirror image (d = the normal part of Cpf, 0.4 |d|). checkMesh flags skewness > 4.
// - Volume ratio (internal faces): larger / smaller volume of the two cells.
// Per cell, each metric is the largest over the cell's faces (0 when it has none, 1 for the volume ratio).
#pragma once

#include <cstdint>
#include <vector>

namespace volgrid
{
namespace quality
{

constexpr double kSevereNonOrthogonality = 70.0; // degrees, checkMesh's threshold
constexpr double kHighSkewness = 4.0;            // checkMesh's threshold

struct CfdSummary
{
  int64_t internalFaces = 0, boundaryFaces = 0;
  // Over internal faces, degrees; the average is checkMesh's, the angle of the mean cosine.
  double maxNonOrthogonality = 0, averageNonOrthogonality = 0;
  int64_t severelyNonOrthogonalFaces = 0; // > kSevereNonOrthogonality
  double maxSkewness = 0;                 // over all faces
  int64_t highlySkewFaces = 0;            // > kHighSkewness
  double maxVolumeRatio = 1;
};

struct CfdCellMetrics
{
  std::vector<double> nonOrthogonality, skewness, volumeRatio; // one per cell
  std::vector<double> volume;                                  // one per cell, positive
};

// Non-orthogonality in degrees of a face with area vector `area` between cells centred at `owner` and
// `neighbour`.
double faceNonOrthogonality(const double owner[3], const double neighbour[3], const double area[3]);
// |cos| of the angle between the normal of triangle (a, b, c) and the line from c1 to c2: 1 when they are
// parallel (an orthogonal face), under cos(kSevereNonOrthogonality) for a severe one, 0 when the triangle
// or the line is degenerate.
double triangleLineCosine(const double* a, const double* b, const double* c, const double c1[3], const double c2[3]);
// Skewness of the triangle (a, b, c) between cell centres `owner` and `neighbour`.
double internalFaceSkewness(const double* a, const double* b, const double* c, const double owner[3],
                            const double neighbour[3]);
// Skewness of the boundary triangle (a, b, c) of the cell centred at `owner`.
double boundaryFaceSkewness(const double* a, const double* b, const double* c, const double owner[3]);

// All faces of the tet mesh (points: xyz; tets: 4 ids each). `cells` (may be null) receives the per-tet
// maxima.
CfdSummary cfdMetrics(const std::vector<double>& points, const std::vector<int32_t>& tets, CfdCellMetrics* cells);

// The cells of a mixed mesh, each shape in SolverMesh's order (Mesh/SolverMesh.h): tets (4 ids, positive),
// prisms (6: base a,b,c whose normal points to the top a',b',c'), pyramids (5: the quad turning towards
// the apex, then the apex). A cell given the other way round is measured the same (its faces are turned
// to point out of it).
struct MixedCells
{
  const std::vector<int32_t>* tets = nullptr;
  const std::vector<int32_t>* prisms = nullptr;
  const std::vector<int32_t>* pyramids = nullptr;
};

// All faces of the mixed mesh; faces match by their corner ids. `cells` (may be null) receives the
// per-cell maxima, tets first, then prisms, then pyramids. For tets only, the figures equal cfdMetrics'.
CfdSummary cfdMetricsMixed(const std::vector<double>& points, const MixedCells& mesh, CfdCellMetrics* cells);

} // namespace quality
} // namespace volgrid
