// Spatial sorting of point sets for incremental insertion: a 3D Hilbert-curve order and BRIO (biased
// randomized insertion order, Amenta-Choi-Rote) rounds. With BRIO, each round is a random subset of the
// remaining points (about half of the points are in the last round, a quarter in the one before, ...)
// and each round follows the Hilbert curve: consecutive points are close (short point-location walks)
// while the random rounds keep the expected cost of randomized incremental construction.
// Everything is deterministic for a given seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

// Hilbert key of every point of `ids` (indices into xyz, 3 doubles per point) on a 2^bits grid per axis
// over the bounding box of those points. bits in [1,21]; bits == 0 chooses it from ids.size(). Equal
// coordinates give equal keys. Non-finite coordinates are not allowed.
void hilbertKeys(const double* xyz, const std::vector<int32_t>& ids, int bits, std::vector<uint64_t>& keys);

// Sort `ids` along the Hilbert curve (stable for equal keys). If sortedKeys is given it receives the key
// of each id in the new order (so that equal-coordinate points can be found among equal keys).
void hilbertSort(const double* xyz, std::vector<int32_t>& ids, std::vector<uint64_t>* sortedKeys = nullptr);

// Reorder Hilbert-sorted `ids` into BRIO rounds (first round the smallest, about minFirstRound points
// or fewer); the Hilbert order is kept inside each round, every other round is traversed backwards so
// that a round starts near where the previous one ended.
// If roundStarts is given it receives the offset of each round in ids, plus ids.size() at the end.
void brioRounds(std::vector<int32_t>& ids, uint64_t seed, size_t minFirstRound = 64,
                std::vector<size_t>* roundStarts = nullptr);

// Convenience: ids = 0..n-1 in BRIO-Hilbert order.
void brioHilbertOrder(const double* xyz, size_t n, uint64_t seed, std::vector<int32_t>& order);

// Small deterministic generator used for BRIO and randomized walks (SplitMix64).
struct SplitMix64
{
  uint64_t state;
  explicit SplitMix64(uint64_t seed)
    : state(seed)
  {
  }
  uint64_t next()
  {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
};

} // namespace volgrid
