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
struct SolverMesh;
}

// The volume: VTK_WEDGE cells (the prisms, first), VTK_PYRAMID cells (over collapsed columns) and VTK_TETRA
// cells, with the cell arrays LayerIndex (-1 for the tets outside the layers), ThinnedReason (Core's
// ThinnedReason of the column), Region and BoundaryFacePatch, and PatchNames as field data.
// BoundaryFacePatch (so that a writer given only the volume, ParaView's Save Data, writes every patch):
// with split prisms (tets only) as VolGridBoundaryFacePatch; else 5 components, component k the patch of
// the cell's Exodus II side k + 1 (Core/IO/BoundaryFaceOwners.h: kExodusTetSide, kExodusWedgeSide,
// kExodusPyramidSide, in Core's vertex order of the cell), -1 where that side is not a boundary face. The boundary (may
// be null): the boundary triangles and the prisms' side quads on symmetry planes, with PatchId and PatchNames. Replaces
// the data sets' points and cells.
// A mesh with prisms and pyramids (a layered result, or a solver file read back) as the volume above
// without LayerIndex and ThinnedReason: VTK_WEDGE, VTK_PYRAMID and VTK_TETRA cells, Region (the cells'
// region labels), BoundaryFacePatch, PatchNames and RegionNames; the boundary (may be null) as above.
VTKVOLGRIDFILTERS_EXPORT void VolGridFillFromMixedSolverMesh(const volgrid::SolverMesh& mesh,
                                                             vtkUnstructuredGrid* volume, vtkPolyData* boundary);

VTKVOLGRIDFILTERS_EXPORT void VolGridFillFromLayeredResult(const volgrid::LayeredMeshResult& result,
                                                           vtkUnstructuredGrid* volume, vtkPolyData* boundary);

#endif
