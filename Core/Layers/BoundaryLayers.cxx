// Boundary layers: option checks, the choice of the layered patches, the thinning rounds and the output.
#include "BoundaryLayers.h"

#include "BoundaryLayersMarching.h"
#include "MeshWriter.h"
#include "PatchNames.h"
#include "Predicates.h"
#include "SurfaceChecks.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace volgrid
{
namespace
{
std::string pointText(const double* p)
{
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p[0], p[1], p[2]);
  return text;
}

// Patch label of each triangle: its patch id, or its shell index when the surface has none.
int32_t trianglePatch(const SurfaceMesh& s, const SurfaceCheckReport& report, int32_t t)
{
  return s.hasPatchIds() ? s.patchIds[t] : report.triangleShell[t];
}

std::string patchName(const SurfaceMesh& s, int32_t patch)
{
  const auto it = s.patchNames.find(patch);
  return it != s.patchNames.end() ? it->second : (s.hasPatchIds() ? "patch" : "shell") + std::to_string(patch);
}

// The default layered patches. A named patch is a wall unless its name says otherwise (OpenFOAM's rule:
// symmetry, farfield, inlet, outlet). An unnamed one (a Medit reference, an unnamed shell) is judged by
// geometry: not a wall when it is on a shell around another shell (a far field around a body), or when it
// reaches both ends of the whole surface's box along some axis (a far-field sphere, a symmetry plane
// through the domain, a box side). A body, also one touching a symmetry plane, reaches neither.
std::set<int32_t> defaultWalls(const SurfaceMesh& s, const SurfaceCheckReport& report, const std::set<int32_t>& present)
{
  std::vector<bool> enclosesAnother(report.shells.size(), false);
  for (const SurfaceShell& shell : report.shells)
    if (shell.parent >= 0)
      enclosesAnother[shell.parent] = true;
  BoundingBox all;
  std::map<int32_t, BoundingBox> box;
  std::set<int32_t> aroundAnother;
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
  {
    const int32_t patch = trianglePatch(s, report, t), shell = report.triangleShell[t];
    for (int i = 0; i < 3; ++i)
    {
      all.add(s.point(s.triangles[3 * t + i]));
      box[patch].add(s.point(s.triangles[3 * t + i]));
    }
    if (shell >= 0 && enclosesAnother[shell])
      aroundAnother.insert(patch);
  }
  const auto spansTheDomain = [&](const BoundingBox& own)
  {
    for (int d = 0; d < 3; ++d)
      if (own.min[d] == all.min[d] && own.max[d] == all.max[d] && all.max[d] > all.min[d])
        return true;
    return false;
  };
  std::set<int32_t> walls;
  for (const int32_t patch : present)
  {
    const bool named = s.hasPatchIds() && s.patchNames.count(patch);
    if (named ? defaultOpenFoamPatchType(s.patchNames.at(patch)) == "wall"
              : present.size() == 1 || (!aroundAnother.count(patch) && !spansTheDomain(box[patch])))
      walls.insert(patch);
  }
  return walls;
}

// The set of layered patch labels, or a Status naming what was asked for and not found.
Status choosePatches(const SurfaceMesh& s, const SurfaceCheckReport& report, const LayerOptions& options,
                     std::set<int32_t>& chosen)
{
  std::set<int32_t> present;
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
    present.insert(trianglePatch(s, report, t));
  std::string available;
  for (const int32_t p : present)
    available += (available.empty() ? "" : ", ") + patchName(s, p) + " (" + std::to_string(p) + ")";
  for (const int32_t id : options.patchIds)
  {
    if (!present.count(id))
      return Status::failure(ErrorKind::InvalidOption,
                             "layer patch id " + std::to_string(id) +
                               " is not a patch of the surface; patches: " + available);
    chosen.insert(id);
  }
  for (const std::string& name : options.patchNames)
  {
    bool found = false;
    for (const int32_t p : present)
      if (patchName(s, p) == name)
        chosen.insert(p), found = true;
    if (!found)
      return Status::failure(ErrorKind::InvalidOption,
                             "layer patch '" + name + "' is not a patch of the surface; patches: " + available);
  }
  if (options.patchIds.empty() && options.patchNames.empty())
    chosen = defaultWalls(s, report, present);
  if (chosen.empty())
    return Status::failure(ErrorKind::InvalidOption,
                           "no wall patch to grow layers from (the far field, symmetry planes and the domain's outer "
                           "box get none); name the patches with --layer-patches / LayerPatches; patches: " +
                             available);
  return Status::success();
}

// Layered points shared with non-layered patches march in those patches' planes: each such patch must be
// flat across one coordinate axis (its extent there at most 1e-9 of its size: a symmetry plane), and each
// shared point on one patch only. Else a Status naming the patch and the first point.
Status slipPlanes(const SurfaceMesh& s, const SurfaceCheckReport& report, layers_detail::Walls& walls,
                  const std::vector<int32_t>& otherIds)
{
  walls.slipAxis.assign(walls.layeredPoints.size(), -1);
  std::map<int32_t, int> axisOf; // touched patch -> its flat axis (-1: not flat)
  std::vector<int32_t> patchAt(walls.layeredPoints.size(), -1);
  for (size_t k = 0; k < otherIds.size(); ++k)
    for (int i = 0; i < 3; ++i)
    {
      const int32_t v = walls.otherTriangles[3 * k + i], c = walls.column[v];
      if (c < 0)
        continue;
      const int32_t patch = trianglePatch(s, report, otherIds[k]);
      const auto refuse = [&](const std::string& why)
      {
        return Status::failure(ErrorKind::InvalidOption,
                               "boundary layers touch the non-layered patch '" + patchName(s, patch) + "' at point " +
                                 std::to_string(v) + " " + pointText(s.point(v)) + ": " + why +
                                 "; layer whole closed bodies, or add that patch to the layer patches",
                               { v });
      };
      if (patchAt[c] >= 0 && patchAt[c] != patch)
        return refuse("the point is also on patch '" + patchName(s, patchAt[c]) +
                      "' (layers along two non-layered patches are not supported yet)");
      patchAt[c] = patch;
      if (!axisOf.count(patch))
      {
        BoundingBox box;
        for (size_t j = 0; j < otherIds.size(); ++j)
          if (trianglePatch(s, report, otherIds[j]) == patch)
            for (int q = 0; q < 3; ++q)
              box.add(s.point(walls.otherTriangles[3 * j + q]));
        int axis = 0;
        for (int d = 1; d < 3; ++d)
          if (box.max[d] - box.min[d] < box.max[axis] - box.min[axis])
            axis = d;
        axisOf[patch] = box.max[axis] - box.min[axis] <= 1e-9 * box.diagonal() ? axis : -1;
      }
      if (axisOf[patch] < 0)
        return refuse("layers march only along a flat patch normal to a coordinate axis (a symmetry plane)");
      walls.slipAxis[c] = static_cast<int8_t>(axisOf[patch]);
    }
  return Status::success();
}

// Splits the triangles into layered walls (oriented into the domain) and the others; refuses walls that
// share a point with a non-layered patch that is not a flat symmetry plane (slipPlanes).
Status buildWalls(const SurfaceMesh& s, const SurfaceCheckReport& report, const std::set<int32_t>& chosen,
                  layers_detail::Walls& walls, std::vector<int32_t>& wallIds, std::vector<int32_t>& otherIds)
{
  walls.points = &s.points;
  walls.column.assign(s.numberOfPoints(), -1);
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
  {
    const int32_t* v = s.triangle(t);
    if (!chosen.count(trianglePatch(s, report, t)))
    {
      walls.otherTriangles.insert(walls.otherTriangles.end(), v, v + 3);
      otherIds.push_back(t);
      continue;
    }
    const SurfaceShell& shell = report.shells[report.triangleShell[t]];
    // Even-odd: the outside of a shell is domain when an odd number of shells enclose it.
    const bool flip = (shell.signedVolume > 0) != (shell.depth % 2 == 1);
    walls.triangles.insert(walls.triangles.end(), { v[0], flip ? v[2] : v[1], flip ? v[1] : v[2] });
    wallIds.push_back(t);
    for (int i = 0; i < 3; ++i)
      if (walls.column[v[i]] < 0)
      {
        walls.column[v[i]] = static_cast<int32_t>(walls.layeredPoints.size());
        walls.layeredPoints.push_back(v[i]);
      }
  }
  return slipPlanes(s, report, walls, otherIds);
}

// Checks `s`, chooses its layered patches and builds their walls; unless the options keep the wall's
// triangles, first splits them around the edges checkMesh would find skewed (WallRefinement.h).
Status layeredWalls(SurfaceMesh& s, const LayerOptions& options, SurfaceCheckReport& checks,
                    layers_detail::Walls& walls, std::vector<int32_t>& wallIds, std::vector<int32_t>& otherIds,
                    WallRefinement& refinement)
{
  SurfaceMesh input;
  for (bool refine = !options.keepWallTriangles;; refine = false)
  {
    checks = checkSurface(s);
    Status status = surfaceStatus(checks);
    std::set<int32_t> chosen;
    if (status.ok())
      status = choosePatches(s, checks, options, chosen);
    walls = layers_detail::Walls();
    wallIds.clear();
    otherIds.clear();
    if (status.ok())
      status = buildWalls(s, checks, chosen, walls, wallIds, otherIds);
    if (!status.ok() && refinement.splitEdges > 0)
    {
      // The split surface fails where the input passed (a new point within rounding of another part):
      // the input's triangles then, with the warning about their skewed edges.
      s = std::move(input);
      refinement = WallRefinement();
      continue;
    }
    if (!status.ok() || !refine || skewedWallEdges(s.points, walls.triangles).empty())
      return status;
    std::vector<uint8_t> isWall(s.numberOfTriangles(), 0);
    for (const int32_t t : wallIds)
      isWall[t] = 1;
    input = s;
    refinement = refineSkewedWall(s, isWall);
  }
}

// Halves the failing columns, then limits every column to 1.5 times its thinnest neighbour.
// A column thinned below this fraction of its height collapses instead (ThinnedReason::Collapsed).
constexpr double kCollapseBelow = 1.0 / 8;

// Halves the bad columns (collapsing those that fall below kCollapseBelow, except on symmetry planes),
// then limits every column to 1.5x its thinnest non-collapsed neighbour.
void thin(const std::vector<int32_t>& bad, ThinnedReason why, const std::vector<int32_t>& start,
          const std::vector<int32_t>& list, layers_detail::Walls& walls, std::vector<double>& scale,
          std::vector<uint8_t>& reason)
{
  for (const int32_t c : bad)
  {
    scale[c] *= 0.5;
    if (reason[c] == uint8_t(ThinnedReason::None) || reason[c] == uint8_t(ThinnedReason::Neighbour))
      reason[c] = uint8_t(why);
    if (scale[c] < kCollapseBelow && walls.slipAxis[c] < 0)
    {
      scale[c] = 0;
      reason[c] = uint8_t(ThinnedReason::Collapsed);
      walls.collapsed[c] = 1;
    }
  }
  for (bool changed = true; changed;)
  {
    changed = false;
    for (size_t c = 0; c + 1 < start.size(); ++c)
      for (int32_t k = start[c]; k < start[c + 1] && !walls.collapsed[c]; ++k)
        if (scale[list[k]] > 1.5 * scale[c])
        {
          scale[list[k]] = 1.5 * scale[c];
          if (reason[list[k]] == uint8_t(ThinnedReason::None))
            reason[list[k]] = uint8_t(ThinnedReason::Neighbour);
          changed = true;
        }
  }
}
} // namespace

