// A layered mesh (Core/Mesher/LayeredMesher.h: prisms on the walls, tets elsewhere) as VTK data sets,
// shared by vtkVolGridTetrahedralize and `volgrid mesh --layers`.
#ifndef VolGridLayeredConversion_h
#define VolGridLayeredConversion_h

#include "vtkVolGridFiltersModule.h" // for export macro

class vtkPolyData;
class vtkUnstructuredGrid;
namespace volgrid
{
struct LayeredMeshResult;
}

// The volume: VTK_WEDGE cells (the prisms, first), VTK_PYRAMID cells (over collapsed columns) and VTK_TETRA
// cells, with the cell arrays LayerIndex (-1 for the tets outside the layers), ThinnedReason (Core's ThinnedReason of the column) and Region,
// and PatchNames as field data. The boundary (may be null): the boundary triangles and the prisms' side
// quads on symmetry planes, with PatchId and PatchNames. Replaces the data sets' points and cells.
VTKVOLGRIDFILTERS_EXPORT void VolGridFillFromLayeredResult(const volgrid::LayeredMeshResult& result,
                                                           vtkUnstructuredGrid* volume, vtkPolyData* boundary);

#endif
