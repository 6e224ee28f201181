// Conversions between VolGrid Core's structures and VTK data sets, shared by the filters and the CLI.
#ifndef VolGridConversion_h
#define VolGridConversion_h

#include "vtkType.h"
#include "vtkVolGridFiltersModule.h" // for export macro

#include <cstdint>
#include <vector>

class vtkUnstructuredGrid;
namespace volgrid
{
class TetMesh;
}

// Fills `grid` with the finite tets of `mesh` (VTK_TETRA cells, same vertex order, so positive volume)
// and the points of the listed mesh vertices: output point o is mesh vertex keptVertices[o]. Every vertex
// used by a tet must be listed. Replaces the grid's points and cells.
VTKVOLGRIDFILTERS_EXPORT void VolGridFillUnstructuredGrid(
  const volgrid::TetMesh& mesh, const std::vector<int32_t>& keptVertices, vtkUnstructuredGrid* grid);

#endif
