#include "BoundaryRecovery.h"
#include "Recoverer.h"

#include "BoundaryCensus.h"
#include "FacetPieces.h"
#include "FacetRecovery.h"

#include <algorithm>
#include <chrono>

namespace volgrid
{

// ------------------------------------------------------------------------------------------------
// Recovery: recoverBoundary() drives a Recoverer (Recoverer.h) over the missing segments and facets.

namespace
{

// The final census: the unrecovered edges and facets counted into `rep`; returns the input triangles of
// the first five of each (edges first).
std::vector<int64_t> finalCensus(MeshEditor& ed, BoundaryConstraints& bc, BoundaryCensus& census, RecoveryReport& rep)
{
  std::vector<int64_t> badEdges, badFaces;
  if (!census.upToDate(ed, bc))
    census.take(ed, bc);
  // A live subface none of whose edges was counted missing above, yet not a face, is a missing facet.
  std::vector<uint8_t> edgeMissing(static_cast<size_t>(bc.capacity()), 0);
  census.forEachSubfaceEdge(bc,
                            [&](int32_t f, int32_t, int32_t, int32_t id, bool first)
                            {
                              if (first && (id < 0 || !census.edgePresent(id)))
                              {
                                ++rep.unrecoveredEdges;
                                edgeMissing[static_cast<size_t>(f)] = 1;
                                if (badEdges.size() < 5)
                                  badEdges.push_back(bc.parent[f]);
                              }
                            });
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f) && !edgeMissing[static_cast<size_t>(f)] && census.faceCode(f) < 0)
    {
      ++rep.unrecoveredFacets;
      if (badFaces.size() < 5)
        badFaces.push_back(bc.parent[f]);
    }
  badEdges.insert(badEdges.end(), badFaces.begin(), badFaces.end());
  return badEdges;
}

// Cavity retetrahedralization of each input triangle with missing subfaces (all its segments present):
// the whole triangle, its pieces, or the slab; a triangle none of them recovers is marked in `fallback`.
Status recoverFacetCavities(MeshEditor& ed, BoundaryConstraints& bc, const std::vector<int32_t>& missingFaces,
                            std::vector<char>& fallback, FacetCavityStats& cavityStats, Progress& progress)
{
  std::unordered_map<int32_t, std::vector<int32_t>> byParent;
  for (int32_t f : missingFaces)
    if (!fallback[static_cast<size_t>(bc.parent[f])])
      byParent.emplace(bc.parent[f], std::vector<int32_t>());
  if (byParent.empty())
    return Status::success();
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f))
    {
      auto it = byParent.find(bc.parent[f]);
      if (it != byParent.end())
        it->second.push_back(f);
    }
  size_t done = 0;
  for (auto& [par, subs] : byParent)
  {
    if (++done % 256 == 0)
    {
      progress.report(0.5 + 0.5 * static_cast<double>(done) / byParent.size(), "Recovering boundary facets");
      if (progress.cancelled())
        return Status::failure(ErrorKind::Cancelled, "Boundary recovery was cancelled.");
    }
    if (!recoverFacetByCavity(ed, bc, par, subs, &cavityStats) &&
        !recoverFacetByPieces(ed, bc, par, subs, &cavityStats) && !recoverFacetBySlab(ed, bc, par, subs, &cavityStats))
      fallback[static_cast<size_t>(par)] = 1;
  }
  return Status::success();
}

// The presplit stage: rounds that split each missing listed segment at its midpoint (insertVertex without
// constraints is the Bowyer-Watson insertion, so the mesh stays Delaunay) until all are edges (true) or
// `budget` points are used or a round splits nothing (false).
template<class CollectMissing>
bool presplit(Recoverer& rec, MeshEditor& ed, BoundaryConstraints& bc, const std::unordered_set<uint64_t>& segments,
              int64_t budget, CollectMissing&& collectMissingEdges,
              const std::vector<std::pair<int32_t, int32_t>>& missingEdges, int64_t& steinerUsed, RecoveryReport& rep)
{
  for (int round = 0; round < 64 && steinerUsed < budget; ++round)
  {
    collectMissingEdges(&segments);
    if (missingEdges.empty())
      return true;
    bool split = false;
    for (auto [a, b] : missingEdges)
      if (bc.isEdge(a, b) && ed.findEdge(a, b) < 0 && steinerUsed < budget && rec.splitEdge(a, b, true))
      {
        ++steinerUsed;
        ++rep.presplitPoints;
        split = true;
      }
    if (!split)
      return false;
  }
  return false;
}

