#include "Enclosures.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace volgrid
{

namespace
{
const double kPi = 3.14159265358979323846;

// Appends triangles joining two closed rings of point ids with uniform angular spacing (both starting
// at angle 0, counter-clockwise about the local +z axis). With `lower` below (or outside) `upper`, the
// triangles face away from the axis (or toward +z for rings in one plane with `lower` outside).
void zipRings(SurfaceMesh& m, const std::vector<int32_t>& lower, const std::vector<int32_t>& upper, bool flip,
              int32_t patch)
{
  const int64_t na = static_cast<int64_t>(lower.size()), nb = static_cast<int64_t>(upper.size());
  auto add = [&](int32_t a, int32_t b, int32_t c)
  {
    if (flip)
    {
      m.addTriangle(a, c, b, patch);
    }
    else
    {
      m.addTriangle(a, b, c, patch);
    }
  };
  if (nb == 1)
  {
    for (int64_t i = 0; i < na; ++i)
    {
      add(lower[i], lower[(i + 1) % na], upper[0]);
    }
    return;
  }
  int64_t i = 0, j = 0;
  while (i < na || j < nb)
  {
    const bool advanceLower = j == nb || (i < na && (i + 1) * nb <= (j + 1) * na);
    if (advanceLower)
    {
      add(lower[i % na], lower[(i + 1) % na], upper[j % nb]);
      ++i;
    }
    else
    {
      add(lower[i % na], upper[(j + 1) % nb], upper[j % nb]);
      ++j;
    }
  }
}

// Local frame: local (x, y, z) -> global with local z along `axis` (a cyclic permutation, so
// orientation is preserved).
struct Frame
{
  double c[3];
  int axis;
  int32_t add(SurfaceMesh& m, double x, double y, double z) const
  {
    double g[3];
    g[axis] = z;
    g[(axis + 1) % 3] = x;
    g[(axis + 2) % 3] = y;
    return m.addPoint(c[0] + g[0], c[1] + g[1], c[2] + g[2]);
  }
};

std::vector<int32_t> ring(SurfaceMesh& m, const Frame& f, double radius, double z, int64_t n)
{
  std::vector<int32_t> ids;
  if (n <= 1 || radius == 0.0)
  {
    ids.push_back(f.add(m, 0, 0, z));
    return ids;
  }
  for (int64_t i = 0; i < n; ++i)
  {
    const double t = 2.0 * kPi * static_cast<double>(i) / static_cast<double>(n);
    ids.push_back(f.add(m, radius * std::cos(t), radius * std::sin(t), z));
  }
  return ids;
}

// A disk of concentric rings inside `outer` (radius R at height z); faces +z unless flip.
void disk(SurfaceMesh& m, const Frame& f, const std::vector<int32_t>& outer, double radius, double z, double h,
          bool flip, int32_t patch)
{
  const int64_t n = static_cast<int64_t>(outer.size());
  const int64_t rings = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(radius / h)));
  std::vector<int32_t> prev = outer;
  for (int64_t j = rings - 1; j >= 0; --j)
  {
    const double r = radius * static_cast<double>(j) / static_cast<double>(rings);
    const int64_t count = j == 0 ? 1 : std::max<int64_t>(6, std::llround(static_cast<double>(n) * j / rings));
    std::vector<int32_t> cur = ring(m, f, r, z, count);
    zipRings(m, prev, cur, flip, patch);
    prev.swap(cur);
  }
}

