#include "MeshImprovement.h"

#include "BadTetSplitting.h"
#include "InsertionImprovement.h"
#include "MeshScan.h"

#include "Predicates.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>

namespace volgrid
{

namespace
{
double since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool finitePositive(double x)
{
  return std::isfinite(x) && x > 0;
}

Status checkOptions(const ImprovementOptions& o)
{
  const FieldPointOptions& f = o.fieldPointOptions;
  const SizingOptions& s = o.sizing;
  const std::pair<const OptionSpec&, double> values[] = {
    { option::alpha, f.alpha },     { option::beta, f.beta },           { option::maxVolume, f.maxVolume },
    { option::sizeScale, s.scale }, { option::gradation, s.gradation }, { option::maxEdge, s.maxEdgeLength }
  };
  for (const auto& [spec, value] : values)
    if (!spec.valid(value))
      return Status::failure(ErrorKind::InvalidOption,
                             std::string(spec.name) + " must be in " + spec.rangeText() + ", not " +
                               std::to_string(value) + ".");
  if (f.maxPasses < 0 || !(s.minEdgeLength >= 0))
    return Status::failure(ErrorKind::InvalidOption, "Field points need maxPasses >= 0, sizing minEdgeLength >= 0.");
  if (o.clusterPoints.size() % 3 != 0 || o.sizingPoints.size() % 3 != 0)
    return Status::failure(ErrorKind::InvalidOption, "Cluster and sizing points are given as x,y,z triples.");
  if (!o.clusterSizes.empty() && o.clusterSizes.size() * 3 != o.clusterPoints.size())
    return Status::failure(ErrorKind::InvalidOption, "clusterSizes needs one value per cluster point (or none).");
  if (o.sizingValues.size() * 3 != o.sizingPoints.size())
    return Status::failure(ErrorKind::InvalidOption, "sizingValues needs one value per sizing point.");
  if (o.optimize &&
      (!option::targetAngle.valid(o.optimization.targetDegrees) || !option::passes.valid(o.optimization.maxPasses)))
    return Status::failure(ErrorKind::InvalidOption,
                           "Optimisation needs targetDegrees in " + option::targetAngle.rangeText() +
                             " and maxPasses in " + option::passes.rangeText() + ".");
  return Status::success();
}
// The worst tet's min(theta_min, 180 - theta_max) in degrees (a sweep on `threads`, MeshScan.h).
double worstSineDegrees(const TetMesh& mesh, int threads)
{
  return sineQualityToDegrees(minSineQuality(mesh, threads));
}

int64_t countBelow(const TetMesh& mesh, double degrees, int threads)
{
  return countSineBelow(mesh, std::sin(degrees * 3.14159265358979323846 / 180.0), threads);
}

// A sizing field sampled on an adaptive octree over a box, with trilinear interpolation in the leaves.
// Field points query the size at tet centroids in an order that jumps around the domain, and each query
// of the background interpolant walks its mesh from the previous one; the octree is built with coherent
// queries (children next to their parent) and answers in O(depth). A cell is split while it is larger
// than 1.5 times the smallest size at its corners and centre, so leaves are about the local size and
// the interpolation follows the field closely.
class OctreeSizing
{
public:
  void build(const SizingField& field, const double lo[3], double size, int maxDepth, size_t maxCells)
  {
    std::copy(lo, lo + 3, lo_);
    size_ = size;
    cells_.assign(1, Cell());
    std::vector<std::array<double, 3>> origin = { { lo[0], lo[1], lo[2] } };
    std::vector<int> depthOf = { 0 };
    for (int k = 0; k < 8; ++k)
    {
      const double p[3] = { lo[0] + ((k & 1) ? size : 0), lo[1] + ((k & 2) ? size : 0), lo[2] + ((k & 4) ? size : 0) };
      cells_[0].h[k] = static_cast<float>(field.evaluate(p));
    }
    float grid[27];
    // Breadth first: cells are appended in groups of eight siblings, so the queue is the cell array.
    for (size_t c = 0; c < cells_.size(); ++c)
    {
      const int depth = depthOf[c];
      const double cs = size / static_cast<double>(1u << depth);
      const std::array<double, 3> o = origin[c];
      const double centre[3] = { o[0] + cs / 2, o[1] + cs / 2, o[2] + cs / 2 };
      const double hc = field.evaluate(centre);
      double hmin = hc;
      for (int k = 0; k < 8; ++k)
        hmin = std::min(hmin, static_cast<double>(cells_[c].h[k]));
      if (!(depth < maxDepth && cs > 1.5 * hmin && cells_.size() + 8 <= maxCells))
        continue;
      // The 3x3x3 lattice of the children's corners: the parent's corners and centre are known.
      for (int l = 0; l < 27; ++l)
      {
        const int i = l % 3, j = (l / 3) % 3, m = l / 9;
        if (i != 1 && j != 1 && m != 1)
          grid[l] = cells_[c].h[(i / 2) | ((j / 2) << 1) | ((m / 2) << 2)];
        else if (i == 1 && j == 1 && m == 1)
          grid[l] = static_cast<float>(hc);
        else
        {
          const double p[3] = { o[0] + i * cs / 2, o[1] + j * cs / 2, o[2] + m * cs / 2 };
          grid[l] = static_cast<float>(field.evaluate(p));
        }
      }
      const int32_t first = static_cast<int32_t>(cells_.size());
      cells_[c].child = first;
      for (int k = 0; k < 8; ++k)
      {
        const int bx = k & 1, by = (k >> 1) & 1, bz = (k >> 2) & 1;
        Cell child;
        for (int n = 0; n < 8; ++n)
          child.h[n] = grid[(bx + (n & 1)) + 3 * (by + ((n >> 1) & 1)) + 9 * (bz + ((n >> 2) & 1))];
        cells_.push_back(child);
        origin.push_back({ o[0] + bx * cs / 2, o[1] + by * cs / 2, o[2] + bz * cs / 2 });
        depthOf.push_back(depth + 1);
      }
    }
  }
  double evaluate(const double* p) const
  {
    double u[3];
    for (int k = 0; k < 3; ++k)
      u[k] = std::clamp((p[k] - lo_[k]) / size_, 0.0, 1.0);
    int32_t c = 0;
    while (cells_[c].child >= 0)
    {
      int k = 0;
      for (int a = 0; a < 3; ++a)
      {
        u[a] *= 2;
        if (u[a] >= 1)
        {
          k |= 1 << a;
          u[a] -= 1;
        }
      }
      c = cells_[c].child + k;
    }
    const float* h = cells_[c].h;
    double r = 0;
    for (int k = 0; k < 8; ++k)
      r += h[k] * ((k & 1) ? u[0] : 1 - u[0]) * ((k & 2) ? u[1] : 1 - u[1]) * ((k & 4) ? u[2] : 1 - u[2]);
    return r;
  }
  size_t cells() const { return cells_.size(); }

private:
  struct Cell
  {
    float h[8];
    int32_t child = -1;
  };
  std::vector<Cell> cells_;
  double lo_[3] = { 0, 0, 0 };
  double size_ = 1;
};

// 1 for the vertices of live tets.
std::vector<uint8_t> usedVertices(const TetMesh& mesh)
{
  std::vector<uint8_t> used(static_cast<size_t>(mesh.numVertices()), 0);
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        used[mesh.vertex(t, i)] = 1;
    });
  return used;
}

