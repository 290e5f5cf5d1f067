// Rotational symmetry detection (issue 22) on procedural shapes whose axis and order are
// exact by construction:
// - twisted k-fold vases (k = 2..12): r = R(z) (1 + a cos(k theta + b z)) with an uneven
//   profile R, so the only symmetries are the turns by multiples of 360/k about the z axis
//   (no mirror plane, no half turn across the axis); the rings have a multiple of k
//   vertices, so a turn by 360/k maps vertices onto vertices;
// - a surface of revolution (a = 0): every order passes (continuous, order = the cap);
// - with noise of 0.05 epsilon, and with a separate box of about 15% of the area beside it;
// - shapes with no rotational symmetry get none: a lumpy vase with three harmonics, and the
//   procedural lumpy blob (MakeAsymmetricBlob, two seeds);
// - with a minimum order of 3, a 2-fold vase gets none and a 6-fold one its order.
// Every shape is moved by a seeded rigid motion; the axis found is compared with the moved z
// axis (angle, and offset at the centroid over the diagonal).
//
//   TestRotationalSymmetry
#include "CoreTestUtilities.h"
#include "ProceduralMeshes.h"
#include "RotationTestShapes.h"
#include "RotationalSymmetry.h"

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace foldingmeshes;
using namespace rotationtest;