void icosphere(SurfaceMesh& m, int64_t freq, int32_t patch)
{
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  const double v[12][3] = { { -1, g, 0 },  { 1, g, 0 },  { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g },  { 0, 1, g },
                            { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 },  { g, 0, 1 },  { -g, 0, -1 }, { -g, 0, 1 } };
  const int f[20][3] = { { 0, 11, 5 }, { 0, 5, 1 },  { 0, 1, 7 },   { 0, 7, 10 }, { 0, 10, 11 },
                         { 1, 5, 9 },  { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
                         { 3, 9, 4 },  { 3, 4, 2 },  { 3, 2, 6 },   { 3, 6, 8 },  { 3, 8, 9 },
                         { 4, 9, 5 },  { 2, 4, 11 }, { 6, 2, 10 },  { 8, 6, 7 },  { 9, 8, 1 } };
  const double n = static_cast<double>(freq);
  for (const auto& face : f)
  {
    const double* A = v[face[0]];
    const double* B = v[face[1]];
    const double* C = v[face[2]];
    // Grid point (i, j) = (i*B + j*C + (n-i-j)*A) / n, computed symmetrically in the three corners so
    // that points on a shared icosahedron edge come out bit-identical from both faces.
    std::vector<int32_t> ids;
    auto index = [&](int64_t i, int64_t j) { return static_cast<size_t>(i * (freq + 1) - i * (i - 1) / 2 + j); };
    ids.resize(static_cast<size_t>((freq + 1) * (freq + 2) / 2));
    for (int64_t i = 0; i <= freq; ++i)
    {
      for (int64_t j = 0; i + j <= freq; ++j)
      {
        const double wa = static_cast<double>(freq - i - j), wb = static_cast<double>(i), wc = static_cast<double>(j);
        double p[3];
        for (int k = 0; k < 3; ++k)
        {
          double terms[3] = { wa * A[k], wb * B[k], wc * C[k] };
          // Sum the three terms in a fixed order of their corner ids (independent of the face).
          int order[3] = { 0, 1, 2 };
          const int cid[3] = { face[0], face[1], face[2] };
          std::sort(order, order + 3, [&](int x, int y) { return cid[x] < cid[y]; });
          p[k] = ((terms[order[0]] + terms[order[1]]) + terms[order[2]]) / n;
        }
        const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        ids[index(i, j)] = m.addPoint(p[0] / len, p[1] / len, p[2] / len);
      }
    }
    for (int64_t i = 0; i < freq; ++i)
    {
      for (int64_t j = 0; i + j < freq; ++j)
      {
        m.addTriangle(ids[index(i, j)], ids[index(i + 1, j)], ids[index(i, j + 1)], patch);
        if (i + j + 1 < freq)
        {
          m.addTriangle(ids[index(i + 1, j)], ids[index(i + 1, j + 1)], ids[index(i, j + 1)], patch);
        }
      }
    }
  }
  mergeCoincidentPoints(m);
}
} // namespace

EnclosureOptions enclosureAround(const BoundingBox& box, EnclosureShape shape, double scale, int axis)
{
  EnclosureOptions o;
  o.shape = shape;
  o.axis = (axis >= 0 && axis < 3) ? axis : 2;
  double ext[3];
  const double diag = box.valid ? box.diagonal() : 1.0;
  for (int k = 0; k < 3; ++k)
  {
    o.center[k] = box.valid ? 0.5 * (box.min[k] + box.max[k]) : 0.0;
    ext[k] = box.valid ? box.max[k] - box.min[k] : 1.0;
    ext[k] = std::max(ext[k], 1e-3 * diag); // flat inputs still get a solid enclosure
    if (!(ext[k] > 0))
    {
      ext[k] = 1.0;
    }
  }
  const double halfDiag = 0.5 * std::sqrt(ext[0] * ext[0] + ext[1] * ext[1] + ext[2] * ext[2]);
  const int a = o.axis, u = (a + 1) % 3, v = (a + 2) % 3;
  switch (shape)
  {
    case EnclosureShape::Box:
      for (int k = 0; k < 3; ++k)
      {
        o.dimensions[k] = scale * ext[k];
      }
      break;
    case EnclosureShape::Sphere:
      o.dimensions[0] = o.dimensions[1] = o.dimensions[2] = scale * halfDiag;
      break;
    case EnclosureShape::Ellipsoid:
      for (int k = 0; k < 3; ++k)
      {
        o.dimensions[k] = scale * 0.5 * std::sqrt(3.0) * ext[k];
      }
      break;
    case EnclosureShape::Cylinder:
      o.dimensions[0] = scale * 0.5 * std::sqrt(ext[u] * ext[u] + ext[v] * ext[v]);
      o.dimensions[1] = scale * ext[a];
      break;
    case EnclosureShape::Hemisphere:
    {
      // Disk on the box's minimum face along the axis; the dome must reach the far corners.
      o.center[a] = box.valid ? box.min[a] : 0.0;
      const double r = std::sqrt(0.25 * ext[u] * ext[u] + 0.25 * ext[v] * ext[v] + ext[a] * ext[a]);
      o.dimensions[0] = o.dimensions[1] = o.dimensions[2] = scale * r;
      break;
    }
  }
  return o;
}

double enclosureExactVolume(const EnclosureOptions& o)
{
  const double* d = o.dimensions;
  switch (o.shape)
  {
    case EnclosureShape::Box:
      return d[0] * d[1] * d[2];
    case EnclosureShape::Sphere:
      return 4.0 / 3.0 * kPi * d[0] * d[0] * d[0];
    case EnclosureShape::Ellipsoid:
      return 4.0 / 3.0 * kPi * d[0] * d[1] * d[2];
    case EnclosureShape::Cylinder:
      return kPi * d[0] * d[0] * d[1];
    case EnclosureShape::Hemisphere:
      return 2.0 / 3.0 * kPi * d[0] * d[0] * d[0];
  }
  return 0.0;
}