double LayerOptions::totalThickness() const
{
  const std::vector<double> offsets = layers_detail::layerOffsets(*this);
  return offsets.empty() ? 0.0 : offsets.back();
}

const char* thinnedReasonName(ThinnedReason reason)
{
  switch (reason)
  {
    case ThinnedReason::Inversion:
      return "inversion";
    case ThinnedReason::Collision:
      return "collision";
    case ThinnedReason::Neighbour:
      return "neighbour";
    case ThinnedReason::Collapsed:
      return "collapsed";
    default:
      return "none";
  }
}

double firstHeightForYPlus(double yPlus, double reynolds, double length)
{
  if (!(yPlus > 0) || !(reynolds > 0) || !(length > 0))
    return 0;
  const double cf = 0.026 / std::pow(reynolds, 1.0 / 7.0);
  return yPlus * length / (reynolds * std::sqrt(cf / 2));
}

namespace
{
// first * (1 + r + ... + r^(n-1)).
double stackThickness(double first, double ratio, int n)
{
  return ratio == 1 ? first * n : first * (std::pow(ratio, n) - 1) / (ratio - 1);
}

// The ratio in [1, 10] that stacks n layers from `first` to `total` (bisection: the thickness grows with
// the ratio), or 0 when none does.
double growthForThickness(double first, double total, int n)
{
  if (!(first > 0) || !(total > 0) || n < 1 || total < stackThickness(first, 1, n) * (1 - 1e-12) ||
      total > stackThickness(first, 10, n))
    return 0;
  double lo = 1, hi = 10;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (stackThickness(first, mid, n) < total ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
} // namespace

LayerOptions LayerOptions::resolved() const
{
  LayerOptions o = *this;
  if (o.yPlus > 0 && o.firstHeight == 0)
    o.firstHeight = firstHeightForYPlus(o.yPlus, o.reynolds, o.referenceLength);
  if (o.thickness > 0 && o.layers > 0)
  {
    if (o.firstHeight > 0)
      o.growth = growthForThickness(o.firstHeight, o.thickness, o.layers);
    else if (o.growth >= 1)
      o.firstHeight = o.thickness / stackThickness(1, o.growth, o.layers);
  }
  return o;
}

void addLayerPatches(const std::string& list, LayerOptions& options)
{
  std::stringstream entries(list);
  for (std::string name; std::getline(entries, name, ',');)
    if (!name.empty() && name.find_first_not_of("0123456789") == std::string::npos && name.size() < 10)
      options.patchIds.push_back(std::stoi(name));
    else if (!name.empty())
      options.patchNames.push_back(name);
}

Status validateLayerOptions(const LayerOptions& given)
{
  if (given.yPlus != 0 && given.firstHeight != 0)
    return Status::failure(ErrorKind::InvalidOption, "give the first layer height or a y+, not both");
  if (given.yPlus != 0 && !(given.yPlus > 0 && given.reynolds > 0 && given.referenceLength > 0))
    return Status::failure(ErrorKind::InvalidOption, "a y+ needs a positive y+, Reynolds number and reference length");
  if (!(given.thickness >= 0) || !std::isfinite(given.thickness))
    return Status::failure(ErrorKind::InvalidOption,
                           "the total layer thickness must be positive and finite, not " +
                             std::to_string(given.thickness));
  const LayerOptions o = given.resolved();
  if (given.thickness > 0 && given.layers >= 1 && o.firstHeight > 0 && o.growth == 0)
    return Status::failure(ErrorKind::InvalidOption,
                           "no growth ratio in 1..10 stacks " + std::to_string(given.layers) +
                             " layers from the first height " + std::to_string(o.firstHeight) +
                             " to the total thickness " + std::to_string(given.thickness) +
                             " (at least layers x first height)");
  if (o.layers < 1 || o.layers > 1000)
    return Status::failure(ErrorKind::InvalidOption,
                           "the number of layers must be 1..1000, not " + std::to_string(o.layers));
  if (!(o.firstHeight > 0) || !std::isfinite(o.firstHeight))
    return Status::failure(ErrorKind::InvalidOption,
                           "the first layer height must be positive and finite, not " + std::to_string(o.firstHeight));
  if (!(o.growth >= 1) || !std::isfinite(o.growth) || o.growth > 10)
    return Status::failure(ErrorKind::InvalidOption,
                           "the layer growth ratio must be in 1..10, not " + std::to_string(o.growth));
  if (!std::isfinite(o.totalThickness()))
    return Status::failure(ErrorKind::InvalidOption, "the total layer thickness overflows");
  return Status::success();
}

namespace
{
// The cell of layer k over wall triangle v: a prism, or with collapsed corners a pyramid (apex: the one
// collapsed point) or a tet (two), or nothing (three). Pyramids and tets are oriented positive.
void addLayerCell(const layers_detail::Walls& walls, const int32_t* v, int k, int layers, int32_t triangle, uint8_t why,
                  LayerResult& r)
{
  int32_t q[6];
  int collapsed = 0, flat = -1, standing = -1;
  for (int i = 0; i < 3; ++i)
  {
    q[i] = layers_detail::layerPoint(walls, v[i], k - 1, layers);
    q[i + 3] = layers_detail::layerPoint(walls, v[i], k, layers);
    (q[i] == q[i + 3] ? flat : standing) = i;
    collapsed += q[i] == q[i + 3];
  }
  const auto at = [&](int32_t id) { return r.points.data() + 3 * size_t(id); };
  if (collapsed == 0)
  {
    r.prisms.insert(r.prisms.end(), q, q + 6);
    r.prismLayer.push_back(k);
    r.prismTriangle.push_back(triangle);
    r.prismReason.push_back(why);
  }
  else if (collapsed == 1)
  {
    const int b = (flat + 1) % 3, c = (flat + 2) % 3;
    int32_t p[5] = { q[b], q[c], q[c + 3], q[b + 3], q[flat] };
    if (predicates::orient3d(at(p[0]), at(p[1]), at(p[2]), at(p[4])) < 0)
      std::swap(p[1], p[3]);
    r.pyramids.insert(r.pyramids.end(), p, p + 5);
    r.pyramidLayer.push_back(k);
    r.pyramidReason.push_back(why);
  }
  else if (collapsed == 2)
  {
    const int a = (standing + 1) % 3, b = (standing + 2) % 3;
    int32_t t[4] = { q[a], q[b], q[standing], q[standing + 3] };
    if (predicates::orient3d(at(t[0]), at(t[1]), at(t[2]), at(t[3])) < 0)
      std::swap(t[0], t[1]);
    r.tets.insert(r.tets.end(), t, t + 4);
    r.tetLayer.push_back(k);
    r.tetReason.push_back(why);
  }
}

// Drops the points of collapsed columns (no cell uses them) and renumbers every list of point ids.
void dropCollapsedPoints(const layers_detail::Walls& walls, int layers, LayerResult& r)
{
  const size_t base = walls.points->size() / 3;
  std::vector<int32_t> newId(r.points.size() / 3);
  int32_t next = 0;
  for (size_t p = 0; p < newId.size(); ++p)
  {
    const bool dropped = p >= base && walls.collapsed[(p - base) / size_t(layers)];
    newId[p] = dropped ? -1 : next;
    if (!dropped)
    {
      std::copy(r.points.begin() + 3 * p, r.points.begin() + 3 * p + 3, r.points.begin() + 3 * size_t(next));
      ++next;
    }
  }
  r.points.resize(3 * size_t(next));
  for (std::vector<int32_t>* ids : { &r.prisms, &r.pyramids, &r.tets, &r.sideQuads, &r.tetBoundaryPoint })
    for (int32_t& id : *ids)
      id = newId[id];
}

// Prisms, wall triangles and the tet region's boundary from the accepted columns.
void assemble(const SurfaceMesh& s, const SurfaceCheckReport& report, const layers_detail::Walls& walls,
              const std::vector<int32_t>& wallIds, const std::vector<int32_t>& otherIds, int layers,
              const std::vector<double>& scale, const std::vector<uint8_t>& reason, LayerResult& r)
{
  const int32_t base = s.numberOfPoints();
  const auto layerPoint = [&](int32_t v, int k) { return layers_detail::layerPoint(walls, v, k, layers); };
  r.numSurfacePoints = base;
  r.pointScale.assign(base, 0.0);
  r.pointReason.assign(base, 0);
  for (size_t c = 0; c < walls.layeredPoints.size(); ++c)
  {
    r.pointScale[walls.layeredPoints[c]] = scale[c];
    r.pointReason[walls.layeredPoints[c]] = reason[c];
  }
  int32_t maxPatch = -1;
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
    maxPatch = std::max(maxPatch, trianglePatch(s, report, t));
  r.interfacePatch = maxPatch + 1;
  SurfaceMesh& b = r.tetBoundary;
  b.patchNames = s.patchNames;
  b.patchNames[r.interfacePatch] = "layer_interface";
  std::vector<int32_t> local(r.points.size() / 3, -1);
  const auto localPoint = [&](int32_t id)
  {
    if (local[id] < 0)
    {
      local[id] = b.addPoint(r.points[3 * size_t(id)], r.points[3 * size_t(id) + 1], r.points[3 * size_t(id) + 2]);
      r.tetBoundaryPoint.push_back(id);
    }
    return local[id];
  };
  for (size_t w = 0; w < wallIds.size(); ++w)
  {
    const int32_t* v = walls.triangles.data() + 3 * w;
    uint8_t why = 0; // the column's own failure first, else Neighbour
    for (int i = 0; i < 3; ++i)
    {
      const uint8_t own = reason[walls.column[v[i]]];
      if (own != 0 && (why == 0 || why == uint8_t(ThinnedReason::Neighbour)))
        why = own;
    }
    for (int k = 0; k < layers; ++k)
      addLayerCell(walls, v, k, layers, wallIds[w], why, r);
    const int32_t* input = s.triangle(wallIds[w]);
    r.wallTriangles.insert(r.wallTriangles.end(), input, input + 3);
    r.wallPatch.push_back(trianglePatch(s, report, wallIds[w]));
    b.addTriangle(localPoint(layerPoint(v[0], layers - 1)), localPoint(layerPoint(v[1], layers - 1)),
                  localPoint(layerPoint(v[2], layers - 1)), r.interfacePatch);
    const bool full =
      scale[walls.column[v[0]]] == 1 && scale[walls.column[v[1]]] == 1 && scale[walls.column[v[2]]] == 1;
    r.stats.fullTriangles += full ? 1 : 0;
    const auto isCollapsed = [&](int i) { return walls.collapsed[walls.column[v[i]]] != 0; };
    r.stats.collapsedTriangles += isCollapsed(0) || isCollapsed(1) || isCollapsed(2) ? 1 : 0;
  }
  // The other patches, their layered corners moved to the last layer (symmetry planes), and the prisms'
  // side faces on those planes.
  const std::vector<int32_t> moved = layers_detail::movedOtherTriangles(walls, layers);
  std::map<std::pair<int32_t, int32_t>, int32_t> planeEdges;
  for (size_t k = 0; k < otherIds.size(); ++k)
  {
    const int32_t* v = moved.data() + 3 * k;
    const int32_t patch = trianglePatch(s, report, otherIds[k]);
    b.addTriangle(localPoint(v[0]), localPoint(v[1]), localPoint(v[2]), patch);
    for (int i = 0; i < 3; ++i)
    {
      const int32_t p = walls.otherTriangles[3 * k + i], q = walls.otherTriangles[3 * k + (i + 1) % 3];
      if (walls.column[p] >= 0 && walls.column[q] >= 0)
        planeEdges[{ std::min(p, q), std::max(p, q) }] = patch;
    }
  }
  for (size_t t = 0; t < walls.triangles.size(); t += 3)
    for (int i = 0; i < 3; ++i)
    {
      const int32_t p = walls.triangles[t + i], q = walls.triangles[t + (i + 1) % 3];
      const auto edge = planeEdges.find({ std::min(p, q), std::max(p, q) });
      if (edge == planeEdges.end())
        continue;
      for (int k = 0; k < layers; ++k)
      {
        r.sideQuads.insert(r.sideQuads.end(),
                           { layerPoint(p, k - 1), layerPoint(q, k - 1), layerPoint(q, k), layerPoint(p, k) });
        r.sidePatch.push_back(edge->second);
      }
    }
  r.stats.layeredTriangles = static_cast<int64_t>(wallIds.size());
  r.stats.layeredPoints = static_cast<int64_t>(walls.layeredPoints.size());
  r.stats.prisms = static_cast<int64_t>(r.prismLayer.size());
  r.stats.pyramids = static_cast<int64_t>(r.pyramidLayer.size());
  r.stats.layerTets = static_cast<int64_t>(r.tetLayer.size());
  dropCollapsedPoints(walls, layers, r);
  for (size_t c = 0; c < scale.size(); ++c)
  {
    r.stats.thinnedColumns += scale[c] < 1 ? 1 : 0;
    r.stats.thinnedBy[reason[c]] += 1;
    r.stats.minScale = std::min(r.stats.minScale, scale[c]);
  }
}
} // namespace

Status growLayers(const SurfaceMesh& input, const LayerOptions& given, LayerResult& result, Progress* progress)
{
  const auto started = std::chrono::steady_clock::now();
  result = LayerResult();
  SilentProgress silent;
  Progress& report = progress ? *progress : silent;
  Status status = validateLayerOptions(given);
  if (!status.ok())
    return status;
  const LayerOptions options = given.resolved();
  SurfaceMesh s = input;
  mergeCoincidentPoints(s); // as the mesher does: point i of the merged surface
  const BoundingBox box = boundingBox(s, true);
  const double total = options.totalThickness();
  if (box.valid && total > 0.5 * box.diagonal())
    return Status::failure(ErrorKind::InvalidOption,
                           "the total layer thickness " + std::to_string(total) +
                             " is more than the domain allows (half its bounding-box diagonal, " +
                             std::to_string(0.5 * box.diagonal()) + ")");
  report.report(0, "Boundary layers: checking the surface");
  SurfaceCheckReport checks;
  layers_detail::Walls walls;
  std::vector<int32_t> wallIds, otherIds;
  status = layeredWalls(s, options, checks, walls, wallIds, otherIds, result.stats.wallRefinement);
  if (!status.ok())
    return status;
  const WallFaceQuality wallQuality = wallFaceQuality(s.points, walls.triangles);
  const std::vector<double> directions = layers_detail::marchingDirections(walls, options.normalSmoothing);
  const std::vector<double> offsets = layers_detail::layerOffsets(options);
  std::vector<int32_t> start, list;
  layers_detail::columnNeighbours(walls, start, list);
  const size_t nc = walls.layeredPoints.size();
  std::vector<double> scale(nc, 1.0);
  std::vector<uint8_t> reason(nc, 0);
  walls.collapsed.assign(nc, 0);
  const int maxRounds = 12; // 1/2^12 of the height: below that a column is declared impossible
  for (int round = 0;; ++round)
  {
    if (report.cancelled())
      return Status::failure(ErrorKind::Cancelled, "boundary layers cancelled");
    report.report(std::min(0.95, round / double(maxRounds)), "Boundary layers: marching");
    layers_detail::placeLayerPoints(walls, directions, offsets, scale, result.points);
    ThinnedReason why = ThinnedReason::Inversion;
    std::vector<int32_t> bad = layers_detail::invertedColumns(walls, result.points, options.layers);
    if (bad.empty())
    {
      why = ThinnedReason::Collision;
      bad = layers_detail::collidingColumns(walls, result.points, options.layers);
    }
    result.stats.iterations = round;
    if (bad.empty())
      break;
    if (round == maxRounds)
    {
      const int32_t p = walls.layeredPoints[bad[0]];
      result = LayerResult();
      return Status::failure(ErrorKind::InvalidOption,
                             std::to_string(bad.size()) + " layer columns still fail (" + thinnedReasonName(why) +
                               ") at 1/4096 of the asked thickness, the first at point " + std::to_string(p) + " " +
                               pointText(s.point(p)) + ": the surface leaves no room for layers there",
                             { p });
    }
    thin(bad, why, start, list, walls, scale, reason);
  }
  assemble(s, checks, walls, wallIds, otherIds, options.layers, scale, reason, result);
  if (result.stats.fullTriangles == 0)
  {
    result = LayerResult();
    return Status::failure(ErrorKind::InvalidOption,
                           "the total layer thickness " + std::to_string(total) +
                             " is more than the domain allows: every layer column had "
                             "to be thinned");
  }
  result.stats.wallFaceQuality = wallQuality;
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  report.report(1, "Boundary layers: marching");
  return Status::success();
}

} // namespace volgrid