// Recovers each missing edge (still a constraint edge: not split meanwhile) by flips while the work lasts
// (workLimit edge removals; outOfWork is set once it is spent); the others go to failedEdges. False when
// cancelled.
bool flipMissingEdges(Recoverer& rec, MeshEditor& ed, BoundaryConstraints& bc,
                      const std::vector<std::pair<int32_t, int32_t>>& missingEdges, uint64_t workLimit, bool& outOfWork,
                      std::vector<std::pair<int32_t, int32_t>>& failedEdges, Progress& pr)
{
  failedEdges.clear();
  size_t done = 0;
  for (auto [a, b] : missingEdges)
  {
    if (++done % 256 == 0)
    {
      pr.report(0.5 * static_cast<double>(done) / missingEdges.size(), "Recovering boundary edges");
      if (pr.cancelled())
        return false;
    }
    if (!bc.isEdge(a, b))
      continue;
    if (ed.removalAttempts > workLimit)
      outOfWork = true;
    if (!outOfWork && rec.recoverEdgeByFlips(a, b))
      continue;
    failedEdges.push_back({ a, b });
  }
  return true;
}

// Gives each failed (sub)segment still missing a Steiner point (by cones first with segmentCones, else at
// its midpoint) while the budget lasts, counting them in steinerUsed. True when any was split.
bool splitFailedEdges(Recoverer& rec, MeshEditor& ed, BoundaryConstraints& bc,
                      const std::vector<std::pair<int32_t, int32_t>>& failedEdges, bool segmentCones, int64_t budget,
                      int64_t& steinerUsed)
{
  bool changed = false;
  for (auto [a, b] : failedEdges)
  {
    if (!bc.isEdge(a, b) || ed.findEdge(a, b) >= 0 || steinerUsed >= budget)
      continue;
    const int64_t before = rec.steinerSegment + rec.steinerFacet;
    if ((segmentCones && rec.splitEdgeByCones(a, b, static_cast<size_t>(budget - steinerUsed))) || rec.splitEdge(a, b))
    {
      steinerUsed += rec.steinerSegment + rec.steinerFacet - before;
      changed = true;
    }
  }
  return changed;
}

// The live subfaces that are not faces of the mesh, in subface order.
void collectMissingFaces(MeshEditor& ed, BoundaryConstraints& bc, BoundaryCensus& census,
                         std::vector<int32_t>& missingFaces)
{
  missingFaces.clear();
  if (!census.upToDate(ed, bc))
    census.take(ed, bc);
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f) && census.faceCode(f) < 0)
      missingFaces.push_back(f);
}

// The missing subfaces of fallback triangles (whose cavity recovery failed) whose three edges are present,
// recovered one by one by flips while the work lasts (workLimit edge removals; outOfWork is set once it is
// spent); those that stay missing go to failedFaces. True when a subface still lacks an edge (the edge
// stage of the next round recovers it).
bool recoverFallbackFacets(Recoverer& rec, MeshEditor& ed, BoundaryConstraints& bc,
                           const std::vector<int32_t>& missingFaces, const std::vector<char>& fallback,
                           uint64_t workLimit, bool& outOfWork, std::vector<int32_t>& failedFaces)
{
  failedFaces.clear();
  bool edgesNeeded = false;
  for (int32_t f : missingFaces)
  {
    if (!bc.alive(f) || !fallback[static_cast<size_t>(bc.parent[f])])
      continue;
    const int32_t* s = bc.subface(f);
    if (ed.findFace(s[0], s[1], s[2]) >= 0)
      continue;
    if (ed.findEdge(s[0], s[1]) < 0 || ed.findEdge(s[1], s[2]) < 0 || ed.findEdge(s[2], s[0]) < 0)
    {
      edgesNeeded = true;
      continue;
    }
    if (ed.removalAttempts > workLimit)
      outOfWork = true;
    if (outOfWork || !rec.recoverFacetByFlips(s[0], s[1], s[2]))
      failedFaces.push_back(f);
  }
  return edgesNeeded;
}

