// An axis of rotation and turns about it (rotational symmetry, rotation nodes of the tree).
#ifndef foldingmeshes_RotationAxis_h
#define foldingmeshes_RotationAxis_h

#include "Plane.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

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

/**
 * The share of the unfolder's stitch tolerance within which a rotation node of order k has its
 * seams stitched (Unfolder::Turn): a tenth, and sin(180/k) above order 31. The builder made
 * the seams meet - paired seam vertices agree closely, the others lie on the sector's
 * half-planes - so the pairs need no more; and near the axis the node's full tolerance
 * (StitchToleranceScale times its epsilon) reaches the next half-plane (2 r sin(180/k) away at
 * radius r), where chains of pairs across the sectors moved the seams' vertices over their
 * neighbours: the bearing's 19 sectors, cut along their half-planes, came back with 1.10 times
 * its area at the full tolerance, 1.044 at a quarter, 1.014 at a tenth (docs/unfolder.md).
 * Above order 31, beyond the seam vertices Turn moves onto the axis (half of
 * StitchToleranceScale times epsilon from it), two half-planes are then farther apart than the
 * tolerance for any k. A compact file's automatic quantisation error is at most this
 * tolerance (CompactTreeFormat.cxx, ChooseBits).
 */
inline double RotationStitchShare(int order)
{
  return std::min(0.1, std::sin(static_cast<double>(EIGEN_PI) / std::max(order, 2)));
}

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

/// Cylindrical coordinates about an axis.
struct AxisFrame
{
  explicit AxisFrame(const RotationAxis& axis)
    : Axis(axis)
  {
    const Vec3& a = axis.direction;
    const Vec3 seed = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    this->U = (seed - seed.dot(a) * a).normalized();
    this->V = a.cross(this->U);
  }
  double Angle(const Vec3& p) const
  {
    const Vec3 r = p - this->Axis.origin;
    return std::atan2(r.dot(this->V), r.dot(this->U));
  }
  double Radius(const Vec3& p) const
  {
    const Vec3 r = p - this->Axis.origin;
    return (r - r.dot(this->Axis.direction) * this->Axis.direction).norm();
  }
  Vec3 OntoAxis(const Vec3& p) const
  {
    return this->Axis.origin +
      (p - this->Axis.origin).dot(this->Axis.direction) * this->Axis.direction;
  }
  RotationAxis Axis;
  Vec3 U, V;
};

/// Angle between two axes' directions in degrees, ignoring orientation (0..90).
double AxisAngleDegrees(const RotationAxis& a, const RotationAxis& b);
/// Distance between the axes at the point of `a` nearest to `at`.
double AxisOffsetAt(const RotationAxis& a, const RotationAxis& b, const Vec3& at);
}

#endif
