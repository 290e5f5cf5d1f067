// An oriented plane and reflection through it.
#ifndef foldingmeshes_Plane_h
#define foldingmeshes_Plane_h

#include "TriangleMesh.h"

#include <algorithm>
#include <cmath>

namespace foldingmeshes
{
struct Plane
{
  Vec3 origin = Vec3::Zero();
  Vec3 normal = Vec3::UnitX(); ///< unit length

  double SignedDistance(const Vec3& p) const { return normal.dot(p - origin); }
  Vec3 Reflect(const Vec3& p) const { return p - 2.0 * SignedDistance(p) * normal; }
  Vec3 ReflectDirection(const Vec3& v) const { return v - 2.0 * v.dot(normal) * normal; }
  Vec3 Project(const Vec3& p) const { return p - SignedDistance(p) * normal; }
};

/// Angle between two planes' normals in degrees, ignoring orientation (0..90).
inline double PlaneAngleDegrees(const Plane& a, const Plane& b)
{
  const double c = std::min(1.0, std::abs(a.normal.dot(b.normal)));
  return std::acos(c) * 180.0 / 3.14159265358979323846;
}

/// Distance between two planes measured at point `at` (how far b is from a there).
inline double PlaneOffsetAt(const Plane& a, const Plane& b, const Vec3& at)
{
  return std::abs(a.SignedDistance(b.Project(at)));
}

/// The same plane with a canonical normal sign (largest component positive) and origin
/// moved to the projection of `reference`.
inline Plane CanonicalPlane(Plane p, const Vec3& reference)
{
  int k = 0;
  p.normal.cwiseAbs().maxCoeff(&k);
  if (p.normal[k] < 0)
  {
    p.normal = -p.normal;
  }
  p.origin = p.Project(reference);
  return p;
}
}

#endif
