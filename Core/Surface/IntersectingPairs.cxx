#include "IntersectingPairs.h"
#include "ParallelFor.h"

#include "SurfaceChecks.h"

#include <algorithm>

namespace volgrid::detail
{

namespace
{

// Bounding volume hierarchy over triangle boxes, for candidate pairs.
struct BVH
{
  struct Node
  {
    double lo[3], hi[3];
    int32_t left = -1, right = -1; // children (right = left + 1), or -1 for a leaf
    int32_t start = 0, count = 0;  // range in `items`
  };
  std::vector<Node> nodes;
  std::vector<int32_t> items;
  const std::vector<double>* boxes = nullptr; // 6 per triangle: lo xyz, hi xyz

  void build(const std::vector<int32_t>& tris, const std::vector<double>& triBoxes)
  {
    boxes = &triBoxes;
    items = tris;
    nodes.clear();
    if (items.empty())
    {
      return;
    }
    nodes.reserve(2 * items.size() / 3 + 2);
    struct Job
    {
      int32_t node, start, end;
    };
    std::vector<Job> stack;
    nodes.emplace_back();
    stack.push_back({ 0, 0, static_cast<int32_t>(items.size()) });
    while (!stack.empty())
    {
      const Job job = stack.back();
      stack.pop_back();
      Node node;
      double clo[3] = { 1e308, 1e308, 1e308 }, chi[3] = { -1e308, -1e308, -1e308 };
      for (int k = 0; k < 3; ++k)
      {
        node.lo[k] = 1e308;
        node.hi[k] = -1e308;
      }
      for (int32_t i = job.start; i < job.end; ++i)
      {
        const double* b = triBoxes.data() + 6 * size_t(items[i]);
        for (int k = 0; k < 3; ++k)
        {
          node.lo[k] = std::min(node.lo[k], b[k]);
          node.hi[k] = std::max(node.hi[k], b[3 + k]);
          const double c = 0.5 * (b[k] + b[3 + k]);
          clo[k] = std::min(clo[k], c);
          chi[k] = std::max(chi[k], c);
        }
      }
      const int32_t count = job.end - job.start;
      node.start = job.start;
      node.count = count;
      if (count <= 4)
      {
        nodes[job.node] = node;
        continue;
      }
      int axis = 0;
      for (int k = 1; k < 3; ++k)
      {
        if (chi[k] - clo[k] > chi[axis] - clo[axis])
        {
          axis = k;
        }
      }
      const int32_t mid = job.start + count / 2;
      std::nth_element(items.begin() + job.start, items.begin() + mid, items.begin() + job.end,
                       [&](int32_t a, int32_t b)
                       {
                         const double* ba = triBoxes.data() + 6 * size_t(a);
                         const double* bb = triBoxes.data() + 6 * size_t(b);
                         return ba[axis] + ba[3 + axis] < bb[axis] + bb[3 + axis];
                       });
      node.left = static_cast<int32_t>(nodes.size());
      node.right = node.left + 1;
      nodes[job.node] = node;
      nodes.emplace_back();
      nodes.emplace_back();
      stack.push_back({ node.left, job.start, mid });
      stack.push_back({ node.right, mid, job.end });
    }
  }

  static bool overlap(const double* alo, const double* ahi, const double* blo, const double* bhi)
  {
    return alo[0] <= bhi[0] && ahi[0] >= blo[0] && alo[1] <= bhi[1] && ahi[1] >= blo[1] && alo[2] <= bhi[2] &&
      ahi[2] >= blo[2];
  }

  // Calls f(i, j), i < j, once for every pair of distinct items whose closed boxes overlap, found below the
  // node pair (a, b) (a == b: pairs within one node). Traversing node pairs instead of querying the tree
  // once per item visits each overlapping pair of subtrees once rather than twice, from its top.
  template<class F>
  void pairs(int32_t a0, int32_t b0, std::vector<std::pair<int32_t, int32_t>>& stack, F&& f) const
  {
    stack.clear();
    stack.push_back({ a0, b0 });
    while (!stack.empty())
    {
      const auto [a, b] = stack.back();
      stack.pop_back();
      const Node& na = nodes[a];
      const Node& nb = nodes[b];
      if (a == b)
      {
        if (na.left < 0)
        {
          for (int32_t i = na.start; i < na.start + na.count; ++i)
            for (int32_t j = i + 1; j < na.start + na.count; ++j)
              leafPair(items[i], items[j], f);
          continue;
        }
        stack.push_back({ na.left, na.left });
        stack.push_back({ na.right, na.right });
        stack.push_back({ na.left, na.right });
        continue;
      }
      if (!overlap(na.lo, na.hi, nb.lo, nb.hi))
        continue;
      if (na.left < 0 && nb.left < 0)
      {
        for (int32_t i = na.start; i < na.start + na.count; ++i)
          for (int32_t j = nb.start; j < nb.start + nb.count; ++j)
            leafPair(items[i], items[j], f);
      }
      else if (nb.left < 0 || (na.left >= 0 && na.count >= nb.count))
      {
        stack.push_back({ na.left, b });
        stack.push_back({ na.right, b });
      }
      else
      {
        stack.push_back({ a, nb.left });
        stack.push_back({ a, nb.right });
      }
    }
  }

