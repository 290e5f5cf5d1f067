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
}

#endif
