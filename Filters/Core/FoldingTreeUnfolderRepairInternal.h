// Internal to FoldingTreeUnfolderRepair.cxx and FoldingTreeUnfolderHoles.cxx: mesh helpers
// of the final repair (edges, orientation, face removal).
#ifndef foldingmeshes_FoldingTreeUnfolderRepairInternal_h
#define foldingmeshes_FoldingTreeUnfolderRepairInternal_h

#include "FoldingTreeUnfolderInternal.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace foldingmeshes
{
namespace unfolder_detail
{
namespace repair
{
using Edge = std::pair<int, int>;
inline Edge Key(int a, int b)
{
  return { std::min(a, b), std::max(a, b) };
}

inline Vec3 Normal(const Piece& p, const Triangle& t)
{
  return (p.points[t[1]] - p.points[t[0]]).cross(p.points[t[2]] - p.points[t[0]]);
}

inline double Area(const Piece& p, const Triangle& t)
{
  return 0.5 * Normal(p, t).norm();
}

/// The faces of one edge (a view into an EdgeTable).
struct FaceList
{
  const int* from;
  const int* to;
  size_t size() const { return static_cast<size_t>(to - from); }
  int operator[](size_t i) const { return from[i]; }
  const int* begin() const { return from; }
  const int* end() const { return to; }
};

/// Undirected edge -> faces using it, sorted by edge, in flat arrays; iterating yields
/// entries with `first` (the edge) and `second` (its faces).
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

inline EdgeTable EdgeFaces(const Piece& p)
{
  std::vector<std::pair<Edge, int>> uses;
  uses.reserve(3 * p.triangles.size());
  for (int f = 0; f < p.NumberOfFaces(); ++f)
  {
    const Triangle& t = p.triangles[f];
    for (int k = 0; k < 3; ++k)
      uses.push_back({ Key(t[k], t[(k + 1) % 3]), f });
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

/// +1 when face t traverses a -> b, -1 when b -> a, 0 when it does not use the edge.
inline int Direction(const Triangle& t, int a, int b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (t[k] == a && t[(k + 1) % 3] == b)
      return 1;
    if (t[k] == b && t[(k + 1) % 3] == a)
      return -1;
  }
  return 0;
}

/// Keeps the faces whose flag is 0 (and their attributes), in order.
inline void KeepFaces(Piece& p, const std::vector<char>& drop)
{
  Piece out;
  for (int f = 0; f < p.NumberOfFaces(); ++f)
    if (!drop[f])
    {
      out.triangles.push_back(p.triangles[f]);
      out.faceOrig.push_back(p.faceOrig[f]);
      out.faceCopy.push_back(p.faceCopy[f]);
      out.faceFilled.push_back(p.faceFilled[f]);
    }
  p.triangles = std::move(out.triangles);
  p.faceOrig = std::move(out.faceOrig);
  p.faceCopy = std::move(out.faceCopy);
  p.faceFilled = std::move(out.faceFilled);
}

/// Distance from x to the segment [a, b].
inline double SegmentDistance(const Vec3& x, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}
} // namespace repair
} // namespace unfolder_detail
} // namespace foldingmeshes

#endif
