// An axis of rotation and turns about it (rotational symmetry, rotation nodes of the tree).
#ifndef foldingmeshes_RotationAxis_h
#define foldingmeshes_RotationAxis_h

#include "Plane.h"

#include <Eigen/Core>

namespace foldingmeshes
{
/// A line in space: the axis of a rotation.
struct RotationAxis
{
  Vec3 origin = Vec3::Zero();     ///< a point of the axis
  Vec3 direction = Vec3::UnitZ(); ///< unit length

  /// p turned by `angle` radians about the axis (right-handed about `direction`).
  Vec3 Rotate(const Vec3& p, double angle) const;
  /// A direction turned the same way.
  Vec3 RotateDirection(const Vec3& v, double angle) const;
};

/// A turn by a fixed angle about an axis, its matrix computed once (RotationAxis::Rotate
/// computes it on every call): for loops that turn many points by the same turn.
struct AxisTurn
{
  AxisTurn(const RotationAxis& axis, double angle);
  Vec3 Point(const Vec3& p) const { return this->origin + this->matrix * (p - this->origin); }
  Vec3 Direction(const Vec3& v) const { return this->matrix * v; }

  Eigen::Matrix3d matrix;
  Vec3 origin;
};

/// Angle between two axes' directions in degrees, ignoring orientation (0..90).
double AxisAngleDegrees(const RotationAxis& a, const RotationAxis& b);
/// Distance between the axes at the point of `a` nearest to `at`.
double AxisOffsetAt(const RotationAxis& a, const RotationAxis& b, const Vec3& at);
}

#endif
