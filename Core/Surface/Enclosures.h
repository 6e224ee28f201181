// Triangulated closed primitives used as far-field enclosures (paper 6.2): box, sphere (icosahedron
// subdivision, no poles), cylinder with closed ends, hemisphere closed by its disk, ellipsoid. All are
// closed, manifold, consistently oriented with outward normals, with well-shaped triangles whose
// edges are close to the target length.
#pragma once

#include "Status.h"
#include "SurfaceMesh.h"

namespace volgrid
{

enum class EnclosureShape
{
  Box,
  Sphere,
  Cylinder,
  Hemisphere,
  Ellipsoid
};

struct EnclosureOptions
{
  EnclosureShape shape = EnclosureShape::Sphere;
  double center[3] = { 0, 0, 0 };
  // Box: edge lengths (x, y, z). Sphere: radius = dimensions[0]. Ellipsoid: semi-axes (x, y, z).
  // Cylinder: radius = dimensions[0], height = dimensions[1], along `axis`, centred on `center`.
  // Hemisphere: radius = dimensions[0]; its disk lies in the plane through `center` normal to `axis`,
  // the dome on the +axis side (or the -axis side with domeNegative).
  double dimensions[3] = { 1, 1, 1 };
  int axis = 2;
  bool domeNegative = false;
  double targetEdgeLength = 0; // 0: about a sixteenth of the primitive's size
  int32_t patchId = -1;        // stored on every triangle when >= 0 (and named "farfield")
};

// Options sized by a factor of a bounding box: the primitive is centred on the box and, for
// scale = 1, just encloses it (sphere radius = half diagonal, box = the box itself, ellipsoid through
// the box corners, cylinder around the box along `axis`); dimensions are multiplied by `scale`. For
// the hemisphere, the disk lies on the box's minimum face along `axis` (a half-model's symmetry
// plane) and the dome covers the box.
EnclosureOptions enclosureAround(const BoundingBox& box, EnclosureShape shape, double scale, int axis = 2);

// Builds the primitive into `out` (cleared first). Fails with InvalidOption on non-positive or
// non-finite dimensions, a bad axis, or a target edge length that would need more than ~20 M triangles.
Status makeEnclosure(const EnclosureOptions& options, SurfaceMesh& out);

// Exact volume of the ideal primitive (for tests and reports).
double enclosureExactVolume(const EnclosureOptions& options);

} // namespace volgrid
