// The marching of BoundaryLayers.h: vertex normals and the column heights that keep every prism valid
// and the last layer's surface free of intersections.
#pragma once

#include "BoundaryLayers.h"

#include <cstdint>
#include <vector>

namespace volgrid
{
namespace layers_detail
{

// The layered part of the surface, triangles oriented with their normal pointing into the domain.
struct Walls
{
  const std::vector<double>* points = nullptr; // the merged surface's points
  std::vector<int32_t> triangles;              // 3 per layered triangle, normal into the domain
  std::vector<int32_t> layeredPoints;          // surface point ids that carry a column
  std::vector<int32_t> column;                 // surface point -> index in layeredPoints, or -1
  std::vector<int32_t> otherTriangles;         // 3 per triangle of the other patches
  std::vector<int8_t> slipAxis;                // per column: the axis normal to the symmetry plane it marches in, or -1
  std::vector<uint8_t> collapsed;              // per column: 1 when its layers collapse onto the wall point
};

// Unit marching direction per column (3 each): angle-weighted face normals, smoothed `passes` times,
// then tilted towards the face it is most oblique to until every incident face sees it.
std::vector<double> marchingDirections(const Walls& walls, int passes);

// Offsets of the tops of the layers from the wall for a full column: first * (1 + r + ... + r^k).
std::vector<double> layerOffsets(const LayerOptions& options);

// Points of the layers: column c's layer k at layeredBase + c * layers + k.
void placeLayerPoints(const Walls& walls, const std::vector<double>& directions, const std::vector<double>& offsets,
                      const std::vector<double>& scale, std::vector<double>& points);

// Point id of column c's layer k (k = -1: the wall point; a collapsed column: the wall point at every k).
int32_t layerPoint(const Walls& walls, int32_t surfacePoint, int k, int layers);

// Columns (by index, never collapsed ones) of the layer cells that are not valid (layerCellIsValid).
std::vector<int32_t> invertedColumns(const Walls& walls, const std::vector<double>& points, int layers);

// The other patches' triangles with their layered points replaced by the last layer's (symmetry planes).
std::vector<int32_t> movedOtherTriangles(const Walls& walls, int layers);

// Columns whose last-layer triangles cross each other, a wall or another triangle, and columns on a
// symmetry plane whose moved plane triangles flip or cross (exact).
std::vector<int32_t> collidingColumns(const Walls& walls, const std::vector<double>& points, int layers,
                                      int threads = 0);

// Neighbouring columns, per column (CSR: start, list).
void columnNeighbours(const Walls& walls, std::vector<int32_t>& start, std::vector<int32_t>& list);

} // namespace layers_detail
} // namespace volgrid
