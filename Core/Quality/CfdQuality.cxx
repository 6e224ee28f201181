// CFD face metrics as checkMesh defines them (see CfdQuality.h).
#include "CfdQuality.h"

#include "CellFaces.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>

namespace volgrid
{
namespace quality
{
namespace
{
constexpr double kRootVSmall = 1e-150; // checkMesh's guard against division by zero (ROOTVSMALL)
constexpr double kRadToDeg = 57.295779513082320876798154814105;

double dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void centroid(const double* a, const double* b, const double* c, double out[3])
{
  for (int k = 0; k < 3; ++k)
    out[k] = (a[k] + b[k] + c[k]) / 3.0;
}

void areaVector(const double* a, const double* b, const double* c, double s[3])
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  s[0] = 0.5 * (u[1] * v[2] - u[2] * v[1]);
  s[1] = 0.5 * (u[2] * v[0] - u[0] * v[2]);
  s[2] = 0.5 * (u[0] * v[1] - u[1] * v[0]);
}

// |sv| / fd for the face with centre fc, area vector s and corners pts[0..n) between the owner's centre and
// the centre-to-centre vector d (see the header).
double skewness(const double fc[3], const double s[3], const double* const* pts, int n, const double owner[3],
                const double d[3], double distanceFactor)
{
  const double cpf[3] = { fc[0] - owner[0], fc[1] - owner[1], fc[2] - owner[2] };
  const double f = dot(s, cpf) / (dot(s, d) + kRootVSmall);
  const double sv[3] = { cpf[0] - f * d[0], cpf[1] - f * d[1], cpf[2] - f * d[2] };
  const double magSv = std::sqrt(dot(sv, sv));
  const double svHat[3] = { sv[0] / (magSv + kRootVSmall), sv[1] / (magSv + kRootVSmall),
                            sv[2] / (magSv + kRootVSmall) };
  double fd = distanceFactor * std::sqrt(dot(d, d)) + kRootVSmall;
  for (int i = 0; i < n; ++i)
  {
    const double* p = pts[i];
    const double r[3] = { p[0] - fc[0], p[1] - fc[1], p[2] - fc[2] };
    fd = std::max(fd, std::fabs(dot(svHat, r)));
  }
  return magSv / fd;
}

// A boundary face is measured against the owner's mirror image: d is the normal part of Cpf.
double boundarySkewness(const double fc[3], const double s[3], const double* const* pts, int n, const double owner[3])
{
  const double magS = std::sqrt(dot(s, s));
  const double unit[3] = { s[0] / (magS + kRootVSmall), s[1] / (magS + kRootVSmall), s[2] / (magS + kRootVSmall) };
  const double cpf[3] = { fc[0] - owner[0], fc[1] - owner[1], fc[2] - owner[2] };
  const double along = dot(unit, cpf);
  const double d[3] = { unit[0] * along, unit[1] * along, unit[2] * along };
  return skewness(fc, s, pts, n, owner, d, 0.4);
}

void tetCentroid(const std::vector<double>& points, const int32_t* v, double c[3])
{
  for (int k = 0; k < 3; ++k)
    c[k] = 0.25 * (points[3 * v[0] + k] + points[3 * v[1] + k] + points[3 * v[2] + k] + points[3 * v[3] + k]);
}

double tetVolumeAbs(const std::vector<double>& points, const int32_t* v)
{
  const double* p0 = &points[3 * v[0]];
  double e[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      e[i][k] = points[3 * v[i + 1] + k] - p0[k];
  return std::fabs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                   e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                   e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
    6.0;
}
// checkMesh's average non-orthogonality: the angle of the mean cosine.
double averageAngle(double cosineSum, int64_t faces)
{
  if (faces == 0)
    return 0.0;
  return std::acos(std::max(-1.0, std::min(1.0, cosineSum / static_cast<double>(faces)))) * kRadToDeg;
}
// The figures of each face, gathered into the summary and the per-cell maxima.
struct FaceSink
{
  CfdSummary& sum;
  CfdCellMetrics& out;
  double cosineSum = 0;

  void skew(int32_t cell, double value)
  {
    out.skewness[cell] = std::max(out.skewness[cell], value);
    sum.maxSkewness = std::max(sum.maxSkewness, value);
    sum.highlySkewFaces += value > kHighSkewness;
  }
  void internal(int32_t o, int32_t n, double angle, double skewness, double ratio)
  {
    ++sum.internalFaces;
    cosineSum += std::cos(angle / kRadToDeg);
    sum.maxNonOrthogonality = std::max(sum.maxNonOrthogonality, angle);
    sum.severelyNonOrthogonalFaces += angle > kSevereNonOrthogonality;
    sum.maxVolumeRatio = std::max(sum.maxVolumeRatio, ratio);
    for (int32_t c : { o, n })
    {
      out.nonOrthogonality[c] = std::max(out.nonOrthogonality[c], angle);
      out.volumeRatio[c] = std::max(out.volumeRatio[c], ratio);
    }
    skew(o, skewness);
    out.skewness[n] = std::max(out.skewness[n], skewness);
  }
};
} // namespace

double faceNonOrthogonality(const double owner[3], const double neighbour[3], const double area[3])
{
  const double d[3] = { neighbour[0] - owner[0], neighbour[1] - owner[1], neighbour[2] - owner[2] };
  const double cosine = dot(d, area) / (std::sqrt(dot(d, d)) * std::sqrt(dot(area, area)) + kRootVSmall);
  return std::acos(std::max(-1.0, std::min(1.0, cosine))) * kRadToDeg;
}

double triangleLineCosine(const double* a, const double* b, const double* c, const double c1[3], const double c2[3])
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
  const double d[3] = { c2[0] - c1[0], c2[1] - c1[1], c2[2] - c1[2] };
  const double nn = std::sqrt(dot(n, n)), dd = std::sqrt(dot(d, d));
  if (!(nn > 0) || !(dd > 0))
    return 0;
  return std::abs(dot(n, d)) / (nn * dd);
}

double internalFaceSkewness(const double* a, const double* b, const double* c, const double owner[3],
                            const double neighbour[3])
{
  double fc[3], s[3];
  centroid(a, b, c, fc);
  areaVector(a, b, c, s);
  const double* pts[3] = { a, b, c };
  const double d[3] = { neighbour[0] - owner[0], neighbour[1] - owner[1], neighbour[2] - owner[2] };
  return skewness(fc, s, pts, 3, owner, d, 0.2);
}

double boundaryFaceSkewness(const double* a, const double* b, const double* c, const double owner[3])
{
  double fc[3], s[3];
  centroid(a, b, c, fc);
  areaVector(a, b, c, s);
  const double* pts[3] = { a, b, c };
  return boundarySkewness(fc, s, pts, 3, owner);
}

CfdSummary cfdMetrics(const std::vector<double>& points, const std::vector<int32_t>& tets, CfdCellMetrics* cells)
{
  MixedCells mesh;
  mesh.tets = &tets;
  return cfdMetricsMixed(points, mesh, cells);
}

// ---------------------------------------------------------------------------------------------------------
// Mixed meshes, tets alone included: the faces come from MixedCellFaces (prisms, pyramids, then tets) and
// the cell across each from faceNeighbours, so no list of faces is held.
namespace
{
// checkMesh's face centre and area vector (see the header) of the face with corners p[0..n).
void faceGeometry(const double* const* p, int n, double centre[3], double area[3])
{
  if (n == 3)
  {
    centroid(p[0], p[1], p[2], centre);
    areaVector(p[0], p[1], p[2], area);
    return;
  }
  double mean[3] = { 0, 0, 0 };
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      mean[k] += p[i][k] / n;
  double sumN[3] = { 0, 0, 0 }, sumAc[3] = { 0, 0, 0 }, sumA = 0;
  for (int i = 0; i < n; ++i)
  {
    const double* next = p[(i + 1) % n];
    double s[3];
    areaVector(p[i], next, mean, s);
    const double a = 2 * std::sqrt(dot(s, s));
    for (int k = 0; k < 3; ++k)
    {
      sumN[k] += 2 * s[k];
      sumAc[k] += a * (p[i][k] + next[k] + mean[k]);
    }
    sumA += a;
  }
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = sumA < kRootVSmall ? mean[k] : sumAc[k] / (3 * sumA);
    area[k] = sumA < kRootVSmall ? 0.0 : 0.5 * sumN[k];
  }
}

// One face of a cell as the metrics need it: corners, centre and area vector out of the cell.
struct Face
{
  const double* corner[4];
  int n;
  double centre[3], area[3];
};

// The cells and where their geometry lives; cell ids are MixedCellFaces'.
class MixedGeometry
{
public:
  MixedGeometry(const std::vector<double>& points, const std::vector<int32_t>& tets, const MixedCellFaces& cells)
    : points_(points)
    , tets_(tets)
    , cells_(cells)
    , numLayer_(cells.numberOfCells() - static_cast<int64_t>(tets.size() / 4))
  {
  }

