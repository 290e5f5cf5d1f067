// Procedural shapes with exact rotational symmetry for the rotation tests (TestRotationalSymmetry,
// TestFoldingTreeRotation, TestCompactTreeFormat): twisted k-fold vases, a box to add beside
// them, flat fans, seeded rigid motions.
#ifndef foldingmeshes_RotationTestShapes_h
#define foldingmeshes_RotationTestShapes_h

#include "TriangleMesh.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace rotationtest
{
using foldingmeshes::Triangle;
using foldingmeshes::TriangleMesh;
using foldingmeshes::Vec3;

const double Pi = 3.14159265358979323846;

/// Uniform in [-1, 1) from the generator's raw bits (not a std distribution: the same numbers
/// on every standard library).
inline double Uniform(std::mt19937& g)
{
  return 2.0 * (static_cast<double>(g()) / 4294967296.0) - 1.0;
}

inline Eigen::Isometry3d Motion(unsigned seed)
{
  std::mt19937 g(seed);
  Eigen::Quaterniond q(Uniform(g), Uniform(g), Uniform(g), Uniform(g));
  q.normalize();
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = q.toRotationMatrix();
  m.translation() = Vec3(3 * Uniform(g), 3 * Uniform(g), 3 * Uniform(g));
  return m;
}

struct VaseShape
{
  int order = 1;          ///< k (the harmonic)
  double amplitude = 0.0; ///< a (0: a surface of revolution)
  double twist = 0.9;     ///< b
  bool lumpy = false;     ///< harmonics 1, 2, 3 with different phases: no symmetry
  /// Ring j's vertices start at angle staggered * fraction(0.37 j^2) of a segment (0: every
  /// ring starts at angle 0, so the vertices form columns).
  double staggered = 0.0;
  /// Caps triangulated as fans from the ring's first vertex (no pole: the axis pierces a cap
  /// face) instead of fans from a pole on the axis.
  bool polygonCaps = false;
};

/// The closed vase along z in [0, 2] with `rings` rings of `segments` vertices and two poles
/// (or, s.polygonCaps, none).
inline TriangleMesh MakeVase(const VaseShape& s, int segments, int rings)
{
  TriangleMesh m;
  const double height = 2.0;
  for (int j = 0; j < rings; ++j)
  {
    const double z = height * (j + 0.5) / rings;
    const double profile = 0.55 + 0.22 * std::sin(1.7 * z + 0.4) + 0.08 * z;
    const double phase = s.staggered * 2.0 * Pi / segments * std::fmod(0.37 * j * j, 1.0);
    for (int i = 0; i < segments; ++i)
    {
      const double theta = phase + 2.0 * Pi * i / segments;
      double f = 1.0 + s.amplitude * std::cos(s.order * theta + s.twist * z);
      if (s.lumpy)
        f = 1.0 + 0.35 * std::cos(theta + 0.3) + 0.25 * std::cos(2 * theta + 1.7 * z) +
          0.2 * std::cos(3 * theta - 2 * z);
      const double r = profile * f;
      m.points.emplace_back(r * std::cos(theta), r * std::sin(theta), z);
    }
  }
  const int bottom = static_cast<int>(m.points.size());
  m.points.emplace_back(0, 0, 0);
  const int top = bottom + 1;
  m.points.emplace_back(0, 0, height);
  auto id = [&](int j, int i) { return j * segments + (i % segments); };
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < segments; ++i)
    {
      m.triangles.push_back({ id(j, i), id(j, i + 1), id(j + 1, i + 1) });
      m.triangles.push_back({ id(j, i), id(j + 1, i + 1), id(j + 1, i) });
    }
  for (int i = 0; i < segments && !s.polygonCaps; ++i)
  {
    m.triangles.push_back({ bottom, id(0, i + 1), id(0, i) });
    m.triangles.push_back({ top, id(rings - 1, i), id(rings - 1, i + 1) });
  }
  for (int i = 1; i + 1 < segments && s.polygonCaps; ++i)
  {
    m.triangles.push_back({ id(0, 0), id(0, i + 1), id(0, i) });
    m.triangles.push_back({ id(rings - 1, 0), id(rings - 1, i), id(rings - 1, i + 1) });
  }
  if (s.polygonCaps) // the poles unused: dropped
    m.points.resize(bottom);
  return m;
}

/// A flat regular n-gon of radius 1 about the origin in the plane z = 0, a fan of n triangles
/// about its centre (point 0).
inline TriangleMesh MakeFan(int n)
{
  TriangleMesh fan;
  fan.points.push_back(Vec3::Zero());
  for (int i = 0; i < n; ++i)
    fan.points.emplace_back(std::cos(2.0 * Pi * i / n), std::sin(2.0 * Pi * i / n), 0.0);
  for (int i = 0; i < n; ++i)
    fan.triangles.push_back({ 0, 1 + i, 1 + (i + 1) % n });
  return fan;
}

/// A closed box of edge `side` centred at `c` appended to m (a separate part).
inline void AddBox(TriangleMesh& m, const Vec3& c, double side)
{
  const int base = static_cast<int>(m.points.size());
  for (int k = 0; k < 8; ++k)
    m.points.push_back(
      c + 0.5 * side * Vec3(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0));
  const int quads[6][4] = {
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 }
  };
  for (const auto& q : quads)
  {
    m.triangles.push_back({ base + q[0], base + q[1], base + q[2] });
    m.triangles.push_back({ base + q[0], base + q[2], base + q[3] });
  }
}

}

#endif
