// Internal to FoldingTreeUnfolderRepair.cxx and FoldingTreeUnfolderHoles.cxx: mesh helpers
// of the final repair (edges, orientation, face removal).
#ifndef foldingmeshes_FoldingTreeUnfolderRepairInternal_h
#define foldingmeshes_FoldingTreeUnfolderRepairInternal_h

#include "EdgeTable.h"
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
using foldingmeshes::Edge;
using foldingmeshes::EdgeTable;
inline Edge Key(int a, int b)
{
  return EdgeKey(a, b);
}

inline Vec3 Normal(const Piece& p, const Triangle& t)
{
  return (p.points[t[1]] - p.points[t[0]]).cross(p.points[t[2]] - p.points[t[0]]);
}

inline double Area(const Piece& p, const Triangle& t)
{
  return 0.5 * Normal(p, t).norm();
}

inline EdgeTable EdgeFaces(const Piece& p)
{
  return foldingmeshes::EdgeFaces(p.triangles);
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
