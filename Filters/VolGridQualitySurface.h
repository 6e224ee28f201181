// The surface path of vtkVolGridQuality (its header documents the arrays and figures): the triangles of a
// vtkPolyData and the surface's topology (Core/Quality/Quality.h).
#ifndef VolGridQualitySurface_h
#define VolGridQualitySurface_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkAlgorithm;
class vtkDoubleArray;
class vtkFieldData;
class vtkPolyData;

// Measures the surface's triangles: appends AspectRatio, Area, MinAngle and MaxAngle (NaN on the other
// cells) to `arrays` and the surface figures to `summary`. skippedCells gets the number of cells that are
// not triangles (a warning names it). False when a triangle has a point id outside the points (an error is
// reported on `self`) or the user aborted; `self` receives progress.
bool VolGridMeasureSurface(vtkAlgorithm* self, vtkPolyData* input, std::vector<vtkSmartPointer<vtkDoubleArray>>& arrays,
                           vtkFieldData* summary, vtkIdType& skippedCells);

#endif
