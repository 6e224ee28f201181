// The quality stage's sizing field (MeshImprovement.h step 2), built once before the field points: the
// boundary PDF (eq. 3) at the surface points, the clustering sizes, the background cloud or callback, a
// lattice of unbounded nodes so that the gradation grows the size away from the boundary, graded and
// capped (SizingField.h), then sampled on an octree that the field points query.
#pragma once

#include "MeshImprovement.h"

namespace volgrid
{

// Builds the field the field points query into `fast` (a callback of an octree it keeps alive) from the
// options and the boundary `surface`; `mesh` gives the box. stats.latticeNodes is set.
// Errors: those of SizingField::build (bad sizes), Cancelled.
Status buildDomainSizing(const TetMesh& mesh, const SurfaceMesh& surface, const ImprovementOptions& options,
                         SizingField& fast, ImprovementStatistics& stats, Progress* progress);

} // namespace volgrid
