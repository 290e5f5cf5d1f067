// Union-find over indices 0..n-1 stored in a parent vector (parent[i] == i: a root).
#ifndef foldingmeshes_UnionFind_h
#define foldingmeshes_UnionFind_h

#include <algorithm>
#include <vector>

namespace foldingmeshes
{
/// The root of i's set, halving the path on the way.
inline int FindRoot(std::vector<int>& parent, int i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// Joins the sets of a and b; the smaller root becomes the root of both (deterministic).
inline void Unite(std::vector<int>& parent, int a, int b)
{
  a = FindRoot(parent, a);
  b = FindRoot(parent, b);
  if (a != b)
    parent[std::max(a, b)] = std::min(a, b);
}
}

#endif
