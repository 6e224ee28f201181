// The volume-grid paths of vtkVolGridQuality (its header documents the arrays and figures): the tets
// (Core/Quality/Quality.h), the wedges (Core/Quality/PrismQuality.h) and checkMesh's CFD metrics on grids of
// tets, or of tets, wedges and pyramids (Core/Quality/CfdQuality.h).
#ifndef VolGridQualityVolume_h
#define VolGridQualityVolume_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkAlgorithm;
class vtkDoubleArray;
class vtkFieldData;
class vtkUnstructuredGrid;

// Measures the grid's cells: appends the per-cell arrays (every one with a value per cell of the grid, NaN
// on the cells it does not measure) to `arrays` and the grid-wide figures to `summary`. skippedCells gets
// the number of cells that are neither tetrahedra, wedges nor pyramids (a warning names it). False when the
// grid is invalid (an error is reported on `self`) or the user aborted; `self` receives progress.
bool VolGridMeasureVolumeGrid(vtkAlgorithm* self, vtkUnstructuredGrid* input,
                              std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays, vtkFieldData* summary,
                              vtkIdType& skippedCells);

#endif