// Gives each failed subface still missing a Steiner point (Recoverer::splitFacet) while the budget lasts,
// counting them in steinerUsed. True when any was split.
bool splitFailedFacets(Recoverer& rec, MeshEditor& ed, BoundaryConstraints& bc, const std::vector<int32_t>& failedFaces,
                       int64_t budget, int64_t& steinerUsed)
{
  bool changed = false;
  for (int32_t f : failedFaces)
  {
    if (!bc.alive(f) || steinerUsed >= budget)
      continue;
    const int32_t* s = bc.subface(f);
    if (ed.findFace(s[0], s[1], s[2]) >= 0)
      continue;
    if (rec.splitFacet(f))
    {
      ++steinerUsed;
      changed = true;
    }
  }
  return changed;
}

} // namespace

// Stop adding Steiner points after this many consecutive rounds in which the number of missing edges grew.
static constexpr int kMaxGrowingRounds = 3;
// Work budget of the flip stages, in edge-removal attempts: kWorkPerMissingEdge per initially missing edge
// plus kWorkBase. Most cases need far less (< 10 per missing edge); CAD models with long thin triangles
// need up to ~1000. Once it is spent, flips stop and what is missing gets Steiner points (bounded by the
// Steiner budget and the growth guard), so hopeless cases still end in seconds.
static constexpr uint64_t kWorkPerMissingEdge = 1000, kWorkBase = 100000;

