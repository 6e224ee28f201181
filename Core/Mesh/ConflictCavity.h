// ConflictCavity: the cavity of a vertex insertion, searched once for both mesh editors (MeshEditor's
// insertVertex for recovery, TetEditor's insertPoint and qualityInsertion for refinement and improvement).
// Bowyer-Watson growth from root tets across the faces a caller's rule allows, a shrink until the cavity is
// strictly star-shaped from the new point (exact orient3d), and the walk over its boundary faces that the
// caller turns into the cone of new tets.
//
// The caller's Rule (each editor keeps its own insphere and its own constrained faces):
//   bool blocks(int32_t t, int i)  growth never crosses face i of cavity tet t
//   bool wall(int32_t t, int i)    face i of t bounds the cavity even with the tet beyond inside it, and the
//                                  connected part is never joined across it
//   (Hull faces always stop growth and bound the cavity; neither is asked about them, and both are asked
//   only when the tet beyond matters, as they may be hash look-ups.)
//   bool conflicts(int32_t u)      u is in conflict with the point (the insphere rule)
//   bool mustKeep(int32_t t)       the cavity cannot do without t (its closure holds the point): the
//                                  shrink fails rather than drop it
//   static constexpr bool kBlocksAreWalls: blocks() == wall(), so growth is already in connected order
#pragma once

#include "MeshNavigator.h"
#include "PredicatesInline.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

class ConflictCavity
{
public:
  explicit ConflictCavity(MeshNavigator& nav)
    : nav_(nav)
  {
  }
  // The cavity's tets, in the order the cone is built from.
  std::vector<int32_t> tets;
  bool contains(int32_t t) const { return t >= 0 && nav_.tetStamp[t] == stamp_; }

  // A new cavity holding the n tets of `roots` (marked with a fresh stamp).
  void start(const int32_t* roots, size_t n);
  // Adds tet u (not in the cavity yet).
  void add(int32_t u)
  {
    nav_.tetStamp[u] = stamp_;
    tets.push_back(u);
    // Its faces are read when growth reaches it: the load starts now (the cavity's tets are scattered
    // through memory, and growth waited on each load in turn).
    __builtin_prefetch(&nav_.mesh.tetNeighbors[4 * static_cast<size_t>(u)]);
  }
  // Unmarks the cavity's tets (after a refused insertion).
  void release();

  // Bowyer-Watson: breadth first from the tets so far, across faces rule.blocks() allows, into tets
  // rule.conflicts() accepts (each tested once), until the cavity holds maxTets tets or more.
  template<class Rule>
  void grow(Rule& rule, size_t maxTets);
  // Drops tets with a boundary face that does not see p strictly, keeping the part connected to the roots,
  // until nothing changes or maxRounds passes ran. False (cavity released) when a rule.mustKeep() tet
  // would go. The cavity ends in breadth-first order from the roots.
  template<class Rule>
  bool shrinkToStar(const double* p, Rule& rule, const int32_t* roots, size_t n, int maxRounds);
  // Whether the last shrinkToStar() ended with a pass that found every boundary face seeing p strictly (so
  // the cone needs no second orient3d per face); false when it stopped at maxRounds.
  bool starShaped() const { return starShaped_; }
  // Calls emit(t, i) for each boundary face i of cavity tet t, in cavity order; stops and returns false
  // as soon as emit does.
  template<class Rule, class Emit>
  bool forBoundaryFaces(Rule& rule, Emit&& emit) const;

private:
  // One pass of the shrink: 1 when it dropped a tet, 0 when none, -1 when a rule.mustKeep() tet would go.
  template<class Rule>
  int dropInvisible(const double* p, Rule& rule);
  // Keeps the part connected to the roots across non-wall faces, in breadth-first order.
  template<class Rule>
  void keepConnected(Rule& rule, const int32_t* roots, size_t n);
  // A face on the cavity's boundary: the hull, a face to a tet outside, or a wall (asked last: it may be
  // a hash look-up).
  template<class Rule>
  bool boundaryFace(Rule& rule, int32_t t, int i) const
  {
    const int32_t u = nav_.mesh.neighbor(t, i);
    return u < 0 || nav_.tetStamp[u] != stamp_ || rule.wall(t, i);
  }

