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

/// The edge table of `triangles`.
inline EdgeTable EdgeFaces(const std::vector<Triangle>& triangles)
{
  std::vector<std::pair<Edge, int>> uses;
  uses.reserve(3 * triangles.size());
  for (size_t f = 0; f < triangles.size(); ++f)
  {
    const Triangle& t = triangles[f];
    for (int k = 0; k < 3; ++k)
      uses.push_back({ EdgeKey(t[k], t[(k + 1) % 3]), static_cast<int>(f) });
  }
  std::sort(uses.begin(), uses.end());
  EdgeTable table;
  table.Faces.reserve(uses.size());
  for (size_t i = 0; i < uses.size(); ++i)
  {
    if (i == 0 || uses[i].first != uses[i - 1].first)
    {
      table.Edges.push_back(uses[i].first);
      table.Offsets.push_back(i);
    }
    table.Faces.push_back(uses[i].second);
  }
  table.Offsets.push_back(uses.size());
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