namespace
{
// The options' own checks (axis, the shape's dimensions, centre) and the target edge length h (given, or
// 1/16 of the size), refused when it would make more than ~20 M triangles.
Status checkEnclosure(const EnclosureOptions& o, double& h)
{
  if (o.axis < 0 || o.axis > 2)
  {
    return Status::failure(ErrorKind::InvalidOption, "enclosure axis must be 0, 1 or 2");
  }
  int needed = 1;
  switch (o.shape)
  {
    case EnclosureShape::Box:
    case EnclosureShape::Ellipsoid:
      needed = 3;
      break;
    case EnclosureShape::Cylinder:
      needed = 2;
      break;
    default:
      break;
  }
  double size = 0;
  for (int k = 0; k < needed; ++k)
  {
    if (!(o.dimensions[k] > 0) || !std::isfinite(o.dimensions[k]))
    {
      return Status::failure(ErrorKind::InvalidOption, "enclosure dimensions must be positive and finite");
    }
    size = std::max(size, o.dimensions[k]);
  }
  for (int k = 0; k < 3; ++k)
  {
    if (!std::isfinite(o.center[k]))
    {
      return Status::failure(ErrorKind::InvalidOption, "enclosure centre must be finite");
    }
  }
  const double reference = o.shape == EnclosureShape::Box ? size : 2.0 * size;
  h = o.targetEdgeLength > 0 ? o.targetEdgeLength : reference / 16.0;
  if (!std::isfinite(h) || (reference / h) > 3000.0)
  {
    return Status::failure(ErrorKind::InvalidOption,
                           "enclosure target edge length " + std::to_string(o.targetEdgeLength) +
                             " is too small for size " + std::to_string(reference) + " (more than ~20 M triangles)");
  }
  return Status::success();
}

// One face of the box: axis k fixed at side (0 low, 1 high), an n[u] x n[v] grid over the other two axes
// (cyclic), split into triangles with alternating diagonals, oriented outward.
void boxFace(SurfaceMesh& m, const EnclosureOptions& o, const int64_t n[3], int k, int side, int32_t patch)
{
  const double* c = o.center;
  const double* d = o.dimensions;
  auto coord = [&](int axis, int64_t i)
  {
    return i == n[axis] ? c[axis] + 0.5 * d[axis]
                        : c[axis] - 0.5 * d[axis] + d[axis] * static_cast<double>(i) / static_cast<double>(n[axis]);
  };
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  std::vector<int32_t> ids(static_cast<size_t>((n[u] + 1) * (n[v] + 1)));
  for (int64_t i = 0; i <= n[u]; ++i)
  {
    for (int64_t j = 0; j <= n[v]; ++j)
    {
      double p[3];
      p[k] = side ? c[k] + 0.5 * d[k] : c[k] - 0.5 * d[k];
      p[u] = coord(u, i);
      p[v] = coord(v, j);
      ids[static_cast<size_t>(i * (n[v] + 1) + j)] = m.addPoint(p[0], p[1], p[2]);
    }
  }
  for (int64_t i = 0; i < n[u]; ++i)
  {
    for (int64_t j = 0; j < n[v]; ++j)
    {
      const int32_t a = ids[static_cast<size_t>(i * (n[v] + 1) + j)];
      const int32_t b = ids[static_cast<size_t>((i + 1) * (n[v] + 1) + j)];
      const int32_t e = ids[static_cast<size_t>((i + 1) * (n[v] + 1) + j + 1)];
      const int32_t f = ids[static_cast<size_t>(i * (n[v] + 1) + j + 1)];
      // (u, v, k) is right-handed: a->b->e turns toward +k. Alternate diagonals.
      const bool alt = ((i + j) & 1) != 0;
      const int32_t tris[2][3] = { { a, b, alt ? e : f }, { alt ? a : b, e, f } };
      for (const auto& t : tris)
      {
        // The high side as listed, the low side reversed (outward on both).
        if (side)
          m.addTriangle(t[0], t[1], t[2], patch);
        else
          m.addTriangle(t[0], t[2], t[1], patch);
      }
    }
  }
}

// The box: six faces of about h spacing, their shared edge points merged.
void boxEnclosure(SurfaceMesh& m, const EnclosureOptions& o, double h, int32_t patch)
{
  int64_t n[3];
  for (int k = 0; k < 3; ++k)
  {
    n[k] = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(o.dimensions[k] / h)));
  }
  for (int k = 0; k < 3; ++k)
  {
    for (int side = 0; side < 2; ++side)
    {
      boxFace(m, o, n, k, side, patch);
    }
  }
  mergeCoincidentPoints(m);
}

