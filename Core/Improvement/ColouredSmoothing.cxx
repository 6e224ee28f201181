#include "ColouredSmoothing.h"

#include "ParallelFor.h"

#include <algorithm>
#include <array>

namespace volgrid
{

namespace
{
// The star and the neighbours of every vertex, flat (entry i of `vertices` spans [off[i], off[i + 1])).
struct Stars
{
  std::vector<int64_t> starOff{ 0 }, nbrOff{ 0 };
  std::vector<int32_t> star, nbrs;
};

Stars collectStars(TetEditor& editor, const std::vector<int32_t>& vertices)
{
  Stars s;
  std::vector<int32_t> star, nbrs;
  for (int32_t v : vertices)
  {
    editor.star(v, star);
    editor.neighbors(v, star, nbrs);
    s.star.insert(s.star.end(), star.begin(), star.end());
    s.nbrs.insert(s.nbrs.end(), nbrs.begin(), nbrs.end());
    s.starOff.push_back(static_cast<int64_t>(s.star.size()));
    s.nbrOff.push_back(static_cast<int64_t>(s.nbrs.size()));
  }
  return s;
}

// Greedy colouring in list order: classes[c] lists the indices (into `vertices`) of colour c, ascending.
std::vector<std::vector<int32_t>> colourClasses(const std::vector<int32_t>& vertices, const Stars& s,
                                                int32_t numVertices)
{
  std::vector<int32_t> colourOf(static_cast<size_t>(numVertices), -1);
  std::vector<std::vector<int32_t>> classes;
  std::vector<uint8_t> taken;
  for (size_t i = 0; i < vertices.size(); ++i)
  {
    taken.assign(classes.size() + 1, 0);
    for (int64_t k = s.nbrOff[i]; k < s.nbrOff[i + 1]; ++k)
    {
      const int32_t c = colourOf[s.nbrs[k]];
      if (c >= 0)
        taken[c] = 1;
    }
    const int32_t c = static_cast<int32_t>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    colourOf[vertices[i]] = c;
    if (static_cast<size_t>(c) == classes.size())
      classes.emplace_back();
    classes[c].push_back(static_cast<int32_t>(i));
  }
  return classes;
}
} // namespace

void smoothColoured(TetEditor& editor, const std::vector<int32_t>& vertices, const SmoothingOptions& options,
                    int threads, std::vector<SmoothMove>& moves, const OrthogonalityFirst* rule, Progress* progress)
{
  moves.assign(vertices.size(), SmoothMove::None);
  if (vertices.empty())
    return;
  const Stars s = collectStars(editor, vertices);
  TetMesh& mesh = editor.mesh;
  const bool ruled = rule && rule->enabled;
  std::vector<RegionCounts> before;
  std::vector<std::array<double, 3>> from;
  // The rule's counts over member i's star (its slots ascending), on the thread that asks.
  auto counts = [&](int32_t i)
  {
    thread_local std::vector<int32_t> star;
    star.assign(s.star.begin() + s.starOff[i], s.star.begin() + s.starOff[i + 1]);
    std::sort(star.begin(), star.end());
    return countRegion(mesh, star, *rule);
  };
  bool first = true;
  for (const std::vector<int32_t>& members : colourClasses(vertices, s, mesh.numVertices()))
  {
    if (!first && progress && progress->cancelled())
      return;
    first = false;
    if (ruled)
    {
      before.resize(members.size());
      from.resize(members.size());
      parallelFor(threads, static_cast<int64_t>(members.size()), 32,
                  [&](int, int64_t begin, int64_t end)
                  {
                    for (int64_t k = begin; k < end; ++k)
                    {
                      before[k] = counts(members[k]);
                      const double* x = mesh.point(vertices[members[k]]);
                      from[k] = { x[0], x[1], x[2] };
                    }
                  });
    }
    parallelFor(threads, static_cast<int64_t>(members.size()), 32,
                [&](int, int64_t begin, int64_t end)
                {
                  for (int64_t k = begin; k < end; ++k)
                  {
                    const int32_t i = members[k];
                    moves[i] = smoothVertexInStar(mesh, vertices[i], s.star.data() + s.starOff[i],
                                                  static_cast<size_t>(s.starOff[i + 1] - s.starOff[i]),
                                                  s.nbrs.data() + s.nbrOff[i],
                                                  static_cast<size_t>(s.nbrOff[i + 1] - s.nbrOff[i]), options);
                  }
                });
    if (!ruled)
      continue;
    std::vector<uint8_t> undo(members.size(), 0);
    parallelFor(threads, static_cast<int64_t>(members.size()), 32,
                [&](int, int64_t begin, int64_t end)
                {
                  for (int64_t k = begin; k < end; ++k)
                    undo[k] = moves[members[k]] != SmoothMove::None && rule->binds(before[k].worst) &&
                      counts(members[k]).worseThan(before[k]);
                });
    for (size_t k = 0; k < members.size(); ++k)
      if (undo[k])
      {
        std::copy(from[k].begin(), from[k].end(), mesh.points.data() + 3 * static_cast<size_t>(vertices[members[k]]));
        moves[members[k]] = SmoothMove::None;
      }
  }
}

} // namespace volgrid
