#include "RotationAxis.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace foldingmeshes
{
Vec3 RotationAxis::Rotate(const Vec3& p, double angle) const
{
  return AxisTurn(*this, angle).Point(p);
}

Vec3 RotationAxis::RotateDirection(const Vec3& v, double angle) const
{
  return AxisTurn(*this, angle).Direction(v);
}

AxisTurn::AxisTurn(const RotationAxis& axis, double angle)
  : matrix(Eigen::AngleAxisd(angle, axis.direction).toRotationMatrix())
  , origin(axis.origin)
{
}

double AxisAngleDegrees(const RotationAxis& a, const RotationAxis& b)
{
  const double c = std::min(1.0, std::abs(a.direction.dot(b.direction)));
  return std::acos(c) * 180.0 / EIGEN_PI;
}

double AxisOffsetAt(const RotationAxis& a, const RotationAxis& b, const Vec3& at)
{
  const Vec3 onA = a.origin + (at - a.origin).dot(a.direction) * a.direction;
  const Vec3 r = onA - b.origin;
  return (r - r.dot(b.direction) * b.direction).norm();
}
}
