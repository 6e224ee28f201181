// One monotonic progress bar for a whole VolGrid Tetrahedralize run. Core reports each stage's own fraction
// (0 to 1, then the next stage starts at 0 again; the optimiser's passes and the smoothing inside them
// alternate). Here every stage the mesher reports gets a slice of the run weighted by its typical cost, the
// bar never moves back, and it reaches 1 only when the run is done.
#ifndef VolGridMesherProgress_h
#define VolGridMesherProgress_h

#include "Progress.h"
#include "vtkAlgorithm.h"

#include <algorithm>
#include <cstring>

class VolGridMesherProgress final : public volgrid::Progress
{
public:
  explicit VolGridMesherProgress(vtkAlgorithm* algorithm)
    : Algorithm(algorithm)
  {
  }
  void report(double fraction, const char* stage) override
  {
    struct Slice
    {
      const char* stage;
      double begin, end;
    };
    // Typical shares of the run time (wing and corpus models with the default settings).
    static const Slice slices[] = {
      { "Checking surface", 0.00, 0.02 },
      { "Sorting points", 0.02, 0.03 },
      { "Inserting points", 0.03, 0.08 },
      { "Recovering boundary edges", 0.08, 0.16 }, // Core reports edges in 0-0.5 and facets in 0.5-1
      { "Recovering boundary facets", 0.08, 0.16 },
      { "Removing boundary Steiner points", 0.16, 0.20 },
      { "Creating field points", 0.20, 0.55 },
      { "Inserting cluster points", 0.55, 0.60 },
      { "Optimising", 0.60, 0.98 },
      { "Smoothing", 0.60, 0.98 }, // inside the optimiser's passes
      { "Done", 1.00, 1.00 },
    };
    for (const Slice& s : slices)
    {
      if (stage && std::strcmp(stage, s.stage) == 0)
      {
        const double f = std::min(1.0, std::max(0.0, fraction));
        // A stage at its own 100% is not the end of the run: stay just below the slice's end.
        const double value = s.begin + (s.end - s.begin) * (s.end < 1.0 ? std::min(f, 0.99) : f);
        this->Last = std::max(this->Last, value);
        break;
      }
    }
    this->Algorithm->SetProgressText(stage);
    this->Algorithm->UpdateProgress(this->Last);
  }
  bool cancelled() override { return this->Algorithm->GetAbortExecute() != 0; }

private:
  vtkAlgorithm* Algorithm;
  double Last = 0.0;
};

#endif