// Whether a tet under `degrees` has a vertex on no constrained face and not locked by the caller: only
// then can a vertex collapse touch the worst tets.
bool hasUnlockedVertexBelow(TetMesh& mesh, const FaceConstraints& fc, const std::vector<uint8_t>& extraLock,
                            double degrees)
{
  TetEditor probe(mesh, &fc, nullptr);
  probe.rebuildVertexMap();
  const std::vector<uint8_t> lock = probe.lockedVertices();
  const double q = std::sin(degrees * 3.14159265358979323846 / 180.0);
  bool found = false;
  mesh.forEachTet(
    [&](int32_t t)
    {
      const int32_t* v = mesh.vertices(t);
      if (found || !(tetSineQuality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])) < q))
        return;
      for (int i = 0; i < 4; ++i)
        if (!lock[v[i]] && !(static_cast<size_t>(v[i]) < extraLock.size() && extraLock[v[i]]))
          found = true;
    });
  return found;
}

} // namespace

ImprovementOptions::ImprovementOptions()
{
  // Defaults chosen for a good mesh with no option set (measured on the sphere-in-sphere domain and the
  // clean corpus). Sizes are target edge lengths: at the boundary points the PDF of eq. 3 (scale 1), and
  // with alpha 0.75 the mean edge follows h (FieldPoints.h); away from the boundary h grows by at most
  // (gradation - 1) per unit length, and does grow at that rate where nothing smaller is asked (the
  // lattice nodes of the sizing field). Optimisation aims at every dihedral angle in [18, 162] where the
  // boundary triangles allow it.
  // alpha, beta, gradation, scale, the target angle and the pass limit: OptionTable.h (the members'
  // own defaults).
  // The mesher writes only the points its tets use: interior points (recovery's Steiner points squeezed
  // against the boundary, field points) may be removed where that improves the worst tet around them.
  optimization.vertexRemoval = true;
}

