// The filters under MPI (pvbatch --mpi, pvserver with N ranks): the surface is gathered onto rank 0, meshed
// there once, and the tets are handed out to the ranks in spatially compact pieces with global point and cell
// ids. Every function here is collective: all ranks of the controller call it together.
#ifndef VolGridParallel_h
#define VolGridParallel_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkDataSet;
class vtkFieldData;
class vtkMultiProcessController;
class vtkPointSet;
class vtkUnstructuredGrid;

/** The global controller when the process runs with more than one rank, else nullptr (serial path). */
vtkMultiProcessController* VolGridParallelController();

/**
 * Gathers the parts of every rank onto rank 0: part slot k of the result holds, in rank order, the pieces
 * of the ranks' local[k] that have cells or points (ghost cells removed). Ranks may pass different numbers
 * of slots (missing ones are empty). Rank 0 gets the slots, the other ranks an empty vector.
 */
std::vector<std::vector<vtkSmartPointer<vtkDataSet>>> VolGridGatherParts(vtkMultiProcessController* controller,
                                                                         const std::vector<vtkDataSet*>& local);

/**
 * Gathers the ranks' pieces of one data set onto rank 0 as one data set (a vtkPolyData when every piece
 * is one, else a vtkUnstructuredGrid); points shared by pieces are repeated (the mesher merges coincident
 * points exactly). Rank 0 gets an empty data set when every piece is empty; the other ranks nullptr.
 */
vtkSmartPointer<vtkPointSet> VolGridGatherPointSet(vtkMultiProcessController* controller, vtkDataSet* local);

/** Rank 0's flag, on every rank. */
bool VolGridBroadcastFlag(vtkMultiProcessController* controller, bool flag);

/**
 * Rank 0 cuts `whole` (ignored on the other ranks) into one spatially compact piece per rank (recursive
 * bisection of the cell centroids) and sends each rank its piece; `piece` receives this rank's cells with
 * the point and cell data, plus the global ids GlobalPointIds (the point's index in `whole`) and
 * GlobalCellIds (the cell's index in `whole`), set as the attributes' global ids.
 */
void VolGridDistributeCells(vtkMultiProcessController* controller, vtkUnstructuredGrid* whole,
                            vtkUnstructuredGrid* piece);

/**
 * Gathers the ranks' pieces of a grid that carries GlobalPointIds and GlobalCellIds onto rank 0 as the one
 * whole grid (points and cells only, in increasing global id order, shared points joined), so that a
 * computation there gives the one-process result. cellsOfRank[r][c] is the index in `whole` of rank r's
 * local cell c (rank 0 only). Returns false on every rank, gathering nothing, when a rank with cells lacks
 * the global ids.
 */
bool VolGridGatherGrid(vtkMultiProcessController* controller, vtkUnstructuredGrid* local,
                       vtkSmartPointer<vtkUnstructuredGrid>& whole, std::vector<std::vector<vtkIdType>>& cellsOfRank);

/**
 * The reverse of VolGridGatherGrid for results: rank 0 sends each rank the cell arrays of `wholeResult`
 * restricted to its cells, and `fieldData` (its summary); every rank adds them to `output`.
 */
void VolGridScatterCellArrays(vtkMultiProcessController* controller, vtkDataSet* wholeResult, vtkFieldData* fieldData,
                              const std::vector<std::vector<vtkIdType>>& cellsOfRank, vtkDataSet* output);

#endif
