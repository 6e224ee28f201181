// Surface preparation, the sequence behind vtkVolGridSurfacePrep and `volgrid prep`: diagnose the merged
// input, repair it (weld, remove degenerate and duplicate triangles, stitch, fill holes, orient), add a
// far-field enclosure, orient the shells for the domain and diagnose the result; plus the summary rows
// (defects before and after, repair actions) that the filter shows as a table and field data.
#pragma once

#include "Enclosures.h"
#include "Progress.h"
#include "Status.h"
#include "SurfaceChecks.h"
#include "SurfaceMesh.h"
#include "SurfaceRepair.h"

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

struct SurfacePreparationOptions
{
  double mergeTolerance = 1e-6; // weld and stitch tolerance (x bounding-box diagonal); 0: exact only
  bool removeDegenerate = true;
  bool removeDuplicates = true;
  int maxHoleEdges = 200; // 0: leave holes open
  bool orientShells = true;
  bool checkIntersections = true;
  // Enclosure: none, or `explicitEnclosure` as given, or `shape` around the input's bounding box scaled by
  // `enclosureScale` (explicit also when there is no input). Its patch id is the one after the input's.
  bool enclosure = false;
  bool aroundInput = true;
  EnclosureOptions explicitEnclosure;
  EnclosureShape shape = EnclosureShape::Sphere;
  double enclosureScale = 10;
  int axis = 2;
  double enclosureEdgeLength = 0;
  Progress* progress = nullptr; // fractions of the whole preparation
};

struct SurfacePreparationReport
{
  bool haveInput = false;        // the input had triangles (else only an enclosure was built)
  SurfaceCheckReport input;      // topology only (no intersection or nesting test)
  SurfaceRepairReport repair;    // including the shells flipped for the domain
  Status repairStatus;           // a repair that could not finish is a warning, not a failure
  SurfaceCheckReport output;     // full check of the result
  int32_t enclosurePatchId = -1; // -1: no enclosure
  bool meshable = false;         // the result has triangles and passes the checks
};

// Prepares `mesh` in place (the parts already merged into it, patch ids below `nextPatch`). Fails with
// Cancelled when progress->cancelled(), or with the enclosure's InvalidOption; the report is filled so far.
Status prepareSurface(SurfaceMesh& mesh, int32_t nextPatch, const SurfacePreparationOptions& options,
                      SurfacePreparationReport& report);

// One row of the summary: a defect class (input and output counts) or a repair action (output only).
struct SurfacePreparationRow
{
  const char* category; // "defect", "shells", "size", "repair"
  const char* item;     // for people: "Open edges"
  const char* key;      // field-data name (the input's count is "Input" + key)
  int64_t input;        // -1: not measured
  int64_t output;       // -1: not measured
  std::string firstIds; // "triangles 3 7", "triangle pairs (1 2) (4 9)"
};

std::vector<SurfacePreparationRow> surfacePreparationRows(const SurfacePreparationReport& report, int64_t parts);

// Closed, consistent shells whose orientation disagrees with their nesting depth (even depth outward).
int64_t misorientedShells(const SurfaceCheckReport& report);

// The warning for a result that cannot be meshed (its defects with their first ids), or for closed
// shells oriented against the domain; empty when there is nothing to warn about.
std::string surfacePreparationWarning(const SurfacePreparationReport& report,
                                      const std::vector<SurfacePreparationRow>& rows, int32_t triangles);

} // namespace volgrid