  MeshNavigator& nav_;
  uint32_t stamp_ = 0;
  bool starShaped_ = false;
  std::vector<int32_t> queue_;
};

template<class Rule>
void ConflictCavity::grow(Rule& rule, size_t maxTets)
{
  const uint32_t sOut = nav_.newStamp(); // tets tested and found not in conflict
  TetMesh& mesh = nav_.mesh;
  for (size_t k = 0; k < tets.size() && tets.size() < maxTets; ++k)
  {
    const int32_t t = tets[k];
    // The four neighbours' marks and vertices are loaded at once, not one after the other.
    int32_t beyond[4];
    for (int i = 0; i < 4; ++i)
    {
      beyond[i] = mesh.neighbor(t, i);
      if (beyond[i] >= 0)
      {
        __builtin_prefetch(&nav_.tetStamp[beyond[i]]);
        __builtin_prefetch(mesh.vertices(beyond[i]));
      }
    }
    for (int i = 0; i < 4; ++i)
    {
      // Visited tets first: blocks() may be a hash look-up (and is true on the hull).
      const int32_t u = beyond[i];
      if (u < 0 || nav_.tetStamp[u] == stamp_ || nav_.tetStamp[u] == sOut || rule.blocks(t, i))
        continue;
      if (rule.conflicts(u))
        add(u);
      else
        nav_.tetStamp[u] = sOut;
    }
  }
}

template<class Rule>
int ConflictCavity::dropInvisible(const double* p, Rule& rule)
{
  const TetMesh& mesh = nav_.mesh;
  int changed = 0;
  for (int32_t t : tets)
  {
    if (nav_.tetStamp[t] != stamp_)
      continue;
    for (int i = 0; i < 4; ++i)
    {
      if (!boundaryFace(rule, t, i))
        continue;
      int32_t f[3];
      mesh.faceVertices(t, i, f);
      if (predicates::orient3dInline(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p) > 0)
        continue;
      if (rule.mustKeep(t))
        return -1;
      nav_.tetStamp[t] = 0;
      changed = 1;
      break;
    }
  }
  return changed;
}

template<class Rule>
void ConflictCavity::keepConnected(Rule& rule, const int32_t* roots, size_t n)
{
  const uint32_t sConn = nav_.newStamp();
  queue_.clear();
  for (size_t k = 0; k < n; ++k)
  {
    queue_.push_back(roots[k]);
    nav_.tetStamp[roots[k]] = sConn;
  }
  for (size_t k = 0; k < queue_.size(); ++k)
  {
    const int32_t t = queue_[k];
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = nav_.mesh.neighbor(t, i);
      if (u >= 0 && nav_.tetStamp[u] == stamp_ && !rule.wall(t, i))
      {
        nav_.tetStamp[u] = sConn;
        queue_.push_back(u);
      }
    }
  }
  for (int32_t t : tets)
    if (nav_.tetStamp[t] == stamp_)
      nav_.tetStamp[t] = 0;
  tets.swap(queue_);
  stamp_ = sConn;
}

template<class Rule>
bool ConflictCavity::shrinkToStar(const double* p, Rule& rule, const int32_t* roots, size_t n, int maxRounds)
{
  starShaped_ = false;
  for (int round = 0; round < maxRounds; ++round)
  {
    const int changed = dropInvisible(p, rule);
    if (changed < 0)
    {
      release();
      return false;
    }
    // Nothing dropped: every boundary face sees p strictly (and keepConnected() below removes nothing,
    // the cavity being connected already).
    starShaped_ = !changed;
    // Growth across exactly the non-wall faces is already breadth first from the roots: nothing to redo.
    if (!changed && Rule::kBlocksAreWalls)
      break;
    keepConnected(rule, roots, n);
    if (!changed)
      break;
  }
  return true;
}

template<class Rule, class Emit>
bool ConflictCavity::forBoundaryFaces(Rule& rule, Emit&& emit) const
{
  for (int32_t t : tets)
    for (int i = 0; i < 4; ++i)
      if (boundaryFace(rule, t, i) && !emit(t, i))
        return false;
  return true;
}

} // namespace volgrid
