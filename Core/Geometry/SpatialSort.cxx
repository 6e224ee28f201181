#include "SpatialSort.h"

#include <algorithm>
#include <cmath>

namespace volgrid
{
namespace
{

// Hilbert index of the cell (x,y,z) on a 2^bits grid. The coordinates are first turned into the
// "transposed" Hilbert representation (rotations/reflections undone level by level from the top, then
// Gray-coded), whose bits are then interleaved (x highest) into one integer along the curve.
uint64_t hilbertIndex(uint32_t x, uint32_t y, uint32_t z, int bits)
{
  uint32_t c[3] = { x, y, z };
  const uint32_t top = 1u << (bits - 1);
  for (uint32_t q = top; q > 1; q >>= 1)
  {
    const uint32_t low = q - 1;
    for (int i = 0; i < 3; ++i)
    {
      if (c[i] & q)
        c[0] ^= low; // reflect the low bits of the first axis
      else
      {
        const uint32_t swap = (c[0] ^ c[i]) & low; // exchange low bits of axis 0 and axis i
        c[0] ^= swap;
        c[i] ^= swap;
      }
    }
  }
  c[1] ^= c[0];
  c[2] ^= c[1];
  uint32_t flip = 0;
  for (uint32_t q = top; q > 1; q >>= 1)
    if (c[2] & q)
      flip ^= q - 1;
  c[0] ^= flip;
  c[1] ^= flip;
  c[2] ^= flip;
  // Interleave: bit b of axis i goes to position 3b + (2-i).
  auto spread = [](uint64_t v)
  {
    v &= 0x1fffff;
    v = (v | (v << 32)) & 0x1f00000000ffffull;
    v = (v | (v << 16)) & 0x1f0000ff0000ffull;
    v = (v | (v << 8)) & 0x100f00f00f00f00full;
    v = (v | (v << 4)) & 0x10c30c30c30c30c3ull;
    v = (v | (v << 2)) & 0x1249249249249249ull;
    return v;
  };
  return (spread(c[0]) << 2) | (spread(c[1]) << 1) | spread(c[2]);
}

int defaultBits(size_t n)
{
  int lg = 0;
  while ((size_t(1) << lg) < n && lg < 62)
    ++lg;
  return std::min(21, std::max(4, (lg + 2) / 3 + 4));
}

} // namespace

void hilbertKeys(const double* xyz, const std::vector<int32_t>& ids, int bits, std::vector<uint64_t>& keys)
{
  keys.resize(ids.size());
  if (ids.empty())
    return;
  if (bits <= 0)
    bits = defaultBits(ids.size());
  bits = std::min(21, std::max(1, bits));
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
    lo[a] = hi[a] = xyz[3 * static_cast<size_t>(ids[0]) + a];
  for (int32_t id : ids)
    for (int a = 0; a < 3; ++a)
    {
      const double v = xyz[3 * static_cast<size_t>(id) + a];
      lo[a] = std::min(lo[a], v);
      hi[a] = std::max(hi[a], v);
    }
  const double cells = static_cast<double>(1u << bits);
  double scale[3];
  for (int a = 0; a < 3; ++a)
  {
    const double ext = hi[a] - lo[a];
    scale[a] = ext > 0 && std::isfinite(ext) ? cells / ext : 0.0;
  }
  const uint32_t maxCell = (1u << bits) - 1;
  for (size_t k = 0; k < ids.size(); ++k)
  {
    const double* p = xyz + 3 * static_cast<size_t>(ids[k]);
    uint32_t c[3];
    for (int a = 0; a < 3; ++a)
    {
      const double f = (p[a] - lo[a]) * scale[a];
      c[a] = f >= maxCell ? maxCell : (f > 0 ? static_cast<uint32_t>(f) : 0u);
    }
    keys[k] = hilbertIndex(c[0], c[1], c[2], bits);
  }
}

void hilbertSort(const double* xyz, std::vector<int32_t>& ids, std::vector<uint64_t>* sortedKeys)
{
  const size_t n = ids.size();
  std::vector<uint64_t> keys;
  const int bits = defaultBits(n);
  hilbertKeys(xyz, ids, bits, keys);
  if (n < (size_t(1) << 14))
  {
    std::vector<uint32_t> perm(n);
    for (size_t i = 0; i < n; ++i)
      perm[i] = static_cast<uint32_t>(i);
    std::stable_sort(perm.begin(), perm.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
    std::vector<int32_t> sortedIds(n);
    std::vector<uint64_t> sk(n);
    for (size_t i = 0; i < n; ++i)
    {
      sortedIds[i] = ids[perm[i]];
      sk[i] = keys[perm[i]];
    }
    ids.swap(sortedIds);
    if (sortedKeys)
      sortedKeys->swap(sk);
    return;
  }
  // LSD radix sort of (key, id) on the 3*bits significant bits, 11 bits per pass (stable).
  struct Item
  {
    uint64_t key;
    int32_t id;
  };
  std::vector<Item> a(n), b(n);
  for (size_t i = 0; i < n; ++i)
    a[i] = { keys[i], ids[i] };
  std::vector<uint64_t>().swap(keys);
  const int totalBits = 3 * bits;
  constexpr int kDigit = 11;
  std::vector<size_t> count(size_t(1) << kDigit);
  for (int shift = 0; shift < totalBits; shift += kDigit)
  {
    std::fill(count.begin(), count.end(), 0);
    const uint64_t mask = (uint64_t(1) << kDigit) - 1;
    for (const Item& it : a)
      ++count[(it.key >> shift) & mask];
    size_t sum = 0;
    for (size_t& c : count)
    {
      const size_t t = c;
      c = sum;
      sum += t;
    }
    for (const Item& it : a)
      b[count[(it.key >> shift) & mask]++] = it;
    a.swap(b);
  }
  for (size_t i = 0; i < n; ++i)
    ids[i] = a[i].id;
  if (sortedKeys)
  {
    sortedKeys->resize(n);
    for (size_t i = 0; i < n; ++i)
      (*sortedKeys)[i] = a[i].key;
  }
}

void brioRounds(std::vector<int32_t>& ids, uint64_t seed, size_t minFirstRound, std::vector<size_t>* roundStarts)
{
  const size_t n = ids.size();
  if (roundStarts)
    *roundStarts = { 0, n };
  if (n <= minFirstRound)
    return;
  // Number of rounds: the first (smallest) round holds about n / 2^(rounds-1) >= minFirstRound points.
  int rounds = 1;
  while ((n >> rounds) >= std::max<size_t>(minFirstRound, 1) && rounds < 40)
    ++rounds;
  // Point k goes to round (rounds-1-t) where t = number of trailing one bits of a random word, capped:
  // P(last round) = 1/2, P(the one before) = 1/4, ...
  SplitMix64 rng(seed ^ 0x5eedb410ull);
  std::vector<uint8_t> round(n);
  std::vector<size_t> count(static_cast<size_t>(rounds) + 1, 0);
  uint64_t word = 0;
  int left = 0;
  for (size_t k = 0; k < n; ++k)
  {
    int t = 0;
    for (;;)
    {
      if (left == 0)
      {
        word = rng.next();
        left = 64;
      }
      const bool one = word & 1;
      word >>= 1;
      --left;
      if (!one || t == rounds - 1)
        break;
      ++t;
    }
    round[k] = static_cast<uint8_t>(rounds - 1 - t);
    ++count[round[k] + 1];
  }
  for (int r = 0; r < rounds; ++r)
    count[r + 1] += count[r];
  std::vector<int32_t> out(n);
  std::vector<size_t> pos(count.begin(), count.end() - 1);
  for (size_t k = 0; k < n; ++k)
    out[pos[round[k]]++] = ids[k];
  // Reverse every other round so that each round starts near where the previous one ended. The last
  // (largest) round is never reversed.
  for (int r = rounds - 2; r >= 0; r -= 2)
    std::reverse(out.begin() + static_cast<std::ptrdiff_t>(count[r]),
                 out.begin() + static_cast<std::ptrdiff_t>(count[r + 1]));
  ids.swap(out);
  if (roundStarts)
    roundStarts->assign(count.begin(), count.end());
}

void brioHilbertOrder(const double* xyz, size_t n, uint64_t seed, std::vector<int32_t>& order)
{
  order.resize(n);
  for (size_t i = 0; i < n; ++i)
    order[i] = static_cast<int32_t>(i);
  hilbertSort(xyz, order);
  brioRounds(order, seed);
}

} // namespace volgrid
