// CFD face metrics as checkMesh defines them (see CfdQuality.h).
#include "CfdQuality.h"

#include "TetFaces.h"

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
  const size_t numTets = tets.size() / 4;
  std::vector<double> centre(3 * numTets), volume(numTets);
  for (size_t t = 0; t < numTets; ++t)
  {
    tetCentroid(points, tets.data() + 4 * t, centre.data() + 3 * t);
    volume[t] = tetVolumeAbs(points, tets.data() + 4 * t);
  }
  CfdCellMetrics local;
  CfdCellMetrics& out = cells ? *cells : local;
  out.nonOrthogonality.assign(numTets, 0.0);
  out.skewness.assign(numTets, 0.0);
  out.volumeRatio.assign(numTets, 1.0);
  out.volume = volume;
  CfdSummary sum;
  FaceSink sink{ sum, out };
  const std::vector<TetFace> faces = sortedTetFaces(points, tets);
  auto pt = [&](int32_t i) { return points.data() + 3 * static_cast<size_t>(i); };
  for (size_t i = 0; i < faces.size();)
  {
    const TetFace& f = faces[i];
    const int32_t o = f.tet;
    const double* co = centre.data() + 3 * o;
    const double *a = pt(f.loop[0]), *b = pt(f.loop[1]), *c = pt(f.loop[2]);
    if (i + 1 < faces.size() && faces[i + 1].key == f.key)
    {
      const int32_t n = faces[i + 1].tet;
      const double* cn = centre.data() + 3 * n;
      double s[3];
      areaVector(a, b, c, s); // oriented out of the owner, towards the neighbour
      sink.internal(o, n, faceNonOrthogonality(co, cn, s), internalFaceSkewness(a, b, c, co, cn),
                    std::max(volume[o], volume[n]) / std::max(std::min(volume[o], volume[n]), 1e-300));
      i += 2;
    }
    else
    {
      ++sum.boundaryFaces;
      sink.skew(o, boundaryFaceSkewness(a, b, c, co));
      i += 1;
    }
  }
  sum.averageNonOrthogonality = averageAngle(sink.cosineSum, sum.internalFaces);
  return sum;
}

// ---------------------------------------------------------------------------------------------------------
// Mixed meshes.
namespace
{
// The faces of each shape, corners listed to point out of a cell in SolverMesh's order.
struct Shape
{
  int corners;
  int faces;
  int8_t face[5][5]; // per face: corner count, then the corners
};
constexpr Shape kTet{ 4, 4, { { 3, 0, 2, 1 }, { 3, 0, 1, 3 }, { 3, 0, 3, 2 }, { 3, 1, 2, 3 } } };
constexpr Shape kPrism{ 6,
                        5,
                        { { 3, 0, 2, 1 }, { 3, 3, 4, 5 }, { 4, 0, 1, 4, 3 }, { 4, 1, 2, 5, 4 }, { 4, 2, 0, 3, 5 } } };
constexpr Shape kPyramid{ 5, 5, { { 4, 0, 3, 2, 1 }, { 3, 0, 1, 4 }, { 3, 1, 2, 4 }, { 3, 2, 3, 4 }, { 3, 3, 0, 4 } } };

struct MixedFace
{
  std::array<int32_t, 4> key; // sorted corner ids (INT32_MAX after a triangle's three)
  int32_t cell;
  int32_t corners[4]; // in the cell's outward order
  int n;
  double centre[3], area[3];
};

// checkMesh's face centre and area vector (see the header).
void faceGeometry(const std::vector<double>& points, MixedFace& f)
{
  const double* p[4];
  for (int i = 0; i < f.n; ++i)
    p[i] = points.data() + 3 * static_cast<size_t>(f.corners[i]);
  if (f.n == 3)
  {
    centroid(p[0], p[1], p[2], f.centre);
    areaVector(p[0], p[1], p[2], f.area);
    return;
  }
  double mean[3] = { 0, 0, 0 };
  for (int i = 0; i < f.n; ++i)
    for (int k = 0; k < 3; ++k)
      mean[k] += p[i][k] / f.n;
  double sumN[3] = { 0, 0, 0 }, sumAc[3] = { 0, 0, 0 }, sumA = 0;
  for (int i = 0; i < f.n; ++i)
  {
    const double* next = p[(i + 1) % f.n];
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
    f.centre[k] = sumA < kRootVSmall ? mean[k] : sumAc[k] / (3 * sumA);
    f.area[k] = sumA < kRootVSmall ? 0.0 : 0.5 * sumN[k];
  }
}

// The faces of one cell, with their geometry, appended to `faces`; the cell's centre and volume
// (checkMesh's face pyramids). Faces that point into the cell are turned.
void addCell(const std::vector<double>& points, const int32_t* ids, const Shape& shape, int32_t cell,
             std::vector<MixedFace>& faces, double centre[3], double& volume)
{
  const size_t first = faces.size();
  double estimate[3] = { 0, 0, 0 };
  for (int f = 0; f < shape.faces; ++f)
  {
    MixedFace face;
    face.cell = cell;
    face.n = shape.face[f][0];
    for (int i = 0; i < face.n; ++i)
      face.corners[i] = ids[shape.face[f][1 + i]];
    face.key = { face.corners[0], face.corners[1], face.corners[2], face.n == 4 ? face.corners[3] : INT32_MAX };
    std::sort(face.key.begin(), face.key.end());
    faceGeometry(points, face);
    for (int k = 0; k < 3; ++k)
      estimate[k] += face.centre[k] / shape.faces;
    faces.push_back(face);
  }
  double weighted[3] = { 0, 0, 0 }, sum = 0;
  for (size_t f = first; f < faces.size(); ++f)
  {
    const MixedFace& face = faces[f];
    const double r[3] = { face.centre[0] - estimate[0], face.centre[1] - estimate[1], face.centre[2] - estimate[2] };
    const double v = dot(face.area, r);
    for (int k = 0; k < 3; ++k)
      weighted[k] += v * (0.75 * face.centre[k] + 0.25 * estimate[k]);
    sum += v;
  }
  if (sum < 0) // given the other way round
    for (size_t f = first; f < faces.size(); ++f)
      for (int k = 0; k < 3; ++k)
        faces[f].area[k] = -faces[f].area[k];
  for (int k = 0; k < 3; ++k)
    centre[k] = std::fabs(sum) > 1e-300 ? weighted[k] / sum : estimate[k];
  volume = std::fabs(sum) / 3.0;
}

} // namespace

