// Defect diagnosis of a triangle surface with exact predicates: the checks the mesher runs to reject
// bad input (surfaceStatus) and that Surface Prep shows as diagnostic arrays.
//
// Topology (edges, shells, orientation) is taken from the point ids as given: run
// mergeCoincidentPoints first when coincident points should be joined (the mesher does). Geometry
// (self-intersections, nesting) treats exactly coincident points as the same vertex, so two triangles
// that touch only at a duplicated point do not count as intersecting.
#pragma once

#include "Progress.h"
#include "Status.h"
#include "SurfaceMesh.h"
#include "TriangleIntersection.h"

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

// Bits of SurfaceCheckReport::triangleFlags.
enum SurfaceTriangleFlag : uint8_t
{
  TriangleDegenerate = 1,         // zero area: repeated point or exactly collinear corners
  TriangleDuplicate = 2,          // same three point ids as an earlier triangle
  TriangleSelfIntersecting = 4,   // crosses/overlaps a triangle of its own shell
  TriangleBoundaryEdge = 8,       // has an edge used by no other triangle
  TriangleNonManifoldEdge = 16,   // has an edge used by more than two triangles
  TriangleInconsistent = 32,      // has an edge its neighbour traverses in the same direction
  TriangleNonManifoldVertex = 64, // has a non-manifold corner
  TriangleShellIntersecting = 128 // crosses/overlaps a triangle of another shell
};

// Bits of SurfaceCheckReport::edgeFlags.
enum SurfaceEdgeFlag : uint8_t
{
  EdgeBoundary = 1,    // used by one triangle
  EdgeNonManifold = 2, // used by more than two triangles
  EdgeInconsistent = 4 // used by two triangles in the same direction
};

struct SurfaceCheckOptions
{
  bool selfIntersections = true; // exact pairwise intersection test (BVH candidates)
  bool nesting = true;           // which closed shell contains which (exact ray parity)
  int maxReportedIds = 8;        // how many first ids each defect class keeps
  int threads = 0;               // worker threads for the intersection test; 0 = up to 2
  Progress* progress = nullptr;
};

struct SurfaceShell
{
  int32_t triangles = 0;
  int32_t firstTriangle = -1;
  bool closed = false;     // every edge of the shell is used by exactly two triangles
  bool consistent = true;  // every such edge is traversed in opposite directions
  double signedVolume = 0; // > 0: outward (meaningful for closed, consistent shells)
  int depth = 0;           // number of closed shells that contain this one
  int32_t parent = -1;     // innermost closed shell containing this one
  bool intersectsOtherShell = false;
  double bounds[6] = { 0, 0, 0, 0, 0, 0 }; // xmin xmax ymin ymax zmin zmax
};

struct SurfaceCheckReport
{
  int32_t points = 0;
  int32_t triangles = 0;
  int64_t edges = 0;

  int64_t invalidTriangles = 0; // point id out of range (excluded from every other check)
  int64_t nonFinitePoints = 0;  // NaN/Inf coordinates among referenced points
  int64_t unreferencedPoints = 0;
  int64_t coincidentPoints = 0; // referenced points whose coordinates equal an earlier point's
  int64_t boundaryEdges = 0;
  int64_t boundaryLoops = 0; // connected groups of boundary edges
  int64_t nonManifoldEdges = 0;
  int64_t inconsistentEdges = 0;
  int64_t nonManifoldVertices = 0;
  int64_t degenerateTriangles = 0;
  int64_t duplicateTriangles = 0;     // triangles repeating an earlier triangle's point set
  int64_t selfIntersectingPairs = 0;  // pairs within one shell
  int64_t shellIntersectingPairs = 0; // pairs from two different shells
  bool intersectionsChecked = false;
  bool nestingChecked = false;

  std::vector<SurfaceShell> shells;
  std::vector<int32_t> triangleShell;    // shell of each triangle (-1: invalid ids or a repeated point id)
  std::vector<uint8_t> triangleFlags;    // SurfaceTriangleFlag bits per triangle
  std::vector<uint8_t> pointNonManifold; // 1 for non-manifold vertices
  std::vector<int32_t> edgePoints;       // 2 per edge (smaller id first)
  std::vector<int32_t> edgeValence;      // triangles using each edge
  std::vector<uint8_t> edgeFlags;        // SurfaceEdgeFlag bits per edge

  // First ids of each defect class (triangle ids unless stated).
  std::vector<int32_t> firstBoundaryEdgeTriangles;
  std::vector<int32_t> firstBoundaryEdges; // edge ids (index into edgePoints/2)
  std::vector<int32_t> firstNonManifoldEdgeTriangles;
  std::vector<int32_t> firstNonManifoldEdges; // edge ids
  std::vector<int32_t> firstInconsistentTriangles;
  std::vector<int32_t> firstNonManifoldVertices; // point ids
  std::vector<int32_t> firstDegenerateTriangles;
  std::vector<int32_t> firstDuplicateTriangles;
  std::vector<int32_t> firstSelfIntersectingPairs;  // flattened pairs (t1, t2)
  std::vector<int32_t> firstShellIntersectingPairs; // flattened pairs (t1, t2)
  std::vector<int32_t> firstInvalidTriangles;

  bool watertight() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
  bool consistentlyOriented() const { return inconsistentEdges == 0; }
  int inwardShells() const; // closed consistent shells with negative volume
  // No defect the mesher rejects (orientation and non-manifold vertices are allowed).
  bool meshable() const;
};

SurfaceCheckReport checkSurface(const SurfaceMesh& mesh, const SurfaceCheckOptions& options = SurfaceCheckOptions());

// The first defect class the mesher rejects, with its count and first ids, or success. Order:
// invalid ids, non-finite points, degenerate, duplicate, non-manifold edges, open surface,
// self-intersection, intersecting shells. Also a failure when `report` is empty (EmptyInput).
Status surfaceStatus(const SurfaceCheckReport& report);

// A multi-line human-readable summary (the CLI's `volgrid check` text and the filter's log).
std::string formatSurfaceReport(const SurfaceCheckReport& report);

// ----- exact building blocks (also used by SurfaceRepair and the tests) -----

// Position of point x relative to the closed surface made of `triangleIds` of `mesh` (exact ray parity;
// rays that hit an edge, a vertex or lie in a triangle's plane are retried in another direction):
// +1 inside, -1 outside, 0 on the surface.
int pointInClosedSurface(const SurfaceMesh& mesh, const std::vector<int32_t>& triangleIds, const double* x);

} // namespace volgrid
