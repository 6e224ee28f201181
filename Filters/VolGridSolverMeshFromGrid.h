// A VTK grid back into Core's SolverMesh, for the solver writers behind ParaView's Save Data: the tets (and
// with a 5-component BoundaryFacePatch the wedges and pyramids of boundary layers, VolGridLayeredConversion.h),
// Region (else region 1) with RegionNames, and the boundary triangles and quads with their patches from
// the BoundaryFacePatch cell array (VolGridConversion.h) with PatchNames; scalar point arrays as point fields.
#ifndef VolGridSolverMeshFromGrid_h
#define VolGridSolverMeshFromGrid_h

#include <string>

class vtkUnstructuredGrid;
namespace volgrid
{
struct SolverMesh;
}

// False with `error` set when the grid has other cells, no cells, or no BoundaryFacePatch array
// (a solver mesh without its boundary patches would be useless to the solver).
bool VolGridSolverMeshFromGrid(vtkUnstructuredGrid* grid, volgrid::SolverMesh& mesh, std::string& error);

#endif
