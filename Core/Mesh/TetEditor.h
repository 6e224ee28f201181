// TetEditor: local edits of a ghost-free TetMesh that never touch a constrained face. Shared by the grid
// control and quality stages (FieldPoints, MeshSmoothing, MeshOptimization); independent of boundary
// recovery's MeshEditor so that these stages can run on any valid tet mesh (the mesher's output, an
// existing VolGrid mesh for adaptivity, a convex hull in tests).
//
// CONSTRAINED FACES (the boundary the stages must keep)
//   * every face without a neighbour (kNoNeighbor): the domain boundary after exterior removal, or the
//     hull of a ghost-free Delaunay mesh;
//   * every face listed in a FaceConstraints set (sorted vertex triple): interior faces that must stay,
//     e.g. interfaces between two kept regions (RegionRule::KeepAll), or boundary triangles before
//     exterior removal.
//   A vertex is LOCKED (never moved) when it lies on a constrained face, or when the caller locks it.
//   Edits keep every constrained face (same three vertices; it may end up in a new tet on the same side)
//   and never remove a locked vertex (an unlocked one may be left in no tet by a replace(): forgetVertex).
//
// EDITS
//   replace(): old tets out, new tets in (positively oriented, filling the same region); adjacency is
//   rebuilt from the old tets' outer faces. It validates that the new tets' faces match the old outer
//   faces exactly before touching the mesh. New tets inherit the kUser flag bits and the label (optional
//   per-tet-slot vector) of the first old tet, so region tags survive.
//   insertPoint(): Bowyer-Watson insertion (ConflictCavity.h, shared with MeshEditor) whose cavity grows by the exact
//   SoS insphere test from the tet containing the point, never crosses a constrained face, and is shrunk until
//   star-shaped from the point (every cavity boundary face sees the point strictly positively, exact orient3d), so the
//   new tets are all positive whether or not the mesh is Delaunay (e.g. after boundary recovery flips).
#pragma once

#include "ConflictCavity.h"
#include "EditJournal.h"
#include "MeshNavigator.h"
#include "TetMesh.h"
#include "VertexKeys.h"

