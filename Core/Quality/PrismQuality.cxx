// Prism metrics: corner tets (exact signs), scaled Jacobian and volume.
#include "PrismQuality.h"

#include "Predicates.h"

#include <algorithm>
#include <cmath>

namespace volgrid
{
namespace quality
{
namespace
{
void sub(const double* a, const double* b, double out[3])
{
  out[0] = a[0] - b[0], out[1] = a[1] - b[1], out[2] = a[2] - b[2];
}

double tripleProduct(const double u[3], const double v[3], const double w[3])
{
  return (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] + (u[0] * v[1] - u[1] * v[0]) * w[2];
}

double length(const double u[3])
{
  return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
}
} // namespace

PrismMetrics prismMetrics(const double* const p[6])
{
  // Corner, its two triangle neighbours (positive order), its column neighbour.
  static const int kCorner[6][4] = { { 0, 1, 2, 3 }, { 1, 2, 0, 4 }, { 2, 0, 1, 5 },
                                     { 3, 5, 4, 0 }, { 4, 3, 5, 1 }, { 5, 4, 3, 2 } };
  static const double kSin60 = std::sqrt(3.0) / 2.0;
  PrismMetrics m{ 0.0, 1e300, 0 };
  for (const auto& c : kCorner)
  {
    const double *o = p[c[0]], *a = p[c[1]], *b = p[c[2]], *t = p[c[3]];
    m.nonPositiveCorners += predicates::orient3d(o, a, b, t) > 0 ? 0 : 1;
    double e1[3], e2[3], e3[3];
    sub(a, o, e1), sub(b, o, e2), sub(t, o, e3);
    const double lengths = length(e1) * length(e2) * length(e3);
    const double jacobian = lengths > 0 ? tripleProduct(e1, e2, e3) / lengths / kSin60 : 0.0;
    m.minScaledJacobian = std::min(m.minScaledJacobian, jacobian);
  }
  static const int kTets[3][4] = { { 0, 1, 2, 3 }, { 1, 2, 3, 4 }, { 2, 3, 4, 5 } };
  for (const auto& t : kTets)
  {
    double u[3], v[3], w[3];
    sub(p[t[1]], p[t[0]], u), sub(p[t[2]], p[t[0]], v), sub(p[t[3]], p[t[0]], w);
    m.volume += tripleProduct(u, v, w) / 6.0;
  }
  return m;
}

} // namespace quality
} // namespace volgrid
