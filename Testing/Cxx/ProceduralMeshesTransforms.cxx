// Transformations of a ProceduralMesh: rigid motion, uniform scaling, Gaussian noise.
#include "ProceduralMeshesInternal.h"

#include <vector>

namespace foldingmeshes
{
namespace testing
{
using namespace procedural;

// ================================= transformations =================================

Eigen::Isometry3d RandomRigidMotion(unsigned seed)
{
  auto g = Rng(seed, 505);
  const double u1 = Uniform(g), u2 = Uniform(g), u3 = Uniform(g); // Shoemake: uniform rotation
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const Eigen::Quaterniond q(b * std::cos(2 * kPi * u3),
    a * std::sin(2 * kPi * u2),
    a * std::cos(2 * kPi * u2),
    b * std::sin(2 * kPi * u3));
  Vec3 t;
  for (int k = 0; k < 3; ++k)
  {
    t[k] = Uniform(g, -5, 5);
  }
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = t;
  return T;
}

void ApplyRigidMotion(ProceduralMesh& m, const Eigen::Isometry3d& T)
{
  std::vector<Vec3> p = GetPoints(m.mesh);
  for (Vec3& x : p)
  {
    x = T * x;
  }
  SetPoints(m.mesh, p);
  for (KnownPlane& k : m.planes)
  {
    k.origin = T * k.origin;
    k.normal = (T.linear() * k.normal).normalized();
  }
  m.center = T * m.center;
  m.axis = (T.linear() * m.axis).normalized();
}

void ScaleUniformly(ProceduralMesh& m, double s)
{
  std::vector<Vec3> p = GetPoints(m.mesh);
  for (Vec3& x : p)
  {
    x *= s;
  }
  SetPoints(m.mesh, p);
  for (KnownPlane& k : m.planes)
  {
    k.origin *= s;
  }
  m.center *= s;
}

void AddGaussianNoise(ProceduralMesh& m, double sigmaFraction, unsigned seed, bool alongNormals)
{
  const double sigma = sigmaFraction * BoundsDiagonal(m.mesh);
  std::vector<Vec3> p = GetPoints(m.mesh), n(p.size(), Vec3::Zero());
  ForEachTriangle(m.mesh,
    [&](vtkIdType, vtkIdType a, vtkIdType b, vtkIdType c)
    {
      const Vec3 w = (p[b] - p[a]).cross(p[c] - p[a]);
      n[a] += w;
      n[b] += w;
      n[c] += w;
    });
  auto g = Rng(seed, 606);
  for (size_t i = 0; i < p.size(); ++i)
  {
    if (alongNormals)
    {
      const double k = n[i].norm();
      const double e = sigma * Gauss(g);
      p[i] += k > 0 ? Vec3(e / k * n[i]) : Vec3::Zero();
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        p[i][c] += sigma * Gauss(g);
      }
    }
  }
  SetPoints(m.mesh, p);
}
} // namespace testing
} // namespace foldingmeshes