#include <array>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace volgrid
{

// A set of faces, keyed by their sorted vertex triple (orientation ignored).
class FaceConstraints
{
public:
  void add(int32_t a, int32_t b, int32_t c) { set_.insert(TriKey(a, b, c)); }
  bool contains(int32_t a, int32_t b, int32_t c) const { return !set_.empty() && set_.count(TriKey(a, b, c)) != 0; }
  size_t size() const { return set_.size(); }
  bool empty() const { return set_.empty(); }
  void clear() { set_.clear(); }
  // Adds 3 x n vertex ids (e.g. the input boundary triangles mapped to mesh vertices).
  void addTriangles(const int32_t* tris, size_t n);

private:
  std::unordered_set<TriKey, TriKeyHash> set_;
};

// Quality used by the improvement stages: the minimum over the six edges of the sine of the dihedral
// angle, negative when the tet is inverted (sign of the volume), 0 when flat or degenerate. It penalises
// small AND large dihedral angles alike: q >= sin(15 deg) means every dihedral angle is in [15, 165].
// (Ordering by q is ordering by min(theta_min, 180 - theta_max).)
double tetSineQuality(const double* a, const double* b, const double* c, const double* d);
// min(theta_min, 180 - theta_max) in degrees from a sine quality (asin clamp).
double sineQualityToDegrees(double q);

// The vertex map, star, findEdge/findFace and stamps are MeshNavigator's (shared with MeshEditor; stale map
// entries are trusted: the edits and forgetVertex keep them exact).
class TetEditor : public MeshNavigator
{
public:
  // constraints and labels may be null. labels (one entry per tet slot) is resized as tets are created.
  TetEditor(TetMesh& mesh, const FaceConstraints* constraints = nullptr, std::vector<int32_t>* labels = nullptr,
            VertexMap map = VertexMap::Kept);

  const FaceConstraints* constraints;
  // labels and the undo log (journal) are MeshNavigator's: replace() and the insertions keep both.

  bool isConstrainedFace(int32_t t, int i) const
  {
    if (mesh.neighborCode(t, i) < 0)
      return true;
    if (!constraints || constraints->empty())
      return false;
    int32_t f[3];
    mesh.faceVertices(t, i, f);
    return constraints->contains(f[0], f[1], f[2]);
  }

  // Per-vertex lock flags: 1 for vertices of constrained faces and for vertices used by no tet.
  std::vector<uint8_t> lockedVertices() const;

  // The distinct vertices adjacent to v (sharing an edge), from its star.
  void neighbors(int32_t v, const std::vector<int32_t>& starTets, std::vector<int32_t>& out);

  // The ring around interior edge xy given a live tet t containing it: ring vertices r_i and tets
  // {x,y,r_i,r_i+1} with orient3d(x,y,r_i,r_i+1) > 0. False when the ring is open (edge on the boundary),
  // when a face around the edge is constrained, or when the ring has more than maxRing tets.
  bool edgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring, std::vector<int32_t>& tets,
                int maxRing = 64) const;

  // Replace oldTets (at least one) by newTets (vertex quadruples, positively oriented, filling the same
  // region): MeshNavigator::replaceTets, closed regions only. False (mesh untouched) when the faces do not
  // match. created (optional) receives the new tet ids. With regionLimit, only when every old tet is the
  // region's, and with slotPool only when it has the slots; else false with lastReplaceDeferred set.
  bool replace(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets,
               std::vector<int32_t>* created = nullptr);
  bool lastReplaceDeferred = false;

  // Visibility walk from `start` to a tet whose closure contains p; -1 if the walk leaves the mesh
  // (p outside, or behind a boundary concavity) or does not converge.
  int32_t locate(const double* p, int32_t start) const;
  // Walk, then a scan of all tets if the walk failed. -1 when no tet contains p.
  int32_t locateRobust(const double* p, int32_t start) const;

  enum class InsertStatus
  {
    Inserted,
    NotInside, // p is outside the start tet's closure, or on a constrained face
    TooClose,  // a cavity vertex is closer than minDistance
    NoCavity,  // no valid star-shaped cavity (would swallow a vertex); nothing changed
    Deferred   // with a region: the cavity needs a tet outside it, or more slots than slotPool has; nothing changed
  };
  // Optional limit for a thread that edits one region of the mesh while others edit theirs
  // (FieldPointRegions.h, RegionFlips.h): vertexRegion[v] is v's region, and insertPoint() and replace()
  // remove only tets whose four vertices are all in `region` (else Deferred). Tets of two different regions never share
  // a face, so the cavity's outer neighbours are then this region's tets or tets no thread removes.
  struct RegionLimit
  {
    const uint8_t* vertexRegion = nullptr;
    uint8_t region = 0;
    bool owns(const int32_t* w) const
    {
      return vertexRegion[w[0]] == region && vertexRegion[w[1]] == region && vertexRegion[w[2]] == region &&
        vertexRegion[w[3]] == region;
    }
  };
  const RegionLimit* regionLimit = nullptr;
  // Insert vertex v (coordinates already in mesh.points, used by no tet) whose position lies in the
  // closure of tet `start`. Rejects it when a vertex of the cavity (which contains the nearest vertex in a
  // Delaunay mesh) is closer than minDistance. nearest (optional) receives that distance.
  InsertStatus insertPoint(int32_t v, int32_t start, double minDistance = 0, double* nearest = nullptr,
                           std::vector<int32_t>* created = nullptr);

  // Quality-driven insertion (after Klingner and Shewchuk's smart vertex insertion) of vertex v
  // (coordinates in mesh.points, used by no tet) lying in the closure of tet `start`: the cavity starts
  // from `start` (with mustReplace >= 0: the shortest path of at most 5 tets from `start` to mustReplace)
  // and grows one tet at a time across the unconstrained face that makes the worst new tet; the cavity
  // (star-shaped from v, every cavity vertex on its boundary) whose worst new tet is best is kept. Returns that worst
  // new quality (tetSineQuality), or -3 when there is no valid cavity or when mustReplace >= 0 is not in it;
  // replacedQuality (optional) receives the worst replaced tet's quality. commit = false leaves the mesh untouched (to
  // compare positions); true inserts v with that cavity. mustBeat: only cavities whose worst new tet is above it count
  // (-3 when none; prunes the search).
  double qualityInsertion(int32_t v, int32_t start, int32_t mustReplace, double* replacedQuality, bool commit,
                          std::vector<int32_t>* created = nullptr, int maxCavity = 24, double mustBeat = -3);

  // After qualityInsertion(v, ..., commit = false) found a cavity (nothing edited since): how many of the
  // tets it would create (newBelow) and of the tets it would replace (oldBelow) have a sine quality under q.
  void countBelowInLastCavity(int32_t v, double q, int& newBelow, int& oldBelow);
  // The same cavity: the interior faces whose centroid line and normal are further apart than severeCosine
  // allows (|cos| under it: a solver's severely non-orthogonal faces), among the faces of the tets it would
  // create less those among the faces of the tets it would replace. Both include the cavity's boundary
  // faces, towards the tets beyond, so the difference is the mesh's change.
  int severeChangeOfLastCavity(int32_t v, double severeCosine);

  // Optional: what qualityInsertion maximises instead of the worst new tet's quality (tetSineQuality): the
  // smallest score(new tet, its quality), a score in (0, 1] (InteriorPolish.h: the quality over the angle
  // the tet must reach). Its return value is then that score. Null (the default): the quality.
  struct ConeScore
  {
    virtual ~ConeScore() = default;
    virtual double operator()(const int32_t tet[4], double quality) const = 0;
  };
  const ConeScore* coneScore = nullptr;
  // The cavity the last qualityInsertion(commit = false) found (nothing edited since): the tets it replaces.
  const std::vector<int32_t>& lastCavity() const { return bestCavity_; }

  uint64_t replacements = 0;

private:
  // insertPoint()'s steps.
  // The cone of v over the cavity's boundary faces into coneTets_; with p (null: checked already), false as soon as a
  // face does not see p strictly (the cavity is not star-shaped).
  bool buildCone(int32_t v, const double* p);
  // Inserted when every cavity vertex is on the cone and none is closer to p than minDistance (nearest:
  // the distance to the closest); NoCavity or TooClose otherwise.
  InsertStatus checkCavityVertices(int32_t v, const double* p, double minDistance, double* nearest);
  // qualityInsertion()'s steps.
  // The first cavity: start, or the shortest path of at most 5 tets from start to mustReplace (false when
  // there is none).
  bool seedQualityCavity(int32_t start, int32_t mustReplace);
  // The faces of cavity tet t on the cavity's boundary, with the quality of v's tet over each, into cone_.
  void addConeFaces(int32_t v, int32_t t);
  // Whether every vertex of the cavity is on cone_ (else the cone would swallow it).
  bool coneKeepsCavityVertices();
  // Adds tet u to the cavity and drops the cone faces it covers.
  void growCavity(int32_t u);
  // Grows the seed one tet at a time across the unconstrained face with the worst new tet; keeps the
  // valid cavity with the best worst new tet above mustBeat in bestCavity_. Returns its worst quality, -3
  // when none.
  double growByQuality(int32_t v, int maxCavity, double mustBeat);

  ConflictCavity cavity_{ *this };
  std::vector<int32_t> seed_, vstamp_, bestCavity_;
  std::vector<std::pair<int32_t, int32_t>> bfsTets_; // (tet, index of its parent)
  struct ConeFace
  {
    int32_t tet;
    int face;
    bool constrained;
    double quality; // of the tet from the new vertex over this face; -1 when not strictly positive
  };
  std::vector<ConeFace> cone_;
  Cone coneTets_;
  // severeChangeOfLastCavity()'s scratch: the cone's centroids and its side faces (base edge, cone tet).
  std::vector<std::array<double, 3>> coneCentroids_;
  std::vector<std::pair<int64_t, int32_t>> coneSides_;
};

} // namespace volgrid
