#include "ConflictCavity.h"

namespace volgrid
{

void ConflictCavity::start(const int32_t* roots, size_t n)
{
  stamp_ = nav_.newStamp();
  tets.clear();
  for (size_t k = 0; k < n; ++k)
    add(roots[k]);
}

void ConflictCavity::release()
{
  for (int32_t t : tets)
    if (nav_.tetStamp[t] == stamp_)
      nav_.tetStamp[t] = 0;
}

} // namespace volgrid
