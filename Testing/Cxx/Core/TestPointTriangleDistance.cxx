// ClosestPointTriangle against independent references:
// - points built inside each of the 7 Voronoi regions (3 vertices, 3 edges, the face), whose
//   closest point is known by construction;
// - an independent "candidates" method (projection if inside, else the best of the three
//   clamped segment projections) for thousands of random points and triangles;
// - a brute-force dense barycentric sampling refined around its best sample;
// - barycentrics non-negative, summing to 1 and reproducing the point, squaredDistance
//   consistent; points on the triangle are at distance 0.
// - degenerate triangles (a point, a repeated vertex, collinear points) and a needle give
//   finite results (no NaN), consistent barycentrics and the distance to the degenerate set
//   (a point or a segment). Regression checks: a == b used to give NaN, and exactly collinear
//   triangles in general position used to give a wrong closest point.
#include "CoreTestUtilities.h"
#include "PointTriangleDistance.h"

#include <algorithm>
#include <cmath>
#include <random>

using foldingmeshes::ClosestPointOnTriangle;
using foldingmeshes::ClosestPointTriangle;
using foldingmeshes::Vec3;

namespace
{
std::mt19937 rng(12345);
double U(double a, double b)
{
  return a + (b - a) * (static_cast<double>(rng()) / 4294967296.0);
}
Vec3 RandomPoint(double s)
{
  return Vec3(U(-s, s), U(-s, s), U(-s, s));
}

/// Closest point of segment [a, b] to p (clamped projection).
Vec3 ClosestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  if (l2 == 0.0)
    return a;
  const double t = std::clamp((p - a).dot(ab) / l2, 0.0, 1.0);
  return a + t * ab;
}

/// Independent reference: if the projection onto the plane lies inside (by signed sub-areas),
/// it is the answer; otherwise the closest of the three edges' clamped projections.
Vec3 ReferenceClosest(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 n = (b - a).cross(c - a);
  if (n.squaredNorm() > 0.0)
  {
    const Vec3 q = p - n.dot(p - a) / n.squaredNorm() * n;
    const bool inside = (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
      (a - c).cross(q - c).dot(n) >= 0;
    if (inside)
      return q;
  }
  Vec3 best = ClosestOnSegment(p, a, b);
  for (const Vec3& e : { ClosestOnSegment(p, b, c), ClosestOnSegment(p, c, a) })
    if ((e - p).squaredNorm() < (best - p).squaredNorm())
      best = e;
  return best;
}

/// Brute force: dense barycentric grid, then a finer grid around the best sample (the squared
/// distance is convex over the triangle, so refining around the best sample converges).
double BruteForceDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  double bu = 1.0 / 3, bv = 1.0 / 3, best = 1e300;
  double cu = 0.5, cv = 0.5, radius = 0.5; // search window centre and half-width in (u, v)
  const int n = 60;
  for (int level = 0; level < 12; ++level)
  {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
      {
        const double u = std::clamp(cu - radius + 2 * radius * i / n, 0.0, 1.0);
        const double v = std::clamp(cv - radius + 2 * radius * j / n, 0.0, 1.0);
        if (u + v > 1.0)
          continue;
        const double d = (a + u * (b - a) + v * (c - a) - p).norm();
        if (d < best)
        {
          best = d;
          bu = u;
          bv = v;
        }
      }
    cu = bu;
    cv = bv;
    radius *= 0.2;
  }
  return best;
}

/// Checks of the result's own consistency; returns true when all hold.
bool CheckConsistency(const ClosestPointOnTriangle& r,
  const Vec3& p,
  const Vec3& a,
  const Vec3& b,
  const Vec3& c,
  const char* what)
{
  const double scale = std::max({ (b - a).norm(), (c - a).norm(), (p - a).norm(), 1.0 });
  const Vec3& w = r.barycentric;
  bool ok = true;
  ok &= r.point.allFinite() && w.allFinite() && std::isfinite(r.squaredDistance);
  EXPECT(ok, what << ": non-finite result");
  EXPECT(w.minCoeff() >= 0.0, what << ": negative barycentric " << w.transpose());
  EXPECT(std::abs(w.sum() - 1.0) <= 1e-14, what << ": barycentrics sum to " << w.sum());
  const Vec3 q = w[0] * a + w[1] * b + w[2] * c;
  EXPECT((q - r.point).norm() <= 1e-13 * scale,
    what << ": barycentrics give " << q.transpose() << " but point is " << r.point.transpose());
  EXPECT(std::abs(r.squaredDistance - (p - r.point).squaredNorm()) <= 1e-14 * scale * scale,
    what << ": squaredDistance " << r.squaredDistance << " != |p - point|^2");
  return ok && w.minCoeff() >= 0.0;
}

