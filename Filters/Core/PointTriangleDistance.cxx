#include "PointTriangleDistance.h"

#include <algorithm>

namespace foldingmeshes
{
ClosestPointOnTriangle ClosestPointTriangle(const Vec3& p,
  const Vec3& a,
  const Vec3& b,
  const Vec3& c)
{
  if (!IsRegularTriangle(a, b, c))
  {
    // Degenerate (repeated or collinear points): the closest point of its three edges.
    ClosestPointOnTriangle best{ a, Vec3(1, 0, 0), (p - a).squaredNorm() };
    const Vec3* corners[3] = { &a, &b, &c };
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& s = *corners[k];
      const Vec3& e = *corners[(k + 1) % 3];
      const Vec3 se = e - s;
      const double len2 = se.squaredNorm();
      const double t = len2 > 0.0 ? std::clamp((p - s).dot(se) / len2, 0.0, 1.0) : 0.0;
      const Vec3 q = s + t * se;
      const double d2 = (p - q).squaredNorm();
      if (d2 < best.squaredDistance)
      {
        Vec3 w = Vec3::Zero();
        w[k] += 1.0 - t;
        w[(k + 1) % 3] += t;
        best = ClosestPointOnTriangle{ q, w, d2 };
      }
    }
    return best;
  }
  return ClosestPointRegularTriangle(p, a, b, c);
}

bool IsRegularTriangle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a;
  const double scale = std::max({ ab.squaredNorm(), ac.squaredNorm(), (c - b).squaredNorm() });
  return ab.cross(ac).squaredNorm() > 1e-24 * scale * scale;
}

}
