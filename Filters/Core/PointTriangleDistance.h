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
/// result without the test, for callers that query one triangle many times.
ClosestPointOnTriangle ClosestPointRegularTriangle(const Vec3& p,
  const Vec3& a,
  const Vec3& b,
  const Vec3& c);
}

#endif
