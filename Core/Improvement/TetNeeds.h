// The angle each tet must reach, for edits that aim at every tet reaching it rather than at the worst tet
// (InteriorPolish.h): a tet with no vertex on the boundary needs interiorQ, one touching the boundary
// boundaryQ (sine qualities, tetSineQuality in TetEditor.h).
//
// An edit judged by it raises the smallest score, min(1, quality / need), of the tets it replaces, and
// keeps what a user relies on: no new tet under the floor (the mesh's worst tet at the start: worstQ), none
// under its need unless it is at least the worst tet it replaces, no more tets under 10 degrees where it
// edits, and, with counts, a share of tets under 10 degrees in the whole mesh no higher than at the start.
#pragma once

#include "Quality.h"
#include "TetEditor.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace volgrid
{

// Issue 16's range for tets with no boundary vertex: every dihedral angle in [15, 165] degrees.
constexpr double kInteriorDegrees = 15;

struct TetNeeds
{
  const TetMesh* mesh = nullptr;
  const std::vector<uint8_t>* boundaryVertex = nullptr; // non-zero: on the boundary
  double interiorQ = 0, boundaryQ = 0;
  // The lowest quality any edit may leave: the mesh's worst tet when the edits start (of both its smallest
  // dihedral angle and 180 minus its largest, so that neither gets worse).
  double worstQ = 0;
  // Optional: the mesh's tets and tets under 10 deg now, kept by the edits that pay (record()), and at the
  // start; an edit that removes tets would otherwise raise the share under 10 deg.
  struct Counts
  {
    int64_t tets = 0, below10 = 0, startTets = 0, startBelow10 = 0;
  };
  Counts* counts = nullptr;

  bool onBoundary(int32_t v) const
  {
    return static_cast<size_t>(v) >= boundaryVertex->size() || (*boundaryVertex)[static_cast<size_t>(v)];
  }
  bool touchesBoundary(const int32_t* w) const
  {
    return onBoundary(w[0]) || onBoundary(w[1]) || onBoundary(w[2]) || onBoundary(w[3]);
  }
  double need(const int32_t* w) const { return touchesBoundary(w) ? boundaryQ : interiorQ; }
  double score(const int32_t* w, double q) const { return std::min(1.0, q / need(w)); }

  // What the tets an edit replaces have: their smallest score, their worst quality, how many have a dihedral
  // angle under 10 deg (what the share under 10 deg counts, DihedralSummary::below10), how many there are.
  struct Region
  {
    double score = 2, worst = 2;
    int below10 = 0, tets = 0;
  };
  Region region(const TetMesh& m, const std::vector<int32_t>& tets) const
  {
    Region r;
    for (int32_t t : tets)
      add(r, m.vertices(t), quality(m, m.vertices(t)));
    return r;
  }
  void add(Region& r, const int32_t* w, double q) const
  {
    r.score = std::min(r.score, score(w, q));
    r.worst = std::min(r.worst, q);
    r.below10 += under10(w, q);
    ++r.tets;
  }
  // The lowest quality a tet of need n may take when it had q (q itself when lower). A hair over the level:
  // an edit pushes tets against their floors, and a tet left at exactly 10 or 15 degrees would fall on
  // either side of the line in another program's arithmetic (ParaView's, a solver's).
  double floor(double q, double n) const { return std::min(q, std::max(n, worstQ) * kFloorMargin); }
  static constexpr double kFloorMargin = 1 + 1e-9;
  static constexpr double kSine10 = 0.17364817766693033; // sin(10 deg)
  // The score of a new tet of quality q replacing tets whose worst was old.worst, or -1 under its floor.
  double newScore(const Region& old, const int32_t* w, double q) const
  {
    const double n = need(w);
    return q < floor(old.worst, n) ? -1.0 : std::min(1.0, q / n);
  }
  // Whether new tets (Region of them, each over its floor) pay for the old ones: a higher smallest score, no
  // more under 10 deg, and with counts no higher share under 10 deg than at the start.
  bool pays(const Region& old, const Region& now) const
  {
    if (!(now.score > old.score) || now.below10 > old.below10)
      return false;
    if (!counts)
      return true;
    const int64_t below10 = counts->below10 + now.below10 - old.below10, tets = counts->tets + now.tets - old.tets;
    return below10 * counts->startTets <= counts->startBelow10 * tets;
  }
  // After an edit that paid: the counts follow it.
  void record(const Region& old, const Region& now) const
  {
    if (!counts)
      return;
    counts->below10 += now.below10 - old.below10;
    counts->tets += now.tets - old.tets;
  }

  // Whether the tet w of sine quality q has a dihedral angle under 10 deg (only a tet under sin(10 deg) can;
  // the margin covers the two computations' rounding).
  bool under10(const int32_t* w, double q) const
  {
    if (!(q < kSine10 * kFloorMargin))
      return false;
    double lo, hi;
    quality::tetDihedralExtremes(mesh->point(w[0]), mesh->point(w[1]), mesh->point(w[2]), mesh->point(w[3]), lo, hi);
    return lo < 10;
  }

  static double quality(const TetMesh& m, const int32_t* w)
  {
    return tetSineQuality(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3]));
  }
};

} // namespace volgrid
