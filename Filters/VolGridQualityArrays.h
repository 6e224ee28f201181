// What the paths of vtkVolGridQuality share: the per-cell arrays and the field-data figures they fill, the
// grid's points as flat doubles, and a threaded loop that reports progress and stops on the user's abort.
#ifndef VolGridQualityArrays_h
#define VolGridQualityArrays_h

#include "vtkAlgorithm.h"
#include "vtkDoubleArray.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <vector>

class vtkFieldData;
class vtkPoints;

// Passed from the CFD metrics of a mixed grid to the summary's TotalVolume (not a figure of its own).
constexpr const char* kVolGridMixedTotalVolume = "MixedTotalVolume";

// A double cell array of n values (not initialized).
vtkSmartPointer<vtkDoubleArray> VolGridNewCellArray(const char* name, vtkIdType n);

// Adds a one-value double array to the field data.
void VolGridAddScalar(vtkFieldData* fd, const char* name, double value);

// Flat xyz doubles of the points: the array itself when it already is one, else a converted copy.
const double* VolGridFlatPoints(vtkPoints* points, std::vector<double>& storage);

// Runs body(begin, end) over [0, n) with vtkSMPTools in a few sequential blocks, reporting progress in
// [p0, p1] between blocks; false if the user aborted.
template<typename Body>
bool VolGridParallelBlocks(vtkAlgorithm* self, vtkIdType n, double p0, double p1, const Body& body)
{
  const vtkIdType blocks = n > 100000 ? 10 : 1;
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    const vtkIdType begin = n * b / blocks, end = n * (b + 1) / blocks;
    vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) { body(first, last); });
    self->UpdateProgress(p0 + (p1 - p0) * static_cast<double>(b + 1) / static_cast<double>(blocks));
    if (self->GetAbortExecute())
    {
      return false;
    }
  }
  return true;
}

#endif
