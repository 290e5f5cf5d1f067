// Proved distance between the fill of a boundary loop and the loop (see LoopFillDeviation.h).
#include "LoopFillDeviation.h"

#include "PointTriangleDistance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace foldingmeshes
{
namespace
{
/// The subdivision of ProvedLoopDeviation, over `count` targets at distance(x, k).
template <typename Distance>
double ProvedDeviation(const std::vector<Vec3>& points,
  const std::vector<Triangle>& from,
  int count,
  Distance distanceTo,
  double limit,
  int maximumPieces)
{
  const double unproved = std::numeric_limits<double>::infinity();
  if (from.empty())
    return 0.0;
  if (count == 0 || !(limit >= 0.0))
    return unproved;
  double bound = 0.0;
  int pieces = 0;
  std::vector<std::array<Vec3, 3>> open;
  for (const Triangle& t : from)
    open.push_back({ points[t[0]], points[t[1]], points[t[2]] });
  while (!open.empty())
  {
    const std::array<Vec3, 3> piece = open.back();
    open.pop_back();
    if (++pieces > maximumPieces)
      return unproved;
    const Vec3 c = (piece[0] + piece[1] + piece[2]) / 3.0;
    double dc = unproved;
    int closest = -1;
    for (int k = 0; k < count; ++k)
    {
      const double d = distanceTo(c, k);
      if (d < dc)
      {
        dc = d;
        closest = k;
      }
    }
    if (!(dc <= limit))
      return unproved; // a point of `from` is farther than the limit (or not finite)
    double r = 0.0, corners = 0.0;
    for (const Vec3& p : piece)
    {
      r = std::max(r, (p - c).norm());
      corners = std::max(corners, distanceTo(p, closest));
    }
    const double b = std::min(dc + r, corners);
    if (b <= limit)
    {
      bound = std::max(bound, b);
      continue;
    }
    const Vec3 m01 = 0.5 * (piece[0] + piece[1]), m12 = 0.5 * (piece[1] + piece[2]),
               m20 = 0.5 * (piece[2] + piece[0]);
    open.push_back({ piece[0], m01, m20 });
    open.push_back({ m01, piece[1], m12 });
    open.push_back({ m20, m12, piece[2] });
    open.push_back({ m12, m20, m01 });
  }
  return bound;
}
}

double ProvedLoopDeviation(const std::vector<Vec3>& points,
  const std::vector<Triangle>& from,
  const std::vector<int>& loop,
  double limit,
  int maximumPieces)
{
  const int n = static_cast<int>(loop.size());
  return ProvedDeviation(
    points,
    from,
    n,
    [&](const Vec3& x, int k)
    {
      // Distance to the segment from loop[k] to the next loop point (convex in x).
      const Vec3& a = points[loop[k]];
      const Vec3 ab = points[loop[(k + 1) % n]] - a;
      const double len2 = ab.squaredNorm();
      const double t = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
      return (x - (a + t * ab)).norm();
    },
    limit,
    maximumPieces);
}
}
