// Bridges Core's Progress interface to a VTK algorithm: progress goes to UpdateProgress (mapped into the
// [begin,end] slice of the filter's run), the stage name to SetProgressText, and the user's abort
// (GetAbortExecute, available in VTK 9.1 and 9.2) to cancelled().
#ifndef VolGridFilterProgress_h
#define VolGridFilterProgress_h

#include "Progress.h"
#include "vtkAlgorithm.h"

class VolGridFilterProgress final : public volgrid::Progress
{
public:
  explicit VolGridFilterProgress(vtkAlgorithm* algorithm, double begin = 0.0, double end = 1.0)
    : Algorithm(algorithm)
    , Begin(begin)
    , End(end)
  {
  }
  void report(double fraction, const char* stage) override
  {
    this->Algorithm->SetProgressText(stage);
    this->Algorithm->UpdateProgress(this->Begin + fraction * (this->End - this->Begin));
  }
  bool cancelled() override { return this->Algorithm->GetAbortExecute() != 0; }

private:
  vtkAlgorithm* Algorithm;
  double Begin;
  double End;
};

/**
 * After a run that was aborted (AbortExecute set, from Python or a GUI): clears the flag, so that the next
 * run (the next Apply) meshes normally instead of failing at once with "cancelled".
 */
inline void VolGridConsumeAbort(vtkAlgorithm* algorithm)
{
  if (algorithm->GetAbortExecute())
  {
    algorithm->SetAbortExecute(0);
  }
}

#endif
