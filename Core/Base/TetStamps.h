// Per-tet-slot visit marks for walks and cavity searches: each search takes a fresh value instead of
// clearing the array, which is cleared only when the 32-bit counter wraps. Shared by MeshEditor and
// TetEditor.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace volgrid
{

class TetStamps
{
public:
  // Room for every slot of a mesh with `capacity` tet slots (with some slack for growth).
  void ensure(int32_t capacity)
  {
    if (marks_.size() < static_cast<size_t>(capacity))
      marks_.resize(static_cast<size_t>(capacity) + 1024, 0);
  }
  // A value no slot holds yet.
  uint32_t next(int32_t capacity)
  {
    ensure(capacity);
    if (++value_ == 0)
    {
      std::fill(marks_.begin(), marks_.end(), 0);
      value_ = 1;
    }
    return value_;
  }
  uint32_t& operator[](int32_t t) { return marks_[static_cast<size_t>(t)]; }
  uint32_t operator[](int32_t t) const { return marks_[static_cast<size_t>(t)]; }

private:
  std::vector<uint32_t> marks_;
  uint32_t value_ = 0;
};

} // namespace volgrid
