// How long Core stages report progress and learn that the user wants to stop. The filters forward to
// UpdateProgress / GetAbortExecute, the CLI ignores progress. Stages call report() at coarse intervals
// (never per element) and return ErrorKind::Cancelled when cancelled() becomes true.
#pragma once

namespace volgrid
{

class Progress
{
public:
  virtual ~Progress() = default;
  // fraction in [0,1] of the current stage; stage is a short static label such as "Inserting points".
  virtual void report(double fraction, const char* stage) = 0;
  virtual bool cancelled() = 0;
};

// A Progress that does nothing: the default when the caller passes none.
class SilentProgress final : public Progress
{
public:
  void report(double, const char*) override {}
  bool cancelled() override { return false; }
};

} // namespace volgrid