Status improveDomainMesh(MeshEditor& editor, const BoundaryConstraints& bc, const SurfaceMesh& surface,
                         std::vector<VertexKind>& kinds, std::vector<int32_t>& tetRegion,
                         const ImprovementOptions& options, ImprovementStatistics& stats, Progress* progress)
{
  stats = ImprovementStatistics();
  TetMesh& mesh = editor.mesh;
  if (!options.fieldPoints && !options.optimize && options.clusterPoints.empty())
    return Status::success();
  Status s = checkOptions(options);
  if (!s.ok())
    return s;
  if (mesh.numGhostTets() > 0)
    return Status::failure(ErrorKind::InternalError, "Grid improvement needs the mesh of the domain (no ghosts).");
  const int32_t nv0 = mesh.numVertices();

  // 1. Interior boundary subfaces (interfaces between kept regions) become explicit constraints; faces
  //    without a neighbour are constrained anyway.
  FaceConstraints fc;
  editor.rebuildVertexMap();
  for (int32_t f = 0; f < bc.capacity(); ++f)
  {
    if (!bc.alive(f))
      continue;
    const int32_t* v = bc.subface(f);
    int face = -1;
    const int32_t t = editor.findFace(v[0], v[1], v[2], &face);
    if (t >= 0 && face >= 0 && mesh.neighborCode(t, face) >= 0)
      fc.add(v[0], v[1], v[2]);
  }
  stats.interfaceFaces = static_cast<int64_t>(fc.size());
  stats.before = summarizeDihedrals(mesh, options.threads);
  if (tetRegion.size() < static_cast<size_t>(mesh.tetCapacity()))
    tetRegion.resize(static_cast<size_t>(mesh.tetCapacity()), -1);

  // 2. Sizing field and 3. clustering + field points. Cluster points stay where the user put them
  //    (locked against smoothing).
  std::vector<uint8_t> clusterLock;
  const size_t nCluster = options.clusterPoints.size() / 3;
  if (options.fieldPoints || nCluster > 0)
  {
    auto t0 = std::chrono::steady_clock::now();
    SizingField sizing, fast;
    std::shared_ptr<OctreeSizing> octree;
    if (options.sizingFunction)
      sizing.setUserFunction(options.sizingFunction);
    if (!options.sizingPoints.empty())
      sizing.setBackgroundCloud(options.sizingPoints.data(), options.sizingValues.data(), options.sizingValues.size());
    if (!options.clusterSizes.empty())
      sizing.addSizedPoints(options.clusterPoints.data(), options.clusterSizes.data(), nCluster);
    if (options.fieldPoints)
    {
      // The boundary points with their PDF (eq. 3) become sized nodes, each moved by a millionth of its
      // own PDF: the background Delaunay of the sizing field then sees no cospherical or coplanar sets
      // (spheres, boxes), which would send every insphere test to exact arithmetic, and the interpolated
      // sizes change by a negligible amount. The mesh itself is untouched.
      const std::vector<double> pdf = pointDistributionFunction(surface.points.data(), surface.numberOfPoints(),
                                                                surface.triangles.data(), surface.numberOfTriangles());
      std::vector<double> xyz, h;
      xyz.reserve(surface.points.size());
      h.reserve(pdf.size());
      uint64_t state = 0x9E3779B97F4A7C15ull;
      for (int32_t i = 0; i < surface.numberOfPoints(); ++i)
      {
        if (!(pdf[i] > 0))
          continue;
        for (int k = 0; k < 3; ++k)
        {
          state = state * 6364136223846793005ull + 1442695040888963407ull;
          const double u = static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0) - 0.5; // [-0.5, 0.5)
          xyz.push_back(surface.points[3 * static_cast<size_t>(i) + k] + 2e-6 * u * pdf[i]);
        }
        h.push_back(pdf[i] * options.sizing.scale);
      }
      // Growth away from the boundary: a jittered lattice of nodes over the bounding box with an
      // unbounded size. The gradation limit (Dijkstra over the background Delaunay edges) then gives each
      // one min over the boundary nodes u of h(u) + (G - 1) * path length, so the size grows away from
      // the boundary at the gradation's rate instead of staying at the boundary spacing inside thick
      // bodies (the plain interpolation of eq. 3's PDF between opposite sides of a body).
      if (options.sizing.gradation > 1 && !h.empty())
      {
        double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
        for (size_t i = 0; i < h.size(); ++i)
          for (int k = 0; k < 3; ++k)
          {
            lo[k] = std::min(lo[k], xyz[3 * i + k]);
            hi[k] = std::max(hi[k], xyz[3 * i + k]);
          }
        const double ext = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
        // About (nodes / 4) lattice nodes, at most 24 per axis: a tenth of the work of the field points.
        const double cells = std::clamp(std::cbrt(static_cast<double>(h.size()) / 4.0), 2.0, 24.0);
        const double step = ext / cells;
        const double unbounded = 4 * ext + 1;
        const size_t nBoundary = h.size();
        for (double x = lo[0] + step / 2; x < hi[0]; x += step)
          for (double y = lo[1] + step / 2; y < hi[1]; y += step)
            for (double z = lo[2] + step / 2; z < hi[2]; z += step)
            {
              const double c[3] = { x, y, z };
              for (int k = 0; k < 3; ++k)
              {
                state = state * 6364136223846793005ull + 1442695040888963407ull;
                const double u = static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0) - 0.5;
                xyz.push_back(c[k] + 0.3 * u * step);
              }
              h.push_back(unbounded);
            }
        stats.latticeNodes = static_cast<int64_t>(h.size() - nBoundary);
      }
      sizing.addSizedPoints(xyz.data(), h.data(), h.size());
      s = sizing.build(nullptr, 0, nullptr, 0, options.sizing, progress);
      if (!s.ok())
        return s;
      // The field points query the octree sampling of this field (see OctreeSizing).
      double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
      for (size_t i = 0; i < mesh.points.size(); i += 3)
        for (int k = 0; k < 3; ++k)
        {
          lo[k] = std::min(lo[k], mesh.points[i + k]);
          hi[k] = std::max(hi[k], mesh.points[i + k]);
        }
      const double ext = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] }) * 1.001 + 1e-300;
      octree = std::make_shared<OctreeSizing>();
      octree->build(sizing, lo, ext, 18, std::max<size_t>(1u << 20, 16 * static_cast<size_t>(mesh.numVertices())));
      std::shared_ptr<const OctreeSizing> tree = octree;
      SizingOptions uniformOptions = options.sizing;
      uniformOptions.gradation = 1; // no sized points in the outer field: nothing to grade
      fast.setUserFunction([tree](const double* p) { return tree->evaluate(p); });
      s = fast.buildUniform(std::numeric_limits<double>::max(), uniformOptions);
      if (!s.ok())
        return s;
    }
    stats.secondsSizing = since(t0);
    t0 = std::chrono::steady_clock::now();
    FieldPointReport fr;
    if (nCluster > 0)
    {
      std::vector<int32_t> ids;
      s = insertClusterPoints(mesh, options.clusterPoints.data(), nCluster, 0, &fc, &tetRegion, &ids, progress, &fr);
      if (!s.ok())
        return s;
      stats.clusterPoints = fr.clusterInserted;
      for (int32_t v : ids)
        if (v >= 0)
        {
          if (clusterLock.size() <= static_cast<size_t>(v))
            clusterLock.resize(static_cast<size_t>(v) + 1, 0);
          clusterLock[v] = 1;
        }
      stats.clusterSkipped = fr.clusterOutside + fr.clusterRejected;
    }
    if (options.fieldPoints)
    {
      s = insertFieldPoints(mesh, fast, options.fieldPointOptions, &fc, &tetRegion, nullptr, progress, &fr);
      if (!s.ok())
        return s;
      stats.fieldPoints = fr.inserted;
      stats.fieldPasses = fr.passes;
    }
    stats.secondsFieldPoints = since(t0);
  }

  // 4. Optimisation, one pass at a time so that it stops once a pass no longer pays: when the tets below
  //    the target are those the boundary triangles force (all four vertices on a constrained face), the
  //    remaining passes would only retry them.
  // The vertices in tets before optimisation: those it removes are counted at the end.
  const int32_t nvField = mesh.numVertices();
  const std::vector<uint8_t> usedBefore = usedVertices(mesh);
  if (options.optimize)
  {
    const auto t0 = std::chrono::steady_clock::now();
    OptimizationOptions one = options.optimization;
    one.threads = options.threads;
    one.maxPasses = 1;
    one.vertexRemoval = false; // a second attempt, below
    one.summaries = false;     // the rounds decide on the smallest angle only; one summary at the end
    // The first call runs up to three passes, then one pass per call while a pass still pays.
    auto optimise = [&](int maxPasses) -> Status
    {
      for (int pass = 0; pass < maxPasses; pass += one.maxPasses)
      {
        one.maxPasses = pass == 0 ? std::min(3, maxPasses) : 1;
        OptimizationReport orep;
        Status os =
          optimizeMesh(mesh, &fc, clusterLock.empty() ? nullptr : &clusterLock, &tetRegion, one, progress, &orep);
        if (!os.ok())
          return os;
        stats.after.minDihedral = orep.minDihedralAfter; // what the rounds below decide on (summary: at the end)
        stats.optimizationPasses += orep.passes;
        stats.flips += orep.flips23 + orep.edgeRemovals;
        stats.smoothMoves += orep.smoothMoves;
        const int64_t gained = orep.belowTargetBefore - orep.belowTargetAfter;
        const bool minImproved = orep.minDihedralAfter > orep.minDihedralBefore + 1.0;
        if (orep.belowTargetAfter == 0 || orep.passes == 0 || (gained <= orep.belowTargetBefore / 50 && !minImproved))
          break;
      }
      return Status::success();
    };
    // Beyond the target the mesh's minimum is decided by its few worst tets: while it pays, aim a little
    // above the current worst (flips, smoothing and splitting touch only the tets below the aim and accept
    // strict improvements only), so a mesh already past the target still gets better where it is worst.
    auto floorRounds = [&]() -> Status
    {
      for (int round = 0; round < options.floorRounds; ++round)
      {
        if (progress && progress->cancelled())
          return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
        const double worst = worstSineDegrees(mesh, options.threads);
        if (!(worst > 0) || worst >= 60)
          break;
        one.targetDegrees = std::max(worst + 2.0, options.optimization.targetDegrees);
        // A plateau of many tets just above the worst (typically at the target) needs global work: not here.
        if (countBelow(mesh, one.targetDegrees, options.threads) > std::max<int64_t>(64, mesh.numTets() / 200))
          break;
        Status fs = optimise(2);
        if (!fs.ok())
          return fs;
        stats.splitPoints += splitBadTets(mesh, &fc, &tetRegion, one.targetDegrees, 64);
        fs = optimise(1);
        if (!fs.ok())
          return fs;
        if (worstSineDegrees(mesh, options.threads) < worst + 0.05)
          break;
      }
      return Status::success();
    };
    // The stage: optimisation, splitting of what it cannot fix, floor rounds.
    auto optimiseSplitFloor = [&]() -> Status
    {
      one.targetDegrees = options.optimization.targetDegrees;
      Status ps = optimise(options.optimization.maxPasses);
      if (!ps.ok())
        return ps;
      // What optimisation cannot fix (slivers spanned by boundary vertices): split by a point inside, then
      // optimise again. At most splitRounds rounds.
      for (int round = 0; round < options.splitRounds && stats.after.minDihedral < options.optimization.targetDegrees;
           ++round)
      {
        if (progress && progress->cancelled())
          return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
        const int64_t n = splitBadTets(mesh, &fc, &tetRegion, options.optimization.targetDegrees,
                                       std::max<int64_t>(200, mesh.numTets() / 20));
        stats.splitPoints += n;
        if (n == 0)
          break;
        const double minBefore = stats.after.minDihedral;
        Status ps = optimise(std::min(3, options.optimization.maxPasses));
        if (!ps.ok())
          return ps;
        if (stats.after.minDihedral < minBefore + 0.1)
          break;
      }
      return floorRounds();
    };
    // Vertex collapses (optimization.vertexRemoval) are a second attempt, from the same start, when the
    // worst tet stays under vertexRemovalDegrees (typically recovery's Steiner points pinned against
    // nearly coplanar boundary faces, which no flip, move or added point opens); the better of the two
    // meshes is kept (collapses coarsen the mesh and change what later rounds reach: kept only when the
    // worst tet gets better).
    const bool removal = options.optimization.vertexRemoval;
    TetMesh startMesh;
    std::vector<int32_t> startRegion;
    ImprovementStatistics startStats;
    if (removal)
    {
      startMesh = mesh;
      startRegion = tetRegion;
      startStats = stats;
    }
    s = optimiseSplitFloor();
    if (!s.ok())
      return s;
    const double worstKept = worstSineDegrees(mesh, options.threads);
    const double removalDegrees =
      std::min(options.optimization.vertexRemovalDegrees, options.optimization.targetDegrees);
    if (removal && worstKept < removalDegrees && hasUnlockedVertexBelow(mesh, fc, clusterLock, removalDegrees))
    {
      TetMesh keptMesh = std::move(mesh);
      std::vector<int32_t> keptRegion = std::move(tetRegion);
      const ImprovementStatistics keptStats = stats;
      mesh = std::move(startMesh);
      tetRegion = std::move(startRegion);
      stats = startStats;
      one.vertexRemoval = true;
      s = optimiseSplitFloor();
      if (!s.ok())
        return s;
      one.vertexRemoval = false;
      if (!(worstSineDegrees(mesh, options.threads) > worstKept))
      {
        mesh = std::move(keptMesh);
        tetRegion = std::move(keptRegion);
        stats = keptStats;
      }
    }
    // Small meshes (a few boundary triangles, few or no field points) often end as a tie with any
    // Delaunay-based mesher: no single flip, move or improving insertion helps. Speculative rounds insert
    // the best point found for the worst tet, optimise around it, and keep the result only when the
    // mesh's worst tet got better (else the mesh is restored: a copy is cheap at this size, and the next
    // bad tet is tried).
    // With many tets below the aim (a surface whose own triangles force bad tets, e.g. falcon1.stl: 10%
    // under 10 deg) a round costs a full optimisation of all of them: fewer rounds then.
    constexpr int64_t kSpeculativeMaxBad = 32;
    constexpr int kSpeculativeRoundsManyBad = 4;
    int speculativeRounds = options.speculativeRounds;
    for (int round = 0, skip = 0; round < speculativeRounds && mesh.numTets() <= 5000; ++round)
    {
      const double worst = worstSineDegrees(mesh, options.threads);
      if (!(worst > 0) || worst >= 60)
        break;
      if (countBelow(mesh, std::max(worst + 2.0, options.optimization.targetDegrees), options.threads) >
          kSpeculativeMaxBad)
        speculativeRounds = std::min(speculativeRounds, kSpeculativeRoundsManyBad);
      const TetMesh savedMesh = mesh;
      const std::vector<int32_t> savedRegion = tetRegion;
      const DihedralSummary savedAfter = stats.after;
      one.targetDegrees = std::max(worst + 2.0, options.optimization.targetDegrees);
      // Up to three points (each for the worst tet after the previous one), judged after each.
      int64_t n = 0;
      bool improved = false;
      for (int depth = 0; depth < 3 && !improved; ++depth)
      {
        const int64_t k =
          splitBadTets(mesh, &fc, &tetRegion, one.targetDegrees, 1, true, depth == 0 ? static_cast<size_t>(skip) : 0);
        if (k == 0)
          break;
        n += k;
        s = optimise(3);
        if (!s.ok())
          return s;
        improved = worstSineDegrees(mesh, options.threads) > worst + 0.01;
      }
      if (improved)
      {
        stats.splitPoints += n;
        skip = 0;
        continue;
      }
      mesh = savedMesh;
      tetRegion = savedRegion;
      stats.after = savedAfter;
      if (countBelow(mesh, one.targetDegrees, options.threads) <= ++skip)
        break;
    }
    // What is still worst (typically tets of four boundary vertices on a needle triangle in a thin wedge,
    // on any mesh size): a point inserted for it, flipped and smoothed around, kept only when its region's
    // worst tet improves.
    if (options.insertionRounds > 0)
    {
      InsertionImprovementOptions io;
      io.rounds = options.insertionRounds;
      io.plateauDegrees = options.optimization.targetDegrees;
      io.threads = options.threads;
      const int64_t kept =
        improveWorstByInsertion(mesh, &fc, clusterLock.empty() ? nullptr : &clusterLock, &tetRegion, io);
      stats.splitPoints += kept;
    }
    stats.after = summarizeDihedrals(mesh, options.threads);
    stats.secondsOptimization = since(t0);
  }
  else
    stats.after = summarizeDihedrals(mesh, options.threads);

  // Tets below 10 degrees whose four vertices lie on constrained faces: their shape is set by the
  // boundary triangles (no flip or move can change it without touching the boundary).
  {
    TetEditor probe(mesh, &fc, nullptr);
    probe.rebuildVertexMap();
    const std::vector<uint8_t> lock = probe.lockedVertices();
    const double q10 = std::sin(10.0 * 3.14159265358979323846 / 180.0);
    mesh.forEachTet(
      [&](int32_t t)
      {
        const int32_t* v = mesh.vertices(t);
        if (lock[v[0]] && lock[v[1]] && lock[v[2]] && lock[v[3]] &&
            tetSineQuality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])) < q10)
          ++stats.boundaryForcedBelow10;
      });
  }

  // Points removed by vertex collapses: recovery's (below nv0), field points (below nvField), split points.
  {
    const std::vector<uint8_t> usedAfter = usedVertices(mesh);
    for (int32_t v = 0; v < mesh.numVertices(); ++v)
    {
      const bool before = v < nvField ? usedBefore[v] != 0 : true; // split points: inserted in use
      if (!before || usedAfter[v])
        continue;
      ++stats.removedPoints;
      if (v >= nvField)
        --stats.splitPoints;
      else if (v >= nv0)
        --stats.fieldPoints;
    }
  }
  if (mesh.numVertices() > nv0)
    kinds.resize(static_cast<size_t>(mesh.numVertices()), VertexKind::SteinerInterior);
  if (tetRegion.size() < static_cast<size_t>(mesh.tetCapacity()))
    tetRegion.resize(static_cast<size_t>(mesh.tetCapacity()), -1);
  editor.rebuildVertexMap();
  return Status::success();
}