namespace
{

struct Case
{
  const char* name;
  VaseShape shape;
  double noise = 0.0;       ///< per coordinate, in epsilon
  double boxFraction = 0.0; ///< area of the added box over the vase's
  unsigned seed = 1;
  int blobFaces = 0;    ///< > 0: MakeAsymmetricBlob of about this many faces instead of a vase
  int minimumOrder = 2; ///< RotationOptions::minimumOrder
};

/// Runs one case; expectedOrder 0: no symmetry expected; -1: continuous (order = the cap).
void Check(const Case& c, int expectedOrder, double minimumRegion)
{
  const int segments =
    std::max(1, c.shape.order) * ((48 + c.shape.order - 1) / std::max(1, c.shape.order));
  TriangleMesh m = c.blobFaces > 0
    ? coretest::ToTriangleMesh(testing::MakeAsymmetricBlob(c.blobFaces, c.seed).mesh)
    : MakeVase(c.shape, segments, 24);
  if (c.boxFraction > 0.0)
  {
    const double side =
      std::sqrt(c.boxFraction * coretest::SurfaceArea(m.points, m.triangles) / 6.0);
    AddBox(m, Vec3(1.3 + side, 0.2, 1.0), side);
  }
  const Eigen::Isometry3d motion = Motion(c.seed);
  for (Vec3& p : m.points)
    p = motion * p;
  Vec3 lo = m.points[0], hi = m.points[0];
  for (const Vec3& p : m.points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = (hi - lo).norm();
  RotationOptions options;
  options.epsilon = 0.02 * diagonal;
  options.minimumOrder = c.minimumOrder;
  if (c.noise > 0.0)
  {
    std::mt19937 g(c.seed + 100);
    for (Vec3& p : m.points)
      p += c.noise * options.epsilon * Vec3(Uniform(g), Uniform(g), Uniform(g));
  }
  const PreparedMesh mesh = coretest::Prepare(m);
  const auto start = std::chrono::steady_clock::now();
  const RotationResult r = DetectRotationalSymmetry(mesh, options);
  const double seconds = coretest::Seconds(start);

  RotationAxis truth;
  truth.origin = motion * Vec3(0, 0, 0);
  truth.direction = motion.linear() * Vec3::UnitZ();
  const Vec3 centroid = motion * Vec3(0, 0, 1);
  const double angle = AxisAngleDegrees(r.axis, truth);
  const double offset = AxisOffsetAt(truth, r.axis, centroid) / diagonal;
  std::printf("%-28s faces %6d: found %d order %2d continuous %d region %.3f rms/eps %.3f "
              "angle %.4f deg offset %.5f diag, %d axes, %d steps, %.2f s\n",
    c.name,
    mesh.NumberOfFaces(),
    r.found,
    r.order,
    r.continuous,
    r.symmetricAreaFraction,
    r.rmsResidual / options.epsilon,
    angle,
    offset,
    r.candidateAxes,
    r.iterations,
    seconds);
  EXPECT(r.distance.size() == mesh.points.size() && r.faceLabel.size() == m.triangles.size(),
    c.name << ": one distance per vertex and one label per face");
  if (expectedOrder == 0)
  {
    EXPECT(!r.found, c.name << ": no rotational symmetry expected, found order " << r.order);
    return;
  }
  EXPECT(r.found, c.name << ": rotational symmetry not found");
  if (expectedOrder < 0)
    EXPECT(r.continuous && r.order == DefaultMaximumRotationOrder,
      c.name << ": a surface of revolution is continuous, order the cap; got order " << r.order
             << " continuous " << r.continuous);
  else
    EXPECT(r.order == expectedOrder && !r.continuous,
      c.name << ": order " << r.order << " (continuous " << r.continuous << "), expected "
             << expectedOrder);
  const double maxAngle = c.noise > 0.0 || c.boxFraction > 0.0 ? 0.5 : 0.01;
  const double maxOffset = c.noise > 0.0 || c.boxFraction > 0.0 ? 2e-3 : 1e-4;
  EXPECT(angle < maxAngle, c.name << ": axis off by " << angle << " degrees");
  EXPECT(offset < maxOffset, c.name << ": axis offset " << offset << " diagonals");
  EXPECT(r.symmetricAreaFraction >= minimumRegion,
    c.name << ": region " << r.symmetricAreaFraction << " < " << minimumRegion);
  if (c.boxFraction > 0.0)
  {
    // The box's faces are not in the region.
    bool boxOut = true;
    for (size_t f = m.triangles.size() - 12; f < m.triangles.size(); ++f)
      boxOut = boxOut && !r.faceLabel[f];
    EXPECT(boxOut, c.name << ": the attached box is not rotationally symmetric");
  }
}
}

int main()
{
  for (int k = 2; k <= 12; ++k)
  {
    const std::string name = "twisted " + std::to_string(k) + "-fold";
    Check({ name.c_str(), { k, 0.15, 0.9, false }, 0.0, 0.0, static_cast<unsigned>(k) }, k, 0.97);
  }
  Check({ "revolution", { 1, 0.0, 0.0, false }, 0.0, 0.0, 21 }, -1, 0.97);
  Check({ "5-fold, noise 0.05 eps", { 5, 0.15, 0.9, false }, 0.05, 0.0, 22 }, 5, 0.9);
  Check({ "7-fold, box 15% of area", { 7, 0.15, 0.9, false }, 0.0, 0.15, 23 }, 7, 0.8);
  Check({ "4-fold, noise and box", { 4, 0.15, 0.9, false }, 0.05, 0.15, 24 }, 4, 0.75);
  Check({ "lumpy vase, no symmetry", { 1, 0.0, 0.0, true }, 0.0, 0.0, 25 }, 0, 0.0);
  for (unsigned seed : { 3u, 4u })
    Check({ "asymmetric blob", {}, 0.0, 0.0, seed, 4000 }, 0, 0.0);
  // RotationOptions::minimumOrder (the builder's, where a mirror fold covers the whole region):
  // an axis of order 2 yields nothing, one of order 6 is found as without it.
  Check({ "twisted 2-fold, orders >= 3", { 2, 0.15, 0.9, false }, 0.0, 0.0, 2, 0, 3 }, 0, 0.0);
  Check({ "twisted 6-fold, orders >= 3", { 6, 0.15, 0.9, false }, 0.0, 0.0, 6, 0, 3 }, 6, 0.97);
  return coretest::Finish("TestRotationalSymmetry");
}
