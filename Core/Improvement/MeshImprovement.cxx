#include "MeshImprovement.h"
#include "SpatialReorder.h"

#include "DomainSizing.h"
#include "InteriorPolish.h"
#include "OrthogonalitySmoothing.h"
#include "QualityRounds.h"

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

// Tets below 10 degrees whose four vertices lie on constrained faces: their shape is set by the boundary
// triangles (no flip or move can change it without touching the boundary). And tets with no vertex on a
// constrained face outside the interior range (TetNeeds.h).
struct ShapeCounts
{
  int64_t boundaryForcedBelow10 = 0, interiorOutside = 0;
};
ShapeCounts countShapes(TetMesh& mesh, const FaceConstraints& fc)
{
  TetEditor probe(mesh, &fc, nullptr); // builds its vertex map
  const std::vector<uint8_t> lock = probe.lockedVertices();
  const double q10 = std::sin(10.0 * 3.14159265358979323846 / 180.0);
  const double qInterior = std::sin(kInteriorDegrees * 3.14159265358979323846 / 180.0);
  ShapeCounts n;
  mesh.forEachTet(
    [&](int32_t t)
    {
      const int32_t* v = mesh.vertices(t);
      const int locked = lock[v[0]] + lock[v[1]] + lock[v[2]] + lock[v[3]];
      if (locked != 0 && locked != 4)
        return;
      const double q = tetSineQuality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
      n.boundaryForcedBelow10 += locked == 4 && q < q10;
      n.interiorOutside += locked == 0 && q < qInterior;
    });
  return n;
}

// The interior polish (InteriorPolish.h), the stage's last edits. tetRegion: per slot, the region each new
// tet takes from the tets it replaces.
// severeCounted: stats.severeFacesAfter holds the mesh's count (the orthogonality moves ran), which the
// polish's edits change.
Status polishInteriorTets(TetMesh& mesh, const FaceConstraints& fc, const std::vector<uint8_t>& clusterLock,
                          std::vector<int32_t>& tetRegion, int threads, bool severeCounted,
                          ImprovementStatistics& stats, Progress* progress)
{
  TetEditor editor(mesh, &fc, &tetRegion); // builds its vertex map
  InteriorPolishOptions options;
  options.threads = threads;
  InteriorPolishReport report;
  const Status s = polishInterior(editor, editor.lockedVertices(), clusterLock.empty() ? nullptr : &clusterLock,
                                  options, progress, &report);
  stats.interiorOutsideBeforePolish = report.before;
  stats.splitPoints += report.splits;
  stats.secondsPolish = report.seconds;
  if (severeCounted) // the orthogonality moves' count, then the polish's edits
    stats.severeFacesAfter += report.severeChange;
  return s;
}

// Points removed by vertex collapses: recovery's (below nv0), field points (below nvField), split points.
void countRemovedPoints(const TetMesh& mesh, const std::vector<uint8_t>& usedBefore, int32_t nv0, int32_t nvField,
                        ImprovementStatistics& stats)
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
    SizingField fast;
    if (options.fieldPoints)
    {
      s = buildDomainSizing(mesh, surface, options, fast, stats, progress);
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
      const int32_t firstFieldPoint = mesh.numVertices();
      FieldPointOptions fieldPointOptions = options.fieldPointOptions;
      fieldPointOptions.threads = options.threads;
      fieldPointOptions.largeMeshTets = options.optimization.largeMeshTets;
      s = insertFieldPoints(mesh, fast, fieldPointOptions, &fc, &tetRegion, nullptr, progress, &fr);
      if (!s.ok())
        return s;
      stats.fieldPoints = fr.inserted;
      stats.fieldPasses = fr.passes;
      stats.fieldPointsInRegions = fr.insertedInRegions;
      // The field points and the tets are scattered through memory by now: one renumbering in space
      // makes the sweeps and local edits below read mostly consecutive memory (SpatialReorder.h). The
      // vertices before the field points (input, boundary Steiner and cluster points) keep their numbers.
      // Only for meshes too large for the caches (LargeMesh.h).
      if (mesh.numTets() >= options.optimization.largeMeshTets)
      {
        if (progress && progress->cancelled()) // each whole-mesh step in between is a few tenths of a second at 10M
          return Status::failure(ErrorKind::Cancelled, "Field point creation was cancelled.");
        const SpatialRenumbering renumbering = reorderSpatially(mesh, firstFieldPoint, options.threads, progress);
        if (progress && progress->cancelled())
          return Status::failure(ErrorKind::Cancelled, "Field point creation was cancelled.");
        renumberTetArray(renumbering, tetRegion, -1);
        renumberVertexArray(renumbering, clusterLock, uint8_t{ 0 });
      }
    }
    stats.secondsFieldPoints = since(t0);
  }

  // 4. Optimisation, one pass at a time so that it stops once a pass no longer pays: when the tets below
  //    the target are those the boundary triangles force (all four vertices on a constrained face), the
  //    remaining passes would only retry them.
  // The vertices in tets before optimisation: those it removes are counted at the end.
  const int32_t nvField = mesh.numVertices();
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  const std::vector<uint8_t> usedBefore = usedVertices(mesh);
  if (options.optimize)
  {
    const auto t0 = std::chrono::steady_clock::now();
    QualityRounds rounds(mesh, fc, clusterLock, tetRegion, options, stats, progress);
    s = rounds.run();
    if (!s.ok())
      return s;
    if (options.orthogonalitySmoothing)
    {
      OrthogonalitySmoothingOptions oo;
      oo.targetDegrees = options.optimization.targetDegrees;
      oo.threads = options.threads;
      OrthogonalitySmoothingReport orep;
      s = smoothNonOrthogonalFaces(mesh, &fc, clusterLock.empty() ? nullptr : &clusterLock, oo, progress, &orep);
      if (!s.ok())
        return s;
      stats.severeFacesBefore = orep.severeBefore;
      stats.severeFacesAfter = orep.severeAfter;
      stats.orthogonalityMoves = orep.moves;
    }
    if (options.interiorPolish)
    {
      s = polishInteriorTets(mesh, fc, clusterLock, tetRegion, options.threads, options.orthogonalitySmoothing, stats,
                             progress);
      if (!s.ok())
        return s;
    }
    if (progress && progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    stats.after = summarizeDihedrals(mesh, options.threads, progress);
    stats.secondsOptimization = since(t0);
  }
  else
    stats.after = summarizeDihedrals(mesh, options.threads, progress);
  // Each whole-mesh step from here on is a tenth of a second or more at 5M tets: asked between them.
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");

  const ShapeCounts shapes = countShapes(mesh, fc);
  stats.boundaryForcedBelow10 += shapes.boundaryForcedBelow10;
  stats.interiorOutside = shapes.interiorOutside;
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  countRemovedPoints(mesh, usedBefore, nv0, nvField, stats);
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