Status tetMeshFromTets(const std::vector<double>& points, const std::vector<int32_t>& tets, TetMesh& mesh)
{
  mesh.clear();
  if (points.size() % 3 != 0 || tets.size() % 4 != 0)
    return Status::failure(ErrorKind::InvalidOption, "Points come in triples and tets in quadruples.");
  const int32_t nv = static_cast<int32_t>(points.size() / 3);
  const size_t nt = tets.size() / 4;
  mesh.points = points;
  mesh.reserve(static_cast<size_t>(nv), nt);
  for (size_t t = 0; t < nt; ++t)
  {
    int32_t v[4] = { tets[4 * t], tets[4 * t + 1], tets[4 * t + 2], tets[4 * t + 3] };
    for (int i = 0; i < 4; ++i)
      if (v[i] < 0 || v[i] >= nv)
        return Status::failure(ErrorKind::InvalidOption,
                               "Tet " + std::to_string(t) + " refers to point " + std::to_string(v[i]) +
                                 ", which does not exist.",
                               { static_cast<int64_t>(t) });
    const int o = predicates::orient3d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
    if (o == 0)
      return Status::failure(ErrorKind::InvalidOption, "Tet " + std::to_string(t) + " is flat.",
                             { static_cast<int64_t>(t) });
    if (o < 0)
      std::swap(v[0], v[1]);
    mesh.newTet(v[0], v[1], v[2], v[3]);
  }
  // Link the faces through a map from the sorted vertex triple.
  struct Key
  {
    int32_t a, b, c;
    bool operator==(const Key& o) const { return a == o.a && b == o.b && c == o.c; }
  };
  struct Hash
  {
    size_t operator()(const Key& k) const
    {
      uint64_t h = static_cast<uint32_t>(k.a) * 0x9E3779B97F4A7C15ull;
      h ^= (static_cast<uint64_t>(static_cast<uint32_t>(k.b)) + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
      h ^= (static_cast<uint64_t>(static_cast<uint32_t>(k.c)) << 21) * 0x165667B19E3779F9ull;
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  std::unordered_map<Key, int32_t, Hash> open;
  open.reserve(nt * 2 + 16);
  for (int32_t t = 0; t < static_cast<int32_t>(nt); ++t)
    for (int i = 0; i < 4; ++i)
    {
      int32_t f[3];
      mesh.faceVertices(t, i, f);
      std::sort(f, f + 3);
      const Key k{ f[0], f[1], f[2] };
      auto it = open.find(k);
      if (it == open.end())
      {
        open.emplace(k, TetMesh::encode(t, i));
        continue;
      }
      if (it->second < 0)
        return Status::failure(ErrorKind::InvalidOption,
                               "Face (" + std::to_string(f[0]) + "," + std::to_string(f[1]) + "," +
                                 std::to_string(f[2]) + ") is shared by more than two tets.",
                               { t });
      mesh.link(t, i, it->second >> 2, it->second & 3);
      it->second = -2; // closed
    }
  return Status::success();
}

Status refineTetMesh(TetMesh& mesh, const std::vector<double>& targetSize, std::vector<int32_t>* regions,
                     const RefineOptions& options, Progress* progress, RefineReport* reportOut)
{
  const auto t0 = std::chrono::steady_clock::now();
  RefineReport local;
  RefineReport& report = reportOut ? *reportOut : local;
  report = RefineReport();
  if (mesh.numGhostTets() > 0)
    return Status::failure(ErrorKind::InvalidOption, "Refinement works on a mesh without ghost tets.");
  if (targetSize.size() != static_cast<size_t>(mesh.numVertices()))
    return Status::failure(ErrorKind::InvalidOption, "Refinement needs one target size per mesh vertex.");
  report.before = summarizeDihedrals(mesh);

  // Constraints: faces between different regions (faces without a neighbour are constrained anyway).
  FaceConstraints fc;
  if (regions)
  {
    regions->resize(static_cast<size_t>(mesh.tetCapacity()), -1);
    mesh.forEachTet(
      [&](int32_t t)
      {
        for (int i = 0; i < 4; ++i)
        {
          const int32_t u = mesh.neighbor(t, i);
          if (u > t && (*regions)[u] != (*regions)[t])
          {
            int32_t f[3];
            mesh.faceVertices(t, i, f);
            fc.add(f[0], f[1], f[2]);
          }
        }
      });
  }

  // The targets as a background cloud over the used vertices, optionally graded over the mesh edges.
  std::vector<double> sizes = targetSize;
  std::vector<uint8_t> used(static_cast<size_t>(mesh.numVertices()), 0);
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        used[mesh.vertex(t, i)] = 1;
    });
  if (options.gradation > 1)
    limitGradation(mesh, options.gradation - 1, sizes);
  std::vector<double> xyz, val;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (used[v] && finitePositive(sizes[v]))
    {
      xyz.insert(xyz.end(), mesh.point(v), mesh.point(v) + 3);
      val.push_back(sizes[v]);
    }
  if (val.empty())
    return Status::failure(ErrorKind::InvalidOption, "No vertex has a finite positive target size.");
  SizingField sizing;
  sizing.setBackgroundCloud(xyz.data(), val.data(), val.size());
  Status s = sizing.buildUniform(1e300, SizingOptions());
  if (!s.ok())
    return s;
  FieldPointReport fr;
  s = insertFieldPoints(mesh, sizing, options.fieldPointOptions, fc.empty() ? nullptr : &fc, regions, nullptr, progress,
                        &fr);
  if (!s.ok())
    return s;
  report.inserted = fr.inserted;
  report.passes = fr.passes;
  if (options.optimize)
  {
    OptimizationReport orep;
    OptimizationOptions optimization = options.optimization;
    optimization.vertexRemoval = false; // every vertex of the given mesh stays in it (its point data too)
    s = optimizeMesh(mesh, fc.empty() ? nullptr : &fc, nullptr, regions, optimization, progress, &orep);
    if (!s.ok())
      return s;
    report.after = orep.after;
  }
  else
    report.after = summarizeDihedrals(mesh);
  if (regions)
    regions->resize(static_cast<size_t>(mesh.tetCapacity()), -1);
  report.seconds = since(t0);
  return Status::success();
}

} // namespace volgrid
