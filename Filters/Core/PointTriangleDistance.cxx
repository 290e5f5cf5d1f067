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

ClosestPointOnTriangle ClosestPointRegularTriangle(const Vec3& p,
  const Vec3& a,
  const Vec3& b,
  const Vec3& c)
{
  auto result = [&p](const Vec3& q, double u, double v, double w) {
    return ClosestPointOnTriangle{ q, Vec3(u, v, w), (p - q).squaredNorm() };
  };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return result(a, 1, 0, 0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return result(b, 0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double v = d1 / (d1 - d3);
    return result(a + v * ab, 1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return result(c, 0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double w = d2 / (d2 - d6);
    return result(a + w * ac, 1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return result(b + w * (c - b), 0, 1 - w, w);
  }
  const double denom = va + vb + vc;
  if (!(denom > 0.0)) // degenerate triangle: fall back to the nearest vertex
  {
    const double da = (p - a).squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
    if (da <= db && da <= dc)
      return result(a, 1, 0, 0);
    return db <= dc ? result(b, 0, 1, 0) : result(c, 0, 0, 1);
  }
  const double v = vb / denom, w = vc / denom;
  return result(a + ab * v + ac * w, 1 - v - w, v, w);
}
}
