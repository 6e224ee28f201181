// Conversions between VTK surfaces and VolGrid Core's SurfaceMesh, shared by Surface Prep, the mesher
// filter and the CLI.
#ifndef VolGridSurfaceConversion_h
#define VolGridSurfaceConversion_h

#include "vtkType.h"
#include "vtkVolGridFiltersModule.h" // for export macro

#include <cstdint>

class vtkDataSet;
class vtkPolyData;
namespace volgrid
{
struct SurfaceMesh;
}

struct VolGridSurfaceConversionInfo
{
  vtkIdType triangles = 0;    // triangles taken as they are
  vtkIdType polygons = 0;     // quads and polygons triangulated (ear clipping in their plane)
  vtkIdType strips = 0;       // triangle strips split into triangles
  vtkIdType fanFallbacks = 0; // polygons ear clipping could not handle (fan used instead)
  vtkIdType skippedCells = 0; // vertices, lines, volume cells and cells with fewer than 3 points
  vtkIdType invalidCells = 0; // cells with a point id out of range (skipped)
};

/**
 * Appends the 2D cells of `input` (vtkPolyData polys and strips, or the triangle/quad/polygon cells of any
 * other vtkDataSet) to `mesh` as triangles, with all of the input's points (ids shifted by the points
 * already in `mesh`). Patch ids: when `patchArrayName` names an integer-valued cell array of the input,
 * its value for the cell plus `patchOffset`; otherwise `defaultPatch`. Exactly coincident points are not
 * merged here. Returns false when the input has no points or no 2D cells.
 */
VTKVOLGRIDFILTERS_EXPORT bool VolGridAppendSurface(vtkDataSet* input, volgrid::SurfaceMesh& mesh,
                                                   const char* patchArrayName, int32_t patchOffset,
                                                   int32_t defaultPatch, VolGridSurfaceConversionInfo* info = nullptr);

/** Convenience: clears `mesh`, then VolGridAppendSurface with the "PatchId" array (no offset, default -1). */
VTKVOLGRIDFILTERS_EXPORT bool VolGridPolyDataToSurfaceMesh(vtkDataSet* input, volgrid::SurfaceMesh& mesh,
                                                           VolGridSurfaceConversionInfo* info = nullptr);

/**
 * Fills `output` with the points (double precision) and triangles of `mesh`, replacing its contents.
 * When the mesh has patch ids (and `patchArrayName` is not null) they become an int cell array of that
 * name.
 */
VTKVOLGRIDFILTERS_EXPORT void VolGridSurfaceMeshToPolyData(const volgrid::SurfaceMesh& mesh, vtkPolyData* output,
                                                           const char* patchArrayName = "PatchId");

#endif
