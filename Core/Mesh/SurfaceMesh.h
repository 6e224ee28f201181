// A triangle surface as flat arrays: the common currency of the readers, the defect checks, the repair
// and the enclosures. Points are double xyz, triangles are three int32 point ids, and an optional
// per-triangle patch id (CAD face, STL solid, Medit/TetGen/gmsh reference) rides along.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace volgrid
{

struct SurfaceMesh
{
  std::vector<double> points;                // 3 * numberOfPoints()
  std::vector<int32_t> triangles;            // 3 * numberOfTriangles()
  std::vector<int32_t> patchIds;             // empty, or one per triangle
  std::map<int32_t, std::string> patchNames; // patch id -> name (STL solid, gmsh physical name, ...)

  int32_t numberOfPoints() const { return static_cast<int32_t>(points.size() / 3); }
  int32_t numberOfTriangles() const { return static_cast<int32_t>(triangles.size() / 3); }
  bool hasPatchIds() const { return !patchIds.empty(); }
  const double* point(int32_t i) const { return points.data() + 3 * static_cast<size_t>(i); }
  const int32_t* triangle(int32_t t) const { return triangles.data() + 3 * static_cast<size_t>(t); }

  int32_t addPoint(double x, double y, double z);
  // patch is stored only when the mesh has patch ids, or when patch != -1 (then earlier triangles get -1).
  int32_t addTriangle(int32_t a, int32_t b, int32_t c, int32_t patch = -1);
  // Appends another mesh (point ids shifted). Patch ids are kept when either has them; names of ids
  // this mesh does not name yet are taken from `other`.
  void append(const SurfaceMesh& other);
  void clear();
};

struct BoundingBox
{
  double min[3] = { 0, 0, 0 };
  double max[3] = { 0, 0, 0 };
  bool valid = false;
  double diagonal() const;
  void add(const double* p);
};

// Box of the points referenced by triangles (all points when referencedOnly is false).
BoundingBox boundingBox(const SurfaceMesh& mesh, bool referencedOnly = false);

// Signed volume enclosed by the triangles (positive when a closed surface is oriented outward). Computed
// about the bounding-box centre in double precision with compensated summation. The optional
// triangle list restricts the sum to those triangles (e.g. one shell).
double signedVolume(const SurfaceMesh& mesh);
double signedVolume(const SurfaceMesh& mesh, const std::vector<int32_t>& triangleIds);

// True when every coordinate is finite. firstBad receives the first offending point id.
bool allPointsFinite(const SurfaceMesh& mesh, int32_t* firstBad = nullptr);

// Map from each point to the first point (smallest id) with exactly the same coordinates, renumbered
// densely in order of first occurrence: oldToNew[i] is i's id after merging. The relative order of
// the surviving points is preserved, so a mesh without duplicates keeps its numbering. -0.0 == 0.0.
// Returns the number of merged (removed) points.
int64_t exactCoincidenceMap(const std::vector<double>& points, std::vector<int32_t>& oldToNew);

struct MergeResult
{
  int64_t mergedPoints = 0;      // points removed because an earlier point had the same coordinates
  std::vector<int32_t> oldToNew; // old point id -> new point id
};

// Merges exactly coincident points in place and renumbers triangles. Triangles are not removed (a
// triangle may become degenerate; the checks report it).
MergeResult mergeCoincidentPoints(SurfaceMesh& mesh);

// Applies a point map (old -> new, new ids dense, -1 = dropped) to the points and triangles.
// The new position of a point is that of the first old point mapped to it.
void remapPoints(SurfaceMesh& mesh, const std::vector<int32_t>& oldToNew, int32_t newCount);

// Removes points no triangle references; returns how many were removed. oldToNew (optional) gets -1
// for removed points.
int64_t removeUnreferencedPoints(SurfaceMesh& mesh, std::vector<int32_t>* oldToNew = nullptr);

} // namespace volgrid
