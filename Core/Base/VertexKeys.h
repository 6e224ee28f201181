// Keys of mesh edges and faces by vertex ids, independent of orientation: edgeKey (the two ids in one
// 64-bit word, smaller first) and TriKey (the three ids sorted), with hashes for FlatHashMap and unordered containers.
// Shared by boundary recovery (BoundaryRecovery.h) and the optimisation's face constraints (TetEditor.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

namespace volgrid
{

inline uint64_t edgeKey(int32_t a, int32_t b)
{
  const uint32_t lo = static_cast<uint32_t>(a < b ? a : b), hi = static_cast<uint32_t>(a < b ? b : a);
  return (static_cast<uint64_t>(lo) << 32) | hi;
}

struct TriKey
{
  int32_t v[3];
  TriKey() = default;
  // The three ids sorted (orientation ignored).
  TriKey(int32_t a, int32_t b, int32_t c)
  {
    if (a > b)
      std::swap(a, b);
    if (b > c)
      std::swap(b, c);
    if (a > b)
      std::swap(a, b);
    v[0] = a;
    v[1] = b;
    v[2] = c;
  }
  bool operator==(const TriKey& o) const { return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2]; }
  bool operator<(const TriKey& o) const
  {
    return v[0] != o.v[0] ? v[0] < o.v[0] : v[1] != o.v[1] ? v[1] < o.v[1] : v[2] < o.v[2];
  }
};
// An edgeKey() is its own hash in FlatHashMap, which mixes the bits itself.
struct EdgeKeyHash
{
  uint64_t operator()(uint64_t k) const { return k; }
};
struct TriKeyHash
{
  size_t operator()(const TriKey& k) const
  {
    uint64_t h = static_cast<uint32_t>(k.v[0]) * 0x9E3779B97F4A7C15ull;
    h ^= (static_cast<uint64_t>(static_cast<uint32_t>(k.v[1])) + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
    h ^= (static_cast<uint64_t>(static_cast<uint32_t>(k.v[2])) + 0x94D049BB133111EBull) * 0x165667B19E3779F9ull;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

} // namespace volgrid
