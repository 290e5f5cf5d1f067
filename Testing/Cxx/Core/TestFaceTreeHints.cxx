// FaceTree::ClosestCompatibleFace: a hint face never changes the answer, also where the best
// distance is within rounding of zero - a sliver (no plane bound in FaceTree::Beyond) with a
// query point 1e-17..1e-14 off its corner and a large face just beyond it as the hint. Without
// a slack on the sliver's gap the hint pruned the sliver in about a quarter of these cases
// (found by review, 2026-12-05).
#include "CoreTestUtilities.h"
#include "FaceTree.h"

#include <cmath>
#include <random>

using foldingmeshes::FaceTree;
using foldingmeshes::PreparedMesh;
using foldingmeshes::Vec3;

namespace
{
const double kPi = 3.14159265358979323846;

/// The sliver is 1e-8 high; the hint is the large face.
void CheckHintNearZero()
{
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int differ = 0;
  const int cases = 20000;
  for (int i = 0; i < cases; ++i)
  {
    PreparedMesh m;
    const double delta = std::pow(10.0, -17.0 + 3.0 * u(rng));
    const double ratio = 1.0 + std::pow(10.0, -4.0 * u(rng));
    const double height = 1e-8 * (0.5 + u(rng));
    const double x = -delta - delta * ratio;
    m.points = { Vec3(0, 0, 0),
      Vec3(1, 0, 0),
      Vec3(0.5, height, 0),
      Vec3(x, -1, -1),
      Vec3(x, 1, -1),
      Vec3(x, 0, 1) };
    m.triangles = { { 0, 1, 2 }, { 3, 4, 5 } };
    m.faceDegenerate = { 0, 0 };
    m.vertexNormals.assign(6, Vec3(0, 0, 1));
    for (const auto& t : m.triangles)
    {
      m.faceCentroids.push_back((m.points[t[0]] + m.points[t[1]] + m.points[t[2]]) / 3.0);
      m.faceNormals.push_back(
        (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]).normalized());
    }
    const FaceTree tree(m);
    const Vec3 p = -m.faceCentroids[0].normalized() * delta;
    const double cosL = std::cos(kPi / 4);
    const FaceTree::Hit plain = tree.ClosestCompatibleFace(p, Vec3(0, 0, 1), cosL, 1.0, -1);
    const FaceTree::Hit hinted = tree.ClosestCompatibleFace(p, Vec3(0, 0, 1), cosL, 1.0, 1);
    if (plain.face != hinted.face || plain.distance != hinted.distance)
      ++differ;
  }
  EXPECT(differ == 0,
    "near-zero distances at a sliver: " << differ << " of " << cases
                                        << " answers change with a hint");
}
}

int main()
{
  CheckHintNearZero();
  return coretest::Finish("TestFaceTreeHints");
}
