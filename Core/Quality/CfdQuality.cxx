// CFD face metrics as checkMesh defines them (see CfdQuality.h).
#include "CfdQuality.h"

#include "TetFaces.h"

#include <algorithm>
#include <cmath>

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

// |sv| / fd for the face (a, b, c) with centre-to-centre vector d (see the header).
double skewness(const double* a, const double* b, const double* c, const double owner[3], const double d[3],
                double distanceFactor)
{
  double fc[3], s[3];
  centroid(a, b, c, fc);
  areaVector(a, b, c, s);
  const double cpf[3] = { fc[0] - owner[0], fc[1] - owner[1], fc[2] - owner[2] };
  const double f = dot(s, cpf) / (dot(s, d) + kRootVSmall);
  const double sv[3] = { cpf[0] - f * d[0], cpf[1] - f * d[1], cpf[2] - f * d[2] };
  const double magSv = std::sqrt(dot(sv, sv));
  const double svHat[3] = { sv[0] / (magSv + kRootVSmall), sv[1] / (magSv + kRootVSmall),
                            sv[2] / (magSv + kRootVSmall) };
  double fd = distanceFactor * std::sqrt(dot(d, d)) + kRootVSmall;
  for (const double* p : { a, b, c })
  {
    const double r[3] = { p[0] - fc[0], p[1] - fc[1], p[2] - fc[2] };
    fd = std::max(fd, std::fabs(dot(svHat, r)));
  }
  return magSv / fd;
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
  const double d[3] = { neighbour[0] - owner[0], neighbour[1] - owner[1], neighbour[2] - owner[2] };
  return skewness(a, b, c, owner, d, 0.2);
}

double boundaryFaceSkewness(const double* a, const double* b, const double* c, const double owner[3])
{
  double fc[3], s[3];
  centroid(a, b, c, fc);
  areaVector(a, b, c, s);
  const double magS = std::sqrt(dot(s, s));
  const double n[3] = { s[0] / (magS + kRootVSmall), s[1] / (magS + kRootVSmall), s[2] / (magS + kRootVSmall) };
  const double cpf[3] = { fc[0] - owner[0], fc[1] - owner[1], fc[2] - owner[2] };
  const double along = dot(n, cpf);
  const double d[3] = { n[0] * along, n[1] * along, n[2] * along };
  return skewness(a, b, c, owner, d, 0.4);
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
  CfdSummary sum;
  double angleSum = 0;
  const std::vector<TetFace> faces = sortedTetFaces(points, tets);
  auto pt = [&](int32_t i) { return points.data() + 3 * static_cast<size_t>(i); };
  for (size_t i = 0; i < faces.size();)
  {
    const TetFace& f = faces[i];
    const int32_t o = f.tet;
    const double* co = centre.data() + 3 * o;
    const double *a = pt(f.loop[0]), *b = pt(f.loop[1]), *c = pt(f.loop[2]);
    double skew = 0;
    if (i + 1 < faces.size() && faces[i + 1].key == f.key)
    {
      const int32_t n = faces[i + 1].tet;
      const double* cn = centre.data() + 3 * n;
      double s[3];
      areaVector(a, b, c, s); // oriented out of the owner, towards the neighbour
      const double angle = faceNonOrthogonality(co, cn, s);
      skew = internalFaceSkewness(a, b, c, co, cn);
      const double ratio = std::max(volume[o], volume[n]) / std::max(std::min(volume[o], volume[n]), 1e-300);
      ++sum.internalFaces;
      angleSum += angle;
      sum.maxNonOrthogonality = std::max(sum.maxNonOrthogonality, angle);
      sum.severelyNonOrthogonalFaces += angle > kSevereNonOrthogonality;
      sum.maxVolumeRatio = std::max(sum.maxVolumeRatio, ratio);
      for (int32_t t : { o, n })
      {
        out.nonOrthogonality[t] = std::max(out.nonOrthogonality[t], angle);
        out.skewness[t] = std::max(out.skewness[t], skew);
        out.volumeRatio[t] = std::max(out.volumeRatio[t], ratio);
      }
      i += 2;
    }
    else
    {
      skew = boundaryFaceSkewness(a, b, c, co);
      ++sum.boundaryFaces;
      out.skewness[o] = std::max(out.skewness[o], skew);
      i += 1;
    }
    sum.maxSkewness = std::max(sum.maxSkewness, skew);
    sum.highlySkewFaces += skew > kHighSkewness;
  }
  sum.averageNonOrthogonality = sum.internalFaces > 0 ? angleSum / static_cast<double>(sum.internalFaces) : 0.0;
  return sum;
}

} // namespace quality
} // namespace volgrid
