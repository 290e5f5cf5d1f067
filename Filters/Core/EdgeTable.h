// The core's one edge table: undirected edges of a triangle list with the faces using each.
#ifndef foldingmeshes_EdgeTable_h
#define foldingmeshes_EdgeTable_h

#include "TriangleMesh.h"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace foldingmeshes
{
/// An undirected edge as (smaller id, larger id).
using Edge = std::pair<int, int>;
inline Edge EdgeKey(int a, int b)
{
  return { std::min(a, b), std::max(a, b) };
}

/// The faces of one edge (a view into an EdgeTable), in increasing face order.
struct FaceList
{
  const int* from;
  const int* to;
  size_t size() const { return static_cast<size_t>(to - from); }
  int operator[](size_t i) const { return from[i]; }
  const int* begin() const { return from; }
  const int* end() const { return to; }
};

/**
 * Undirected edge -> the faces using it, in flat arrays sorted by edge (the order of a
 * std::map keyed by EdgeKey, without its allocations); iterating yields entries with `first`
 * (the edge) and `second` (its faces). Build it with EdgeFaces.
 */
class EdgeTable
{
public:
  struct Entry
  {
    Edge first;
    FaceList second;
  };
  class Iterator
  {
  public:
    Iterator(const EdgeTable* t, size_t i)
      : Table(t)
      , Index(i)
    {
    }
    Entry operator*() const
    {
      return { this->Table->Edges[this->Index],
        { this->Table->Faces.data() + this->Table->Offsets[this->Index],
          this->Table->Faces.data() + this->Table->Offsets[this->Index + 1] } };
    }
    Iterator& operator++()
    {
      ++this->Index;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return this->Index != o.Index; }

  private:
    const EdgeTable* Table;
    size_t Index;
  };
  Iterator begin() const { return Iterator(this, 0); }
  Iterator end() const { return Iterator(this, this->Edges.size()); }

  std::vector<Edge> Edges;
  std::vector<size_t> Offsets; ///< Edges.size() + 1
  std::vector<int> Faces;
};

/// The edge table of `triangles` (point ids >= 0). In linear time: the edge uses counted by
/// their smaller point, then each point's few uses sorted by (larger point, face) - the order
/// of sorting all (edge, face) pairs at once.
inline EdgeTable EdgeFaces(const std::vector<Triangle>& triangles)
{
  int top = -1;
  for (const Triangle& t : triangles)
    for (int v : t)
      top = std::max(top, v);
  std::vector<size_t> first(static_cast<size_t>(top) + 2, 0); // uses of points < a
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k)
      ++first[static_cast<size_t>(std::min(t[k], t[(k + 1) % 3])) + 1];
  for (size_t i = 1; i < first.size(); ++i)
    first[i] += first[i - 1];
  std::vector<std::pair<int, int>> uses(3 * triangles.size()); // (larger point, face)
  std::vector<size_t> next(first.begin(), first.end() - 1);
  for (size_t f = 0; f < triangles.size(); ++f)
  {
    const Triangle& t = triangles[f];
    for (int k = 0; k < 3; ++k)
    {
      const Edge e = EdgeKey(t[k], t[(k + 1) % 3]);
      uses[next[static_cast<size_t>(e.first)]++] = { e.second, static_cast<int>(f) };
    }
  }
  EdgeTable table;
  table.Faces.reserve(uses.size());
  for (int a = 0; a <= top; ++a)
  {
    const auto from = uses.begin() + static_cast<std::ptrdiff_t>(first[a]);
    const auto to = uses.begin() + static_cast<std::ptrdiff_t>(first[a + 1]);
    std::sort(from, to);
    for (auto it = from; it != to; ++it)
    {
      if (it == from || it->first != (it - 1)->first)
      {
        table.Edges.push_back({ a, it->first });
        table.Offsets.push_back(table.Faces.size());
      }
      table.Faces.push_back(it->second);
    }
  }
  table.Offsets.push_back(table.Faces.size());
  return table;
}

/// The edges of `triangles` used by exactly one of them (open edges), sorted.
inline std::vector<Edge> OpenEdges(const std::vector<Triangle>& triangles)
{
  std::vector<Edge> open;
  for (const auto& e : EdgeFaces(triangles))
    if (e.second.size() == 1)
      open.push_back(e.first);
  return open;
}
}

#endif