void RegularTriangles()
{
  // ---- 1. The 7 Voronoi regions of a few scalene triangles in general position ----
  int regionChecks = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const Vec3 v[3] = { RandomPoint(2), RandomPoint(2), RandomPoint(2) };
    const Vec3 n = (v[1] - v[0]).cross(v[2] - v[0]);
    if (n.norm() < 0.3)
      continue; // keep the triangles well shaped for this part
    const Vec3 un = n.normalized();
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 &a = v[k], &b = v[(k + 1) % 3], &c = v[(k + 2) % 3];
      // Vertex region of a: the cone of directions making obtuse angles with ab and ac.
      const Vec3 out = -((b - a).normalized() + (c - a).normalized()).normalized();
      const Vec3 pv = a + U(0.01, 2.0) * out + U(-1, 1) * un;
      // Edge region of ab: outward in-plane edge normal (away from c), parameter in (0, 1).
      const Vec3 ab = b - a;
      Vec3 m = un.cross(ab).normalized();
      if (m.dot(c - a) > 0)
        m = -m;
      const double t = U(0.05, 0.95);
      const Vec3 pe = a + t * ab + U(0.01, 2.0) * m + U(-1, 1) * un;
      for (int which = 0; which < 2; ++which)
      {
        const Vec3& p = which == 0 ? pv : pe;
        const Vec3 expected = which == 0 ? a : Vec3(a + t * ab);
        const ClosestPointOnTriangle r = ClosestPointTriangle(p, v[0], v[1], v[2]);
        CheckConsistency(r, p, v[0], v[1], v[2], which == 0 ? "vertex region" : "edge region");
        EXPECT((r.point - expected).norm() <= 1e-12,
          (which == 0 ? "vertex" : "edge") << " region " << k << ": closest " << r.point.transpose()
                                           << " expected " << expected.transpose());
        // The barycentric of the vertex opposite an edge (or of the other two vertices for a
        // vertex region) must be exactly zero.
        const int ia = k, ib = (k + 1) % 3, ic = (k + 2) % 3;
        if (which == 0)
          EXPECT(r.barycentric[ia] == 1.0 && r.barycentric[ib] == 0.0 && r.barycentric[ic] == 0.0,
            "vertex region " << k << ": barycentric " << r.barycentric.transpose());
        else
          EXPECT(r.barycentric[ic] == 0.0,
            "edge region " << k << ": barycentric " << r.barycentric.transpose());
        regionChecks += 1;
      }
    }
    // Face region: an interior point lifted along the normal.
    const double u = U(0.05, 0.9), w = U(0.05, 0.95 - u);
    const Vec3 inside = v[0] + u * (v[1] - v[0]) + w * (v[2] - v[0]);
    const Vec3 pf = inside + U(-2, 2) * un;
    const ClosestPointOnTriangle r = ClosestPointTriangle(pf, v[0], v[1], v[2]);
    CheckConsistency(r, pf, v[0], v[1], v[2], "face region");
    EXPECT((r.point - inside).norm() <= 1e-12,
      "face region: closest " << r.point.transpose() << " expected " << inside.transpose());
    EXPECT((r.barycentric - Vec3(1 - u - w, u, w)).norm() <= 1e-12,
      "face region: barycentric " << r.barycentric.transpose());
    ++regionChecks;
  }
  EXPECT(regionChecks > 1000, "too few Voronoi region checks: " << regionChecks);

  // ---- 2. Random points and triangles against the independent reference ----
  double worst = 0.0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const Vec3 a = RandomPoint(1), b = RandomPoint(1), c = RandomPoint(1), p = RandomPoint(2);
    const ClosestPointOnTriangle r = ClosestPointTriangle(p, a, b, c);
    CheckConsistency(r, p, a, b, c, "random");
    const double ref = (ReferenceClosest(p, a, b, c) - p).norm();
    worst = std::max(worst, std::abs(std::sqrt(r.squaredDistance) - ref));
  }
  EXPECT(worst <= 1e-12, "random triangles: max |distance - reference| = " << worst);

  // ---- 3. Brute-force sampling + refinement (a subset) ----
  double worstBrute = 0.0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const Vec3 a = RandomPoint(1), b = RandomPoint(1), c = RandomPoint(1), p = RandomPoint(2);
    const double exact = std::sqrt(ClosestPointTriangle(p, a, b, c).squaredDistance);
    const double brute = BruteForceDistance(p, a, b, c);
    // The brute force samples the triangle, so it can never beat the exact minimum.
    EXPECT(brute >= exact - 1e-12, "brute force " << brute << " below exact " << exact);
    worstBrute = std::max(worstBrute, brute - exact);
  }
  EXPECT(worstBrute <= 1e-9, "brute-force minimum exceeds exact distance by " << worstBrute);

  // Exactly on a vertex / edge / in the face: distance 0.
  {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    for (const Vec3& p : { a, b, c, Vec3(0.5, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0.2, 0.3, 0) })
    {
      const ClosestPointOnTriangle r = ClosestPointTriangle(p, a, b, c);
      CheckConsistency(r, p, a, b, c, "on triangle");
      EXPECT(r.squaredDistance <= 1e-30, "point on the triangle at distance " << r.squaredDistance);
    }
  }
}

