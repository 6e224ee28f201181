// Disjoint sets over 0..n-1 with path halving; the smaller id is the root of a union, so a set's root is
// its smallest member (callers count sets as the ids that are their own root).
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace volgrid
{

template<typename Index>
class UnionFind
{
public:
  explicit UnionFind(size_t n)
    : parent_(n)
  {
    std::iota(parent_.begin(), parent_.end(), Index(0));
  }

  Index find(Index x)
  {
    while (parent_[static_cast<size_t>(x)] != x)
    {
      parent_[static_cast<size_t>(x)] = parent_[static_cast<size_t>(parent_[static_cast<size_t>(x)])];
      x = parent_[static_cast<size_t>(x)];
    }
    return x;
  }

  void unite(Index a, Index b)
  {
    a = find(a);
    b = find(b);
    if (a < b)
      parent_[static_cast<size_t>(b)] = a;
    else if (b < a)
      parent_[static_cast<size_t>(a)] = b;
  }

private:
  std::vector<Index> parent_;
};

} // namespace volgrid
