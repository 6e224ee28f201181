// Icospheres and boxes with named patches for the boundary-layer tests (header-only, test code).
#pragma once

#include "MesherTestShapes.h"
#include "SurfaceMesh.h"


namespace volgrid
{
namespace layertest
{

// Icosphere of `subdivisions` levels (MesherTestShapes.h's), radius r, centre c, outward, every triangle on
// `patch`.
inline void addIcosphere(SurfaceMesh& s, const double c[3], double r, int subdivisions, int32_t patch)
{
  const size_t first = static_cast<size_t>(s.numberOfTriangles());
  testshapes::addSphere(s, c, r, subdivisions);
  s.patchIds.resize(first, -1); // earlier triangles without a patch keep none
  s.patchIds.resize(static_cast<size_t>(s.numberOfTriangles()), patch);
}

// A unit body sphere (patch 1 "wall") inside a far-field sphere of radius 10 (patch 2 "farfield").
inline SurfaceMesh sphereInSphere(int bodySubdivisions = 3)
{
  SurfaceMesh s;
  const double o[3] = { 0, 0, 0 };
  addIcosphere(s, o, 1.0, bodySubdivisions, 1);
  addIcosphere(s, o, 10.0, 1, 2);
  s.patchNames[1] = "wall";
  s.patchNames[2] = "farfield";
  return s;
}

} // namespace layertest
} // namespace volgrid
