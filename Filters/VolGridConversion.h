// Conversions between VolGrid Core's structures and VTK data sets, shared by the filters and the CLI.
#ifndef VolGridConversion_h
#define VolGridConversion_h

#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkVolGridFiltersModule.h" // for export macro

#include <cstdint>
#include <map>
#include <string>
#include <vector>

class vtkDataObject;
class vtkIntArray;
class vtkPolyData;
class vtkUnstructuredGrid;
namespace volgrid
{
class TetMesh;
struct MesherResult;
struct SolverMesh;
}

// Fills `grid` with the finite tets of `mesh` (VTK_TETRA cells, same vertex order, so positive volume)
// and the points of the listed mesh vertices: output point o is mesh vertex keptVertices[o]. Every vertex
// used by a tet must be listed. Replaces the grid's points and cells.
VTKVOLGRIDFILTERS_EXPORT void VolGridFillUnstructuredGrid(const volgrid::TetMesh& mesh,
                                                          const std::vector<int32_t>& keptVertices,
                                                          vtkUnstructuredGrid* grid);

// The cell array BoundaryFacePatch of a tet grid: 4 components, component k the patch of the tet's face
// that is Exodus II side k + 1 (volgrid::kExodusTetSide: vertices 013, 123, 032, 021, outward), -1 where
// that face is not a boundary triangle. It carries the patches on the volume output itself, so that a
// writer given only the volume (ParaView's Save Data) still writes every patch.
VTKVOLGRIDFILTERS_EXPORT vtkSmartPointer<vtkIntArray> VolGridBoundaryFacePatch(const std::vector<int32_t>& tets,
                                                                               const std::vector<int32_t>& triangles,
                                                                               const std::vector<int32_t>& patches);

// Fills `volume` (may be null) with the mesher's points and tets (cell arrays Region, Forced and
// BoundaryFacePatch) and `boundary` (may be null) with
// the same points and the boundary triangles (cell array PatchId). Replaces their points, cells and the
// named arrays; other arrays are left to the caller. Forced (unsigned char): 1 where the input surface
// forces the tet's shape (MesherResult::tetForced).
VTKVOLGRIDFILTERS_EXPORT void VolGridFillFromMesherResult(const volgrid::MesherResult& result,
                                                          vtkUnstructuredGrid* volume, vtkPolyData* boundary);

// Adds the field-data string array `arrayName` to `data`: entry L (0..max label in `labels`) is the name
// of label L (its name in `names`, or "<prefix>L"); negative labels have no entry. Replaces an array of
// that name.
VTKVOLGRIDFILTERS_EXPORT void VolGridSetLabelNames(vtkDataObject* data, const char* arrayName,
                                                   const std::vector<int32_t>& labels,
                                                   const std::map<int32_t, std::string>& names, const char* prefix);

// The names in a field-data string array written by VolGridSetLabelNames (entry L names label L; a
// missing array gives no names).
VTKVOLGRIDFILTERS_EXPORT std::map<int32_t, std::string> VolGridReadLabelNames(vtkDataObject* data,
                                                                              const char* arrayName);

// PatchNames (of result.boundaryPatch) on both outputs and RegionNames (of result.tetRegion) on the
// volume; either may be null.
VTKVOLGRIDFILTERS_EXPORT void VolGridSetPatchAndRegionNames(const volgrid::MesherResult& result,
                                                            const std::map<int32_t, std::string>& patchNames,
                                                            const std::map<int32_t, std::string>& regionNames,
                                                            vtkUnstructuredGrid* volume, vtkPolyData* boundary);

// A solver's mesh (Core/IO/MeshReader.h) as VTK data: `volume` gets the tets with Region, PatchNames and
// RegionNames and the point fields as point arrays; `boundary` (may be null) the boundary triangles with
// PatchId and PatchNames. With prisms or pyramids, VolGridFillFromMixedSolverMesh's grid (and the point
// fields).
VTKVOLGRIDFILTERS_EXPORT void VolGridFillFromSolverMesh(const volgrid::SolverMesh& mesh, vtkUnstructuredGrid* volume,
                                                        vtkPolyData* boundary);

#endif
