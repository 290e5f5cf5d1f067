// Measures: areas, centroids, plane angle and offset errors, best plane match, region IoU.
#include "ProceduralMeshesInternal.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
using namespace procedural;

// ===================================== measures =====================================

double BoundsDiagonal(vtkPolyData* mesh)
{
  double b[6];
  mesh->GetBounds(b);
  return Vec3(b[1] - b[0], b[3] - b[2], b[5] - b[4]).norm();
}

std::vector<double> FaceAreas(vtkPolyData* mesh)
{
  std::vector<double> a(size_t(mesh->GetNumberOfCells()), 0.0);
  const std::vector<Vec3> p = GetPoints(mesh);
  ForEachTriangle(mesh,
    [&](vtkIdType c, vtkIdType i, vtkIdType j, vtkIdType k)
    { a[size_t(c)] += 0.5 * (p[j] - p[i]).cross(p[k] - p[i]).norm(); });
  return a;
}

Eigen::Vector3d AreaCentroid(vtkPolyData* mesh)
{
  const std::vector<Vec3> p = GetPoints(mesh);
  Vec3 s = Vec3::Zero();
  double w = 0;
  ForEachTriangle(mesh,
    [&](vtkIdType, vtkIdType i, vtkIdType j, vtkIdType k)
    {
      const double a = 0.5 * (p[j] - p[i]).cross(p[k] - p[i]).norm();
      s += a * (p[i] + p[j] + p[k]) / 3;
      w += a;
    });
  return w > 0 ? Vec3(s / w) : Vec3::Zero();
}

double MaskAreaFraction(vtkPolyData* mesh, const std::vector<char>& mask)
{
  const std::vector<double> a = FaceAreas(mesh);
  if (mask.size() != a.size())
  {
    throw std::invalid_argument("MaskAreaFraction: mask size differs from the cell count");
  }
  double in = 0, all = 0;
  for (size_t f = 0; f < a.size(); ++f)
  {
    in += mask[f] ? a[f] : 0.0;
    all += a[f];
  }
  return all > 0 ? in / all : 0.0;
}

double PlaneAngleDegrees(const Eigen::Vector3d& n1, const Eigen::Vector3d& n2)
{
  return std::atan2(n1.cross(n2).norm(), std::abs(n1.dot(n2))) * 180 / kPi;
}

double PlaneOffsetError(const KnownPlane& truth,
  const Eigen::Vector3d& origin,
  const Eigen::Vector3d& normal,
  const Eigen::Vector3d& at,
  double diagonal)
{
  const Vec3 nt = truth.normal.normalized();
  const Vec3 q = at - nt.dot(at - truth.origin) * nt;
  return std::abs(normal.normalized().dot(q - origin)) / diagonal;
}

PlaneMatch BestPlaneMatch(const ProceduralMesh& m,
  const Eigen::Vector3d& origin,
  const Eigen::Vector3d& normal)
{
  const Vec3 at = AreaCentroid(m.mesh);
  const double diag = BoundsDiagonal(m.mesh);
  std::vector<PlaneMatch> c;
  for (size_t i = 0; i < m.planes.size(); ++i)
  {
    c.push_back({ int(i),
      PlaneAngleDegrees(normal, m.planes[i].normal),
      PlaneOffsetError(m.planes[i], origin, normal, at, diag) });
  }
  Vec3 n = normal.normalized();
  if (m.family == SymmetryFamily::AnyPlaneContainingAxis)
  {
    const Vec3 a = m.axis.normalized();
    n -= n.dot(a) * a;
    n = n.norm() > 1e-12 ? Vec3(n.normalized()) : a.unitOrthogonal();
  }
  if (m.family != SymmetryFamily::None)
  {
    const KnownPlane k{ m.center, n };
    c.push_back(
      { -1, PlaneAngleDegrees(normal, n), PlaneOffsetError(k, origin, normal, at, diag) });
  }
  PlaneMatch best;
  for (const PlaneMatch& x : c)
  {
    best.angleDegrees = std::min(best.angleDegrees, x.angleDegrees);
  }
  const double minAngle = best.angleDegrees;
  for (const PlaneMatch& x : c)
  {
    if (x.angleDegrees <= minAngle + 1e-6 && x.offsetError < best.offsetError)
    {
      best = x;
    }
  }
  return best;
}

double RegionIoU(vtkPolyData* mesh, const std::vector<char>& found, const std::vector<char>& truth)
{
  const std::vector<double> a = FaceAreas(mesh);
  if (found.size() != a.size() || truth.size() != a.size())
  {
    throw std::invalid_argument("RegionIoU: mask sizes differ from the cell count");
  }
  double inter = 0, uni = 0;
  for (size_t f = 0; f < a.size(); ++f)
  {
    inter += found[f] && truth[f] ? a[f] : 0.0;
    uni += found[f] || truth[f] ? a[f] : 0.0;
  }
  return uni > 0 ? inter / uni : 1.0;
}
} // namespace testing
} // namespace foldingmeshes
