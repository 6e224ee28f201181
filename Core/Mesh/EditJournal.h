// An undo log of local edits to a TetMesh (and its per-slot labels), so that a speculative operation
// (InsertionImprovement.h: insert a point, flip and smooth around it, keep it only when its region
// improved) is undone in time and memory proportional to what it changed, not by a copy of the whole
// mesh per attempt.
//
// The editor (TetEditor::journal) saves a tet slot's old content before it writes the slot (free,
// reuse, relink), the caller saves a point before it moves an existing vertex. mark() notes where the log
// and the arrays stand; rollback(mark) writes the saved contents back in reverse order, restores the
// free list's head and counters, and drops the slots, points and labels appended since the mark: the
// mesh is then exactly (slot for slot, free list included) what it was at the mark. Marks nest (a
// rollback to an inner mark keeps what came before it).
#pragma once

#include "TetMesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

class EditJournal
{
public:
  struct Mark
  {
    size_t tets = 0, points = 0; // log positions
    int32_t capacity = 0;        // tet slots
    int32_t vertices = 0;        // mesh points
    size_t labels = 0;           // labels->size()
    TetMesh::Bookkeeping bookkeeping{ -1, 0, 0 };
  };

  Mark mark(const TetMesh& mesh, const std::vector<int32_t>* labels) const;
  // Slot t's content before a write (any slot below the mesh's capacity).
  void saveTet(const TetMesh& mesh, const std::vector<int32_t>* labels, int32_t t);
  // Vertex v's position before a move.
  void savePoint(const TetMesh& mesh, int32_t v);
  // What the edits since mark m touched: the slots saved (tets removed, reused or relinked) and the vertices
  // moved, each as often as it was saved. A slot appended since (from m.capacity on) is listed only when a
  // later edit wrote it again: callers add that range themselves.
  void changedSince(const Mark& m, std::vector<int32_t>& slots, std::vector<int32_t>& points) const;
  // Back to the mark (see above); the log is cut back to it.
  void rollback(const Mark& mark, TetMesh& mesh, std::vector<int32_t>* labels);
  void clear();

private:
  struct TetRecord
  {
    int32_t t;
    int32_t label;
    int32_t vertices[4];
    int32_t neighbors[4];
    uint8_t flags;
  };
  struct PointRecord
  {
    int32_t v;
    std::array<double, 3> xyz;
  };
  std::vector<TetRecord> tets_;
  std::vector<PointRecord> points_;
};

} // namespace volgrid