CfdSummary cfdMetricsMixed(const std::vector<double>& points, const MixedCells& mesh, CfdCellMetrics* cells)
{
  const std::pair<const std::vector<int32_t>*, const Shape*> groups[] = { { mesh.tets, &kTet },
                                                                          { mesh.prisms, &kPrism },
                                                                          { mesh.pyramids, &kPyramid } };
  size_t numCells = 0;
  for (const auto& g : groups)
    numCells += g.first ? g.first->size() / g.second->corners : 0;
  CfdCellMetrics local;
  CfdCellMetrics& out = cells ? *cells : local;
  out.nonOrthogonality.assign(numCells, 0.0);
  out.skewness.assign(numCells, 0.0);
  out.volumeRatio.assign(numCells, 1.0);
  out.volume.assign(numCells, 0.0);
  std::vector<double> centre(3 * numCells);
  std::vector<MixedFace> faces;
  faces.reserve(4 * numCells);
  int32_t cell = 0;
  for (const auto& g : groups)
    for (size_t i = 0; g.first && i + g.second->corners <= g.first->size(); i += g.second->corners, ++cell)
      addCell(points, g.first->data() + i, *g.second, cell, faces, centre.data() + 3 * cell, out.volume[cell]);
  std::sort(faces.begin(), faces.end(),
            [](const MixedFace& a, const MixedFace& b) { return a.key != b.key ? a.key < b.key : a.cell < b.cell; });

  CfdSummary sum;
  FaceSink sink{ sum, out };
  auto pt = [&](int32_t i) { return points.data() + 3 * static_cast<size_t>(i); };
  for (size_t i = 0; i < faces.size();)
  {
    const MixedFace& f = faces[i];
    const double* co = centre.data() + 3 * f.cell;
    const double* pts[4];
    for (int k = 0; k < f.n; ++k)
      pts[k] = pt(f.corners[k]);
    if (i + 1 < faces.size() && faces[i + 1].key == f.key)
    {
      const int32_t n = faces[i + 1].cell;
      const double* cn = centre.data() + 3 * n;
      const double d[3] = { cn[0] - co[0], cn[1] - co[1], cn[2] - co[2] };
      const double vo = out.volume[f.cell], vn = out.volume[n];
      sink.internal(f.cell, n, faceNonOrthogonality(co, cn, f.area), skewness(f.centre, f.area, pts, f.n, co, d, 0.2),
                    std::max(vo, vn) / std::max(std::min(vo, vn), 1e-300));
      i += 2;
    }
    else
    {
      ++sum.boundaryFaces;
      sink.skew(f.cell, boundarySkewness(f.centre, f.area, pts, f.n, co));
      i += 1;
    }
  }
  sum.averageNonOrthogonality = averageAngle(sink.cosineSum, sum.internalFaces);
  return sum;
}

} // namespace quality
} // namespace volgrid
