// TetSlotPool: tet slots set aside for one thread's edits, so that threads editing disjoint parts of a
// mesh at once never share the mesh's free list or grow its arrays (FieldPointRegions.h).
//
// A pool holds slots taken from the mesh's free list or appended to the mesh before the threads start, and
// the slots its own edits free. An editor with a pool (MeshNavigator::slotPool) takes new slots from it, the
// ones it freed first (as the mesh's free list does), and gives freed slots back to it; the mesh's free
// list and counters are not touched. After the threads have joined, returnAll() hands what is left to the
// mesh's free list, in a fixed order.
#pragma once

#include "TetMesh.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace volgrid
{

class TetSlotPool
{
public:
  // The slots `taken` (out of the mesh's free list: TetMesh::takeFreeSlot), used in their order, then
  // [first, first + count) (appended: TetMesh::appendTets). Nothing references any of them.
  void assign(std::vector<int32_t> taken, int32_t first, int32_t count)
  {
    freed_ = std::move(taken);
    std::reverse(freed_.begin(), freed_.end()); // take() uses the back first
    next_ = first;
    end_ = first + count;
  }
  int64_t available() const { return static_cast<int64_t>(freed_.size()) + (end_ - next_); }
  // A slot for a new tet (available() > 0).
  int32_t take()
  {
    if (!freed_.empty())
    {
      const int32_t t = freed_.back();
      freed_.pop_back();
      return t;
    }
    return next_++;
  }
  // Slot t's tet is gone: marked free, kept for this pool's next take().
  void give(TetMesh& mesh, int32_t t)
  {
    mesh.tetFlags[static_cast<size_t>(t)] = TetMesh::kFree;
    freed_.push_back(t);
  }
  // Every slot still in the pool goes to the mesh's free list (freed ones first, then the unused range).
  void returnAll(TetMesh& mesh)
  {
    for (int32_t t : freed_)
      mesh.returnSlot(t);
    for (int32_t t = next_; t < end_; ++t)
      mesh.returnSlot(t);
    freed_.clear();
    next_ = end_;
  }

private:
  int32_t next_ = 0, end_ = 0;
  std::vector<int32_t> freed_;
};

} // namespace volgrid
