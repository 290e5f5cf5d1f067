#include "FaceTreeFrame.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace foldingmeshes
{
namespace
{
/// A rotation must save this share of the identity's score to be taken.
constexpr double RequiredSaving = 0.25;

/// Summed surface area of the faces' boxes in the frame `axes` (rows).
double BoxScore(const PreparedMesh& mesh,
  const std::vector<int>& faces,
  const Eigen::Matrix3d& axes)
{
  double score = 0.0;
  for (int f : faces)
  {
    const Triangle& t = mesh.triangles[f];
    const Vec3 a = axes * mesh.points[t[0]], b = axes * mesh.points[t[1]],
               c = axes * mesh.points[t[2]];
    const Vec3 extent = a.cwiseMax(b).cwiseMax(c) - a.cwiseMin(b).cwiseMin(c);
    score += extent.x() * extent.y() + extent.y() * extent.z() + extent.z() * extent.x();
  }
  return score;
}

/// The eigenvectors of a symmetric 3x3 matrix as the rows of a right-handed frame.
Eigen::Matrix3d Axes(const Eigen::Matrix3d& tensor)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(tensor);
  Eigen::Matrix3d axes = solver.eigenvectors().transpose();
  if (axes.determinant() < 0.0)
    axes.row(2) *= -1.0;
  return axes;
}
}

Eigen::Matrix3d BoxFrame(const PreparedMesh& mesh, const std::vector<int>& faces)
{
  Eigen::Matrix3d edges = Eigen::Matrix3d::Zero(), spread = Eigen::Matrix3d::Zero();
  // Only points, triangles and centroids: what every FaceTree's mesh has.
  std::vector<double> areas(faces.size());
  Vec3 mean = Vec3::Zero();
  double area = 0.0;
  for (size_t k = 0; k < faces.size(); ++k)
  {
    const Triangle& t = mesh.triangles[faces[k]];
    for (int i = 0; i < 3; ++i)
    {
      const Vec3 e = mesh.points[t[(i + 1) % 3]] - mesh.points[t[i]];
      edges += e * e.transpose();
    }
    areas[k] = 0.5 *
      (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]).norm();
    mean += areas[k] * mesh.faceCentroids[faces[k]];
    area += areas[k];
  }
  if (!(area > 0.0) || !edges.allFinite())
    return Eigen::Matrix3d::Identity();
  mean /= area;
  for (size_t k = 0; k < faces.size(); ++k)
  {
    const Vec3 d = mesh.faceCentroids[faces[k]] - mean;
    spread += areas[k] * d * d.transpose();
  }
  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  const double identity = BoxScore(mesh, faces, best);
  double bestScore = (1.0 - RequiredSaving) * identity;
  for (const Eigen::Matrix3d& tensor : { edges, spread })
  {
    if (!tensor.allFinite())
      continue;
    const Eigen::Matrix3d axes = Axes(tensor);
    const double score = BoxScore(mesh, faces, axes);
    if (score < bestScore)
    {
      bestScore = score;
      best = axes;
    }
  }
  return best;
}
}
