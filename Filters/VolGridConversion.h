// Conversions between VolGrid Core's structures and VTK data sets, shared by the filters and the CLI.
#ifndef VolGridConversion_h
#define VolGridConversion_h

#include "vtkType.h"
#include "vtkVolGridFiltersModule.h" // for export macro

#include <cstdint>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;
namespace volgrid
{
class TetMesh;
struct MesherResult;
}

// Fills `grid` with the finite tets of `mesh` (VTK_TETRA cells, same vertex order, so positive volume)
// and the points of the listed mesh vertices: output point o is mesh vertex keptVertices[o]. Every vertex
// used by a tet must be listed. Replaces the grid's points and cells.
VTKVOLGRIDFILTERS_EXPORT void VolGridFillUnstructuredGrid(
  const volgrid::TetMesh& mesh, const std::vector<int32_t>& keptVertices, vtkUnstructuredGrid* grid);

// Fills `volume` with the mesher's points and tets (cell arrays Region and Forced) and `boundary` (may be null) with
// the same points and the boundary triangles (cell array PatchId). Replaces their points, cells and the
// named arrays; other arrays are left to the caller. Forced (unsigned char): 1 where the input surface
// forces the tet's shape (MesherResult::tetForced).
VTKVOLGRIDFILTERS_EXPORT void VolGridFillFromMesherResult(
  const volgrid::MesherResult& result, vtkUnstructuredGrid* volume, vtkPolyData* boundary);

#endif
