#pragma once
/// @file UnionFind.h
/// @brief Disjoint sets with path halving: merging coincident end points and corners.

#include <numeric>
#include <vector>

namespace exactmat
{

class UnionFind
{
public:
  explicit UnionFind(int n)
    : Parent(n)
  {
    std::iota(Parent.begin(), Parent.end(), 0);
  }
  int find(int a)
  {
    while (Parent[a] != a)
    {
      Parent[a] = Parent[Parent[a]];
      a = Parent[a];
    }
    return a;
  }
  void unite(int a, int b) { Parent[find(a)] = find(b); }

private:
  std::vector<int> Parent;
};

} // namespace exactmat