Status recoverBoundary(MeshEditor& ed, BoundaryConstraints& bc, std::vector<VertexKind>& kinds,
                       const RecoveryOptions& options, Progress* progress, RecoveryReport* report)
{
  const auto t0 = std::chrono::steady_clock::now();
  SilentProgress silent;
  Progress* pr = progress ? progress : &silent;
  RecoveryReport rep;
  Recoverer rec(ed, bc, kinds);
  const int64_t budget =
    options.maxSteinerPoints >= 0 ? options.maxSteinerPoints : 4 * static_cast<int64_t>(bc.numInputTriangles()) + 1000;
  const uint64_t f23 = ed.flips23, f32 = ed.flips32, fer = ed.flipsEdgeRemoval;
  std::vector<std::pair<int32_t, int32_t>> missingEdges;
  std::vector<int32_t> missingFaces;
  std::vector<std::pair<int32_t, int32_t>> failedEdges;
  std::vector<int32_t> failedFaces;
  bool first = true, firstFacets = true;
  int64_t steinerUsed = 0;
  size_t prevMissing = 0;
  int growing = 0;
  uint64_t workLimit = 0;
  bool outOfWork = false;
  // Input triangles whose cavity recovery failed: their inner subface edges are recovered one by one
  // (flips, then Steiner points) like the segments. Other triangles only need their segments: the cavity
  // retetrahedralization (FacetRecovery.h) triangulates their interior.
  std::vector<char> fallback(static_cast<size_t>(bc.numInputTriangles()), 0);
  auto requiredEdge = [&](int32_t a, int32_t b)
  {
    const std::array<int32_t, 2>* ef = bc.edgeFaces(a, b);
    if (!ef)
      return false;
    const int32_t f0 = (*ef)[0], f1 = (*ef)[1];
    if (f0 < 0 || f1 < 0 || bc.parent[f0] != bc.parent[f1])
      return true; // a (sub)segment
    return fallback[static_cast<size_t>(bc.parent[f0])] != 0;
  };
  FacetCavityStats cavityStats;
  BoundaryCensus census;
  // Missing required subface edges, in subface order (the order recovery tries them in); `only`: those
  // on these input segments.
  auto collectMissingEdges = [&](const std::unordered_set<uint64_t>* only)
  {
    missingEdges.clear();
    if (!census.upToDate(ed, bc))
      census.take(ed, bc);
    census.forEachSubfaceEdge(bc,
                              [&](int32_t, int32_t a, int32_t b, int32_t id, bool first)
                              {
                                if (first && (id < 0 || !census.edgePresent(id)) && requiredEdge(a, b) &&
                                    (!only || only->count(bc.segmentOf(a, b))))
                                  missingEdges.push_back({ a, b });
                              });
  };
  if (options.presplitSegments && !options.presplitSegments->empty() && options.allowSteiner)
  {
    // Presplit stage (see RecoveryOptions::presplitSegments). At most one presplit point per input triangle: beyond
    // that (segments of needle triangles, whose pieces would have to be as short as the needles are thin) the retry
    // would only end in a slow Steiner removal of thousands of points.
    const int64_t presplitBudget = std::min<int64_t>(budget, bc.numInputTriangles());
    const bool converged = presplit(rec, ed, bc, *options.presplitSegments, presplitBudget, collectMissingEdges,
                                    missingEdges, steinerUsed, rep);
    if (!converged)
    {
      rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (report)
        *report = rep;
      return Status::failure(ErrorKind::RecoveryFailed,
                             "Boundary recovery failed: splitting the listed segments did not make them edges within " +
                               std::to_string(presplitBudget) + " Steiner points (needle-thin triangles).");
    }
  }
  for (int round = 0; round < 100000; ++round)
  {
    if (pr->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Boundary recovery was cancelled.");
    collectMissingEdges(nullptr);
    if (first)
    {
      rep.missingEdgesInitially = static_cast<int64_t>(missingEdges.size());
      workLimit = ed.removalAttempts + kWorkBase + kWorkPerMissingEdge * missingEdges.size();
    }
    first = false;
    if (!flipMissingEdges(rec, ed, bc, missingEdges, workLimit, outOfWork, failedEdges, *pr))
      return Status::failure(ErrorKind::Cancelled, "Boundary recovery was cancelled.");
    // Divergence guard: Steiner points that only make more edges go missing will not converge.
    if (round > 0 && missingEdges.size() > prevMissing)
      ++growing;
    else
      growing = 0;
    prevMissing = missingEdges.size();
    if (growing >= kMaxGrowingRounds)
      break;
    if (!failedEdges.empty())
    {
      if (!options.allowSteiner || steinerUsed >= budget)
        break;
      if (splitFailedEdges(rec, ed, bc, failedEdges, options.segmentCones, budget, steinerUsed))
        continue;
      break; // nothing could be split
    }
    // All edges present: facets.
    collectMissingFaces(ed, bc, census, missingFaces);
    if (firstFacets)
      rep.missingFacetsInitially = static_cast<int64_t>(missingFaces.size());
    firstFacets = false;
    if (missingFaces.empty())
      break;
    const Status cavities = recoverFacetCavities(ed, bc, missingFaces, fallback, cavityStats, *pr);
    if (!cavities.ok())
      return cavities;
    const bool edgesNeeded =
      recoverFallbackFacets(rec, ed, bc, missingFaces, fallback, workLimit, outOfWork, failedFaces);
    if (failedFaces.empty() || edgesNeeded)
      continue; // re-check edges (flips never remove constraint edges, so this ends quickly)
    if (!options.allowSteiner || steinerUsed >= budget)
      break;
    if (!splitFailedFacets(rec, ed, bc, failedFaces, budget, steinerUsed))
      break;
  }

  const std::vector<int64_t> ids = finalCensus(ed, bc, census, rep);
  rep.facetCavities = static_cast<int64_t>(cavityStats.successes);
  rep.facetCavityEnlargements = static_cast<int64_t>(cavityStats.enlargements);
  rep.steinerSegment = rec.steinerSegment;
  rep.splitSegments = bc.splitSegments();
  rep.steinerFacet = rec.steinerFacet;
  rep.flips23 = ed.flips23 - f23;
  rep.flips32 = ed.flips32 - f32;
  rep.flipsEdgeRemoval = ed.flipsEdgeRemoval - fer;
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (report)
    *report = rep;
  if (rep.unrecoveredEdges || rep.unrecoveredFacets)
  {
    return Status::failure(ErrorKind::RecoveryFailed,
                           "Boundary recovery failed: " + std::to_string(rep.unrecoveredEdges) + " edge(s) and " +
                             std::to_string(rep.unrecoveredFacets) + " facet(s) could not be recovered (" +
                             std::to_string(steinerUsed) + " Steiner points used" +
                             (options.allowSteiner ? "" : ", Steiner points disabled") +
                             (outOfWork                        ? ", flip work budget exhausted"
                                : growing >= kMaxGrowingRounds ? ", missing edges kept growing"
                                : steinerUsed >= budget        ? ", Steiner budget exhausted"
                                                               : "") +
                             "); first input triangles listed.",
                           ids);
  }
  return Status::success();
}

} // namespace volgrid
