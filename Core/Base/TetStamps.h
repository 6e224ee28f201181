// Per-tet-slot visit marks for walks and cavity searches: each search takes a fresh value instead of
// clearing the array, which is cleared only when the 32-bit counter wraps. Shared by MeshEditor and
// TetEditor.
//
// The marks are calloc'ed, not a filled vector: the quality stage makes a new editor per pass, and most
// passes touch a small part of the mesh, so the pages no search reaches are never written (the kernel
// hands out zero pages on first use). A filled vector wrote the whole mesh's worth each time.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>

namespace volgrid
{

class TetStamps
{
public:
  // Room for every slot of a mesh with `capacity` tet slots (with some slack for growth).
  void ensure(int32_t capacity)
  {
    const size_t need = static_cast<size_t>(std::max(capacity, 0));
    if (size_ >= need)
      return;
    const size_t grown = std::max(need + 1024, size_ + size_ / 2);
    uint32_t* fresh = static_cast<uint32_t*>(std::calloc(grown, sizeof(uint32_t)));
    if (!fresh)
      throw std::bad_alloc();
    if (size_ > 0)
      std::memcpy(fresh, marks_.get(), size_ * sizeof(uint32_t));
    marks_.reset(fresh);
    size_ = grown;
  }
  // A value no slot holds yet.
  uint32_t next(int32_t capacity)
  {
    ensure(capacity);
    if (++value_ == 0)
    {
      std::fill(marks_.get(), marks_.get() + size_, 0u);
      value_ = 1;
    }
    return value_;
  }
  uint32_t& operator[](int32_t t) { return marks_[static_cast<size_t>(t)]; }
  uint32_t operator[](int32_t t) const { return marks_[static_cast<size_t>(t)]; }

private:
  struct Free
  {
    void operator()(uint32_t* p) const { std::free(p); }
  };
  std::unique_ptr<uint32_t[], Free> marks_;
  size_t size_ = 0;
  uint32_t value_ = 0;
};

} // namespace volgrid
