// Compass (pattern) search in three dimensions, for the point placements of BadTetSplitting and
// InsertionImprovement: from x, scoring q, the six axis moves x +- step e_k are tried in the order
// +x, -x, +y, -y, +z, -z; the first that scores higher is taken, and the step halves when none does.
#pragma once

#include <array>

namespace volgrid
{

// score(y): the score of position y. more(step, rounds, evals): whether to go on, with the rounds done
// (a move or a halving each) and the scores computed so far. x and q end at the best position found.
template<typename Score, typename More>
void compassSearch(std::array<double, 3>& x, double& q, double step, const Score& score, const More& more)
{
  int evals = 0;
  for (int round = 0; more(step, round, evals); ++round)
  {
    bool moved = false;
    for (int k = 0; k < 3 && !moved; ++k)
      for (const double sgn : { 1.0, -1.0 })
      {
        std::array<double, 3> y = x;
        y[k] += sgn * step;
        const double qy = score(y);
        ++evals;
        if (qy > q)
        {
          q = qy;
          x = y;
          moved = true;
          break;
        }
      }
    if (!moved)
      step *= 0.5;
  }
}

} // namespace volgrid
