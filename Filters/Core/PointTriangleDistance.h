// Closest point on a triangle (exact, with barycentric coordinates).
#ifndef foldingmeshes_PointTriangleDistance_h
#define foldingmeshes_PointTriangleDistance_h

#include "TriangleMesh.h"

namespace foldingmeshes
{
struct ClosestPointOnTriangle
{
  Vec3 point;
  Vec3 barycentric; ///< weights of a, b, c (non-negative, sum 1)
  double squaredDistance;
};

/// The point of triangle (a, b, c) closest to p, by Voronoi-region classification.
ClosestPointOnTriangle ClosestPointTriangle(const Vec3& p,
  const Vec3& a,
  const Vec3& b,
  const Vec3& c);

/// False for triangles ClosestPointTriangle treats as degenerate (repeated or collinear
/// points: it then takes the closest point of the three edges).
bool IsRegularTriangle(const Vec3& a, const Vec3& b, const Vec3& c);

/// ClosestPointTriangle for a triangle known to be regular (IsRegularTriangle): the same
/// result without the test, for callers that query one triangle many times (inline: the face
/// tree's leaf tests call it millions of times).
inline ClosestPointOnTriangle ClosestPointRegularTriangle(const Vec3& p,
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

#endif