  template<class F>
  void leafPair(int32_t t, int32_t u, F&& f) const
  {
    const double* bt = boxes->data() + 6 * size_t(t);
    const double* bu = boxes->data() + 6 * size_t(u);
    if (overlap(bt, bt + 3, bu, bu + 3))
      f(std::min(t, u), std::max(t, u));
  }
};

} // namespace

std::vector<std::pair<int32_t, int32_t>> findIntersectingPairs(const SurfaceMesh& mesh,
                                                               const std::vector<int32_t>& candidates,
                                                               const std::vector<int32_t>& canon, int threads)
{
  const int32_t nt = mesh.numberOfTriangles();
  std::vector<double> boxes(6 * size_t(nt), 0.0);
  for (int32_t t : candidates)
  {
    const int32_t* v = mesh.triangle(t);
    double* b = boxes.data() + 6 * size_t(t);
    for (int k = 0; k < 3; ++k)
    {
      const double* p0 = mesh.point(v[0]);
      const double* p1 = mesh.point(v[1]);
      const double* p2 = mesh.point(v[2]);
      b[k] = std::min({ p0[k], p1[k], p2[k] });
      b[3 + k] = std::max({ p0[k], p1[k], p2[k] });
    }
  }
  BVH bvh;
  bvh.build(candidates, boxes);
  const int nthreads = std::min(resolveThreads(threads), 16);
  // Node pairs to traverse, split a few levels down so that the threads share the work.
  std::vector<std::pair<int32_t, int32_t>> tasks;
  if (!bvh.nodes.empty())
    tasks.push_back({ 0, 0 });
  for (size_t k = 0; k < tasks.size() && tasks.size() < 64 * size_t(nthreads);)
  {
    const auto [a, b] = tasks[k];
    const BVH::Node& na = bvh.nodes[a];
    const BVH::Node& nb = bvh.nodes[b];
    if (na.left < 0 || nb.left < 0)
    {
      ++k;
      continue;
    }
    // Replace the task by its children's pairs (as the traversal would).
    tasks.erase(tasks.begin() + static_cast<std::ptrdiff_t>(k));
    if (a == b)
    {
      tasks.push_back({ na.left, na.left });
      tasks.push_back({ na.right, na.right });
      tasks.push_back({ na.left, na.right });
    }
    else if (BVH::overlap(na.lo, na.hi, nb.lo, nb.hi))
      for (int32_t x : { na.left, na.right })
        for (int32_t y : { nb.left, nb.right })
          tasks.push_back({ x, y });
  }
  std::vector<std::vector<std::pair<int32_t, int32_t>>> found(nthreads);
  auto work = [&](int w)
  {
    std::vector<std::pair<int32_t, int32_t>> stack;
    for (size_t k = w; k < tasks.size(); k += nthreads)
      bvh.pairs(tasks[k].first, tasks[k].second, stack,
                [&](int32_t t, int32_t u)
                {
                  const int32_t* tv = mesh.triangle(t);
                  const int32_t* uv = mesh.triangle(u);
                  const double* p[3] = { mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]) };
                  const double* q[3] = { mesh.point(uv[0]), mesh.point(uv[1]), mesh.point(uv[2]) };
                  const int32_t ip[3] = { canon[tv[0]], canon[tv[1]], canon[tv[2]] };
                  const int32_t iq[3] = { canon[uv[0]], canon[uv[1]], canon[uv[2]] };
                  if (trianglesIntersect(p, ip, q, iq))
                    found[w].emplace_back(t, u);
                });
  };
  parallelRun(nthreads, work);
  std::vector<std::pair<int32_t, int32_t>> pairs;
  for (auto& f : found)
  {
    pairs.insert(pairs.end(), f.begin(), f.end());
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

} // namespace volgrid::detail