  // Face f of cell c, out of it (a layer cell given the other way round, `turned`, has its loops inward).
  Face face(int64_t c, int f, bool turned) const
  {
    const std::array<int32_t, 4> loop = cells_.loop(c, f);
    Face face;
    face.n = loop[3] < 0 ? 3 : 4;
    for (int i = 0; i < face.n; ++i)
      face.corner[i] = points_.data() + 3 * static_cast<size_t>(loop[i]);
    faceGeometry(face.corner, face.n, face.centre, face.area);
    if (turned)
      for (double& a : face.area)
        a = -a;
    return face;
  }

  // The centre and volume of cell c: a tet's centroid; other cells checkMesh's face pyramids about the mean
  // of their face centres. Returns whether the cell's loops point into it.
  bool centreAndVolume(int64_t c, double centre[3], double& volume) const
  {
    if (c >= numLayer_)
    {
      const int32_t* v = tets_.data() + 4 * (c - numLayer_);
      tetCentroid(points_, v, centre);
      volume = tetVolumeAbs(points_, v);
      return false;
    }
    const int nf = cells_.numberOfFaces(c);
    Face faces[5];
    double estimate[3] = { 0, 0, 0 };
    for (int f = 0; f < nf; ++f)
    {
      faces[f] = face(c, f, false);
      for (int k = 0; k < 3; ++k)
        estimate[k] += faces[f].centre[k] / nf;
    }
    double weighted[3] = { 0, 0, 0 }, sum = 0;
    for (int f = 0; f < nf; ++f)
    {
      const double r[3] = { faces[f].centre[0] - estimate[0], faces[f].centre[1] - estimate[1],
                            faces[f].centre[2] - estimate[2] };
      const double v = dot(faces[f].area, r);
      for (int k = 0; k < 3; ++k)
        weighted[k] += v * (0.75 * faces[f].centre[k] + 0.25 * estimate[k]);
      sum += v;
    }
    for (int k = 0; k < 3; ++k)
      centre[k] = std::fabs(sum) > 1e-300 ? weighted[k] / sum : estimate[k];
    volume = std::fabs(sum) / 3.0;
    return sum < 0;
  }

private:
  const std::vector<double>& points_;
  const std::vector<int32_t>& tets_;
  const MixedCellFaces& cells_;
  const int64_t numLayer_; // prisms and pyramids, numbered before the tets
};
} // namespace