// A sphere or an axis-aligned ellipsoid: a subdivided icosahedron scaled to the radii.
void ellipsoidEnclosure(SurfaceMesh& m, const EnclosureOptions& o, double h, int32_t patch)
{
  const double* c = o.center;
  const double* d = o.dimensions;
  const double r = o.shape == EnclosureShape::Sphere ? d[0] : std::max({ d[0], d[1], d[2] });
  // Icosahedron edge = 1.0515 R; a frequency-n subdivision has edges of about that / n.
  const int64_t freq = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(1.0515 * r / h)));
  icosphere(m, freq, patch);
  for (int32_t i = 0; i < m.numberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double s = o.shape == EnclosureShape::Sphere ? d[0] : d[k];
      m.points[3 * size_t(i) + k] = c[k] + s * m.points[3 * size_t(i) + k];
    }
  }
}

// A cylinder along o.axis: rings zipped into the side, closed by two disks.
void cylinderEnclosure(SurfaceMesh& m, const EnclosureOptions& o, double h, int32_t patch)
{
  const double* c = o.center;
  const double* d = o.dimensions;
  const Frame f{ { c[0], c[1], c[2] }, o.axis };
  const double r = d[0], height = d[1];
  const int64_t nt = std::max<int64_t>(6, static_cast<int64_t>(std::ceil(2.0 * kPi * r / h)));
  const int64_t nz = std::max<int64_t>(1, static_cast<int64_t>(std::ceil(height / h)));
  std::vector<std::vector<int32_t>> rings;
  for (int64_t k = 0; k <= nz; ++k)
  {
    const double z = k == nz ? 0.5 * height : -0.5 * height + height * static_cast<double>(k) / static_cast<double>(nz);
    rings.push_back(ring(m, f, r, z, nt));
  }
  for (int64_t k = 0; k < nz; ++k)
  {
    zipRings(m, rings[k], rings[k + 1], false, patch);
  }
  disk(m, f, rings[nz], r, 0.5 * height, h, false, patch);
  disk(m, f, rings[0], r, -0.5 * height, h, true, patch);
}

// A hemisphere on o.axis (dome on + or -, domeNegative): shrinking rings up to the pole, closed by the
// equator disk.
void hemisphereEnclosure(SurfaceMesh& m, const EnclosureOptions& o, double h, int32_t patch)
{
  const double* c = o.center;
  const double* d = o.dimensions;
  const Frame f{ { c[0], c[1], c[2] }, o.axis };
  const double r = d[0];
  const double s = o.domeNegative ? -1.0 : 1.0;
  const int64_t nt = std::max<int64_t>(6, static_cast<int64_t>(std::ceil(2.0 * kPi * r / h)));
  const int64_t nphi = std::max<int64_t>(2, static_cast<int64_t>(std::ceil(0.5 * kPi * r / h)));
  std::vector<int32_t> equator = ring(m, f, r, 0.0, nt);
  std::vector<int32_t> prev = equator;
  for (int64_t k = 1; k <= nphi; ++k)
  {
    const double phi = 0.5 * kPi * static_cast<double>(k) / static_cast<double>(nphi);
    const int64_t count = k == nphi ? 1 : std::max<int64_t>(6, std::llround(static_cast<double>(nt) * std::cos(phi)));
    std::vector<int32_t> cur = ring(m, f, k == nphi ? 0.0 : r * std::cos(phi), s * r * std::sin(phi), count);
    // Dome on -axis: mirrored, so the triangles flip.
    zipRings(m, prev, cur, o.domeNegative, patch);
    prev.swap(cur);
  }
  disk(m, f, equator, r, 0.0, h, !o.domeNegative, patch);
}
} // namespace

Status makeEnclosure(const EnclosureOptions& o, SurfaceMesh& m)
{
  m.clear();
  double h = 0;
  const Status s = checkEnclosure(o, h);
  if (!s.ok())
  {
    return s;
  }
  const int32_t patch = o.patchId;
  if (patch >= 0)
  {
    m.patchNames[patch] = "farfield"; // a generated enclosure is the far field of an external flow
  }
  switch (o.shape)
  {
    case EnclosureShape::Box:
      boxEnclosure(m, o, h, patch);
      break;
    case EnclosureShape::Sphere:
    case EnclosureShape::Ellipsoid:
      ellipsoidEnclosure(m, o, h, patch);
      break;
    case EnclosureShape::Cylinder:
      cylinderEnclosure(m, o, h, patch);
      break;
    case EnclosureShape::Hemisphere:
      hemisphereEnclosure(m, o, h, patch);
      break;
  }
  return Status::success();
}

} // namespace volgrid
