// FaceTree::HasCompatibleFaceWithin (the rotation scan's query: is there a partner at all?)
// answers exactly ClosestCompatibleFace(...).face >= 0: on the bilateral blob, on the blob with
// large triangles across its box (a soup) and on a turned cylinder of slivers (boxes in a
// rotated frame), for random points near and far, random and surface normals, compatibility
// angles of 10 to 120 degrees (and cosines outside [-1, 1]) and search radii from 0 and a
// hundredth of the diagonal to past the box and infinity - and at the radius equal to the
// closest compatible distance itself, and just below it (the boundary, where a search that
// stops early could decide otherwise). Both answers must occur. Also: an exact tie at the
// radius (a point 1 above a face, radius 1: taken), a mesh of degenerate faces only and an
// empty mesh (no face: false).
#include "CoreTestUtilities.h"
#include "FaceTree.h"
#include "ProceduralMeshes.h"


#include <cmath>
#include <limits>
#include <random>

using foldingmeshes::FaceTree;
using foldingmeshes::PreparedMesh;
using foldingmeshes::TriangleMesh;
using foldingmeshes::Vec3;
using foldingmeshes::testing::MakeBilateralBlob;

namespace
{
const double kPi = 3.14159265358979323846;
std::mt19937_64 rng(7);

double U(double a, double b)
{
  return std::uniform_real_distribution<double>(a, b)(rng);
}

Vec3 RandomUnit()
{
  Vec3 v;
  do
    v = Vec3(U(-1, 1), U(-1, 1), U(-1, 1));
  while (v.squaredNorm() > 1.0 || v.squaredNorm() < 1e-6);
  return v.normalized();
}

void Check(const char* name, const PreparedMesh& m, int queries)
{
  const FaceTree tree(m);
  const double diagonal = m.diagonal;
  const double angles[] = { 10.0, 45.0, 90.0, 120.0 };
  int differ = 0, yes = 0, no = 0, boundary = 0;
  for (int i = 0; i < queries; ++i)
  {
    const int v = static_cast<int>(U(0, m.NumberOfPoints() - 1e-9));
    const bool near = i % 2 == 0;
    const Vec3 p = near
      ? Vec3(m.points[v] + U(0, 0.05) * diagonal * RandomUnit())
      : Vec3(m.boundsMin +
          (m.boundsMax - m.boundsMin).cwiseProduct(Vec3(U(-0.2, 1.2), U(-0.2, 1.2), U(-0.2, 1.2))));
    const Vec3 n = i % 3 == 0 ? RandomUnit() : m.vertexNormals[v];
    const double cosLimit =
      i % 17 == 0 ? (i % 2 ? 1.5 : -1.5) : std::cos(angles[i % 4] * kPi / 180.0);
    const double radii[] = { 0.0,
      0.01 * diagonal,
      0.05 * diagonal,
      0.3 * diagonal,
      2.0 * diagonal,
      std::numeric_limits<double>::infinity() };
    for (double r : radii)
    {
      const bool has = tree.HasCompatibleFaceWithin(p, n, cosLimit, r);
      const bool closest = tree.ClosestCompatibleFace(p, n, cosLimit, r).face >= 0;
      differ += has != closest;
      (has ? yes : no) += 1;
    }
    // At the closest compatible distance itself, and the next double below it.
    const FaceTree::Hit hit =
      tree.ClosestCompatibleFace(p, n, cosLimit, std::numeric_limits<double>::infinity());
    if (hit.face >= 0)
      for (double r : { hit.distance, std::nextafter(hit.distance, 0.0) })
      {
        differ += tree.HasCompatibleFaceWithin(p, n, cosLimit, r) !=
          (tree.ClosestCompatibleFace(p, n, cosLimit, r).face >= 0);
        ++boundary;
      }
  }
  EXPECT(
    differ == 0, name << ": " << differ << " existence answers differ from the closest search's");
  EXPECT(yes > 0 && no > 0,
    name << ": the queries must see both answers (" << yes << " yes, " << no << " no)");
  EXPECT(boundary > queries / 2, name << ": too few boundary queries (" << boundary << ")");
}

/// Exact cases: a tie at the radius, degenerate faces only, no faces.
void CheckExactCases()
{
  const PreparedMesh plate =
    coretest::Prepare({ { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) }, { { 0, 1, 2 } } });
  const FaceTree tree(plate);
  const Vec3 up(0, 0, 1), p(0.25, 0.25, 1.0);
  EXPECT(tree.HasCompatibleFaceWithin(p, up, 0.5, 1.0) &&
      tree.ClosestCompatibleFace(p, up, 0.5, 1.0).face == 0,
    "a face exactly at the radius: not taken");
  EXPECT(!tree.HasCompatibleFaceWithin(p, up, 0.5, std::nextafter(1.0, 0.0)),
    "a face just beyond the radius: taken");
  EXPECT(!tree.HasCompatibleFaceWithin(p, -up, 0.5, 2.0), "an incompatible face: taken");
  // Built by hand: PrepareMesh refuses meshes without area.
  PreparedMesh flat;
  flat.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0) };
  flat.triangles = { { 0, 1, 2 } };
  flat.faceDegenerate = { 1 };
  flat.faceCentroids = { Vec3(1, 0, 0) };
  flat.faceNormals = { up };
  flat.vertexNormals.assign(3, up);
  EXPECT(!FaceTree(flat).HasCompatibleFaceWithin(Vec3(1, 0, 0), up, -1.0, 10.0),
    "degenerate faces only: a partner found");
  const PreparedMesh none;
  EXPECT(!FaceTree(none).HasCompatibleFaceWithin(Vec3(0, 0, 0), up, -1.0, 10.0),
    "no faces: a partner found");
}
}

int main()
{
  CheckExactCases();
  const TriangleMesh blob = coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh);
  Check("bilateral blob", coretest::Prepare(blob), 600);

  const TriangleMesh soup = coretest::WithLargeTriangles(blob, 60, U, RandomUnit);
  Check("blob with large triangles", coretest::Prepare(soup), 600);

  TriangleMesh turned = coretest::SliverCylinder(0.025, 0.22, 300);
  for (Vec3& q : turned.points)
    q = coretest::Turned(q);
  const PreparedMesh cylinder = coretest::Prepare(turned);
  EXPECT(FaceTree(cylinder).RotatedFrame(), "turned cylinder: boxes not in a rotated frame");
  Check("turned cylinder of slivers", cylinder, 600);
  return coretest::Finish("TestFaceTreeExistence");
}
