// The quality stage's rule for meshes that a finite-volume solver reads (ImprovementOptions::
// orthogonalityFirst; issue 16, acceptance 6).
//
// The stage raises the worst dihedral angle by edits that each strictly improve the worst tet they
// replace: flips and edge removals (MeshOptimization.h), points that split bad tets (BadTetSplitting.h)
// and the insertion rounds (InsertionImprovement.h). Such an edit may leave more tets under the target
// than it removed, and faces that a solver finds severely non-orthogonal (checkMesh: more than 70 degrees
// between the line joining the two cells' centroids and the face's normal). Measured on the ONERA M6
// domain at default settings: the first optimisation pass leaves 281 severe faces; the splits and the
// insertion rounds, which take the worst angle from 0.03 to 8 degrees, end at 949, and 838 of the 854
// left after the orthogonality moves touch a point they added (in clusters behind the sharp trailing edge).
//
// With the rule on, an edit whose worst replaced tet is at or above kDegenerateDegrees is made only when
// it leaves no more tets under the target than there were, and (splits and insertion rounds, which add a
// point) no more severe faces, among the faces of the tets it changes. Edits for tets under
// kDegenerateDegrees (nearly flat cells, which a solver cannot use either) are made as without the rule.
// Smoothing moves keep the rule too (no more tets under the target nor severe faces in the moved vertex's
// star). The price is dihedral angle. On the same domain (checkMesh): 208 severe faces instead of 854, the
// worst angle 2.4 instead of 8.1 degrees, 0.18% of the tets under 10 degrees instead of 0.05%.
#pragma once

#include "CfdQuality.h"
#include "TetMesh.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace volgrid
{

struct OrthogonalityFirst
{
  static constexpr double kDegenerateDegrees = 2.0;

  bool enabled = false;
  double targetQuality = 0;     // tetSineQuality of the target angle: the tets an edit may not add
  double degenerateQuality = 0; // tetSineQuality of kDegenerateDegrees
  double severeCosine = 0;      // |cos| of checkMesh's severe limit between centroid line and normal

  // The rule for a quality stage aiming at targetDegrees.
  static OrthogonalityFirst forTarget(double targetDegrees)
  {
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    OrthogonalityFirst rule;
    rule.enabled = true;
    rule.targetQuality = std::sin(targetDegrees * kDegree);
    rule.degenerateQuality = std::sin(kDegenerateDegrees * kDegree);
    rule.severeCosine = std::cos(quality::kSevereNonOrthogonality * kDegree);
    return rule;
  }
  // Whether an edit whose worst replaced tet has sine quality qWorst must keep the rule.
  bool binds(double qWorst) const { return enabled && !(qWorst < degenerateQuality); }
};

// What the rule compares before and after an edit, over the tets it changes: how many are under the target,
// how many of their faces are severely non-orthogonal (each interior face once, the faces towards the
// tets beyond included), and the worst tet's sine quality.
struct RegionCounts
{
  int64_t below = 0, severe = 0;
  double worst = 2;
  bool worseThan(const RegionCounts& before) const { return below > before.below || severe > before.severe; }
};
// region: distinct live tets of `mesh`, ascending.
RegionCounts countRegion(const TetMesh& mesh, const std::vector<int32_t>& region, const OrthogonalityFirst& rule);

} // namespace volgrid