namespace
{
// MixedCellFaces numbers prisms, pyramids, then tets; the metrics are reported tets, prisms, pyramids.
struct ReportOrder
{
  int64_t numTets, numLayer;
  int32_t operator()(int64_t c) const { return static_cast<int32_t>(c < numLayer ? numTets + c : c - numLayer); }
};

// Every face once (an internal one from its smaller cell), into the summary and the per-cell maxima.
void measureFaces(const MixedCellFaces& faces, const MixedGeometry& geometry, const std::vector<int32_t>& across,
                  const std::vector<double>& centre, const std::vector<uint8_t>& turned, ReportOrder reported,
                  FaceSink& sink)
{
  for (int64_t c = 0; c < faces.numberOfCells(); ++c)
    for (int f = 0; f < faces.numberOfFaces(c); ++f)
    {
      const int32_t n = across[faces.firstFace(c) + f];
      if (n >= 0 && n < c)
        continue; // measured from the other side
      const Face face = geometry.face(c, f, c < reported.numLayer && turned[c]);
      const int32_t o = reported(c);
      const double* co = centre.data() + 3 * o;
      if (n < 0)
      {
        ++sink.sum.boundaryFaces;
        sink.skew(o, boundarySkewness(face.centre, face.area, face.corner, face.n, co));
        continue;
      }
      const int32_t r = reported(n);
      const double* cn = centre.data() + 3 * r;
      const double d[3] = { cn[0] - co[0], cn[1] - co[1], cn[2] - co[2] };
      const double vo = sink.out.volume[o], vn = sink.out.volume[r];
      sink.internal(o, r, faceNonOrthogonality(co, cn, face.area),
                    skewness(face.centre, face.area, face.corner, face.n, co, d, 0.2),
                    std::max(vo, vn) / std::max(std::min(vo, vn), 1e-300));
    }
}
} // namespace

CfdSummary cfdMetricsMixed(const std::vector<double>& points, const MixedCells& mesh, CfdCellMetrics* cells)
{
  static const std::vector<int32_t> kNone;
  const std::vector<int32_t>& tets = mesh.tets ? *mesh.tets : kNone;
  const MixedCellFaces faces(points, tets, mesh.prisms ? *mesh.prisms : kNone, mesh.pyramids ? *mesh.pyramids : kNone);
  const MixedGeometry geometry(points, tets, faces);
  const ReportOrder reported{ static_cast<int64_t>(tets.size() / 4),
                              faces.numberOfCells() - static_cast<int64_t>(tets.size() / 4) };
  const size_t numCells = static_cast<size_t>(faces.numberOfCells());
  CfdCellMetrics local;
  CfdCellMetrics& out = cells ? *cells : local;
  out.nonOrthogonality.assign(numCells, 0.0);
  out.skewness.assign(numCells, 0.0);
  out.volumeRatio.assign(numCells, 1.0);
  out.volume.assign(numCells, 0.0);
  CfdSummary sum;
  // A face of more than two cells fails, but the pairs found are measured all the same; a point id out of
  // range leaves nothing to measure.
  std::vector<int32_t> across;
  (void)faceNeighbours(faces, static_cast<int64_t>(points.size() / 3), across);
  if (static_cast<int64_t>(across.size()) != faces.numberOfCellFaces())
    return sum;
  std::vector<double> centre(3 * numCells);
  std::vector<uint8_t> turned(static_cast<size_t>(reported.numLayer));
  for (int64_t c = 0; c < faces.numberOfCells(); ++c)
  {
    const bool inward = geometry.centreAndVolume(c, centre.data() + 3 * reported(c), out.volume[reported(c)]);
    if (c < reported.numLayer)
      turned[c] = inward;
  }
  FaceSink sink{ sum, out };
  measureFaces(faces, geometry, across, centre, turned, reported, sink);
  sum.averageNonOrthogonality = averageAngle(sink.cosineSum, sum.internalFaces);
  return sum;
}

} // namespace quality
} // namespace volgrid
