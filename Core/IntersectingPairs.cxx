#include "IntersectingPairs.h"

#include "SurfaceChecks.h"

#include <algorithm>
#include <thread>

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
    int32_t left = -1, right = -1; // children, or -1 for a leaf
    int32_t start = 0, count = 0;  // leaf range in `items`
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
      if (count <= 4)
      {
        node.start = job.start;
        node.count = count;
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
        [&](int32_t a, int32_t b) {
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

  // Calls f(j) for every item whose closed box overlaps `b`.
  template <class F>
  void query(const double* b, std::vector<int32_t>& stack, F&& f) const
  {
    if (nodes.empty())
    {
      return;
    }
    stack.clear();
    stack.push_back(0);
    while (!stack.empty())
    {
      const Node& n = nodes[stack.back()];
      stack.pop_back();
      if (n.lo[0] > b[3] || n.hi[0] < b[0] || n.lo[1] > b[4] || n.hi[1] < b[1] || n.lo[2] > b[5] || n.hi[2] < b[2])
      {
        continue;
      }
      if (n.left < 0)
      {
        for (int32_t i = n.start; i < n.start + n.count; ++i)
        {
          const int32_t j = items[i];
          const double* c = boxes->data() + 6 * size_t(j);
          if (c[0] <= b[3] && c[3] >= b[0] && c[1] <= b[4] && c[4] >= b[1] && c[2] <= b[5] && c[5] >= b[2])
          {
            f(j);
          }
        }
      }
      else
      {
        stack.push_back(n.left);
        stack.push_back(n.right);
      }
    }
  }
};

} // namespace

std::vector<std::pair<int32_t, int32_t>> findIntersectingPairs(const SurfaceMesh& mesh,
  const std::vector<int32_t>& candidates, const std::vector<int32_t>& canon, int threads)
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
  int nthreads = threads > 0 ? threads : 2;
  const unsigned hw = std::thread::hardware_concurrency();
  if (threads <= 0 && hw > 0)
  {
    nthreads = std::min<int>(nthreads, static_cast<int>(hw));
  }
  nthreads = std::max(1, std::min(nthreads, 16));
  std::vector<std::vector<std::pair<int32_t, int32_t>>> found(nthreads);
  auto work = [&](int w) {
    std::vector<int32_t> stack;
    for (size_t i = w; i < candidates.size(); i += nthreads)
    {
      const int32_t t = candidates[i];
      const int32_t* tv = mesh.triangle(t);
      const double* p[3] = { mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]) };
      const int32_t ip[3] = { canon[tv[0]], canon[tv[1]], canon[tv[2]] };
      bvh.query(boxes.data() + 6 * size_t(t), stack, [&](int32_t u) {
        if (u <= t)
        {
          return;
        }
        const int32_t* uv = mesh.triangle(u);
        const double* q[3] = { mesh.point(uv[0]), mesh.point(uv[1]), mesh.point(uv[2]) };
        const int32_t iq[3] = { canon[uv[0]], canon[uv[1]], canon[uv[2]] };
        if (trianglesIntersect(p, ip, q, iq))
        {
          found[w].emplace_back(t, u);
        }
      });
    }
  };
  if (nthreads == 1)
  {
    work(0);
  }
  else
  {
    std::vector<std::thread> pool;
    for (int w = 0; w < nthreads; ++w)
    {
      pool.emplace_back(work, w);
    }
    for (auto& th : pool)
    {
      th.join();
    }
  }
  std::vector<std::pair<int32_t, int32_t>> pairs;
  for (auto& f : found)
  {
    pairs.insert(pairs.end(), f.begin(), f.end());
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

} // namespace volgrid::detail