void DegenerateTriangles()
{
  // ---- 4. Degenerate and needle triangles ----
  // Regressions: "repeated a=b" used to divide 0 / 0 in the edge-ab branch (NaN for
  // p = (0.5, 1, 0), a = b = 0, c = (1, 0, 0)); "collinear a between" (a = o + e, b = o,
  // c = o + 2e, e in general position) used to reach the face branch with a tiny rounded
  // denominator and return a non-closest point of the segment (~1.7% of random points).
  const Vec3 o(0.3, -0.2, 0.1), e(1.0, 2.0, -0.5);
  struct Case
  {
    const char* name;
    Vec3 a, b, c;
  };
  const Case cases[] = {
    { "single point", o, o, o },
    { "repeated a=b", o, o, o + e },
    { "repeated b=c", o, o + e, o + e },
    { "repeated a=c", o + e, o, o + e },
    { "collinear c between", o, o + 2 * e, o + e },
    { "collinear a between", o + e, o, o + 2 * e },
    { "collinear b between", o, o + e, o + 2 * e },
    { "needle", o, o + 2 * e, o + e + Vec3(1e-9, -2e-9, 0) },
  };
  for (const Case& k : cases)
  {
    // Reference: the distance to the convex hull of the three points (a point or a segment,
    // for the needle to the almost identical triangle).
    for (int trial = 0; trial < 2000; ++trial)
    {
      const Vec3 p = o + RandomPoint(3);
      const ClosestPointOnTriangle r = ClosestPointTriangle(p, k.a, k.b, k.c);
      if (!CheckConsistency(r, p, k.a, k.b, k.c, k.name))
        break;
      const double ref = (ReferenceClosest(p, k.a, k.b, k.c) - p).norm();
      if (std::abs(std::sqrt(r.squaredDistance) - ref) > 1e-8)
      {
        EXPECT(false,
          k.name << ": distance " << std::sqrt(r.squaredDistance)
                 << " but the degenerate triangle is at " << ref << " from " << p.transpose());
        break;
      }
    }
  }
}
}

int main()
{
  const auto t0 = std::chrono::steady_clock::now();
  RegularTriangles();
  DegenerateTriangles();
  std::printf("TestPointTriangleDistance: %.2f s\n", coretest::Seconds(t0));
  return coretest::Finish("TestPointTriangleDistance");
}
