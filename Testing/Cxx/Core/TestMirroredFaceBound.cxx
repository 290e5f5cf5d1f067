// MirroredFacesWithin (the builder's proof that a mirrored face stays within its limit at
// every point, not only at its corners) on a flat plate with a dip:
// - a large triangle over the plate whose corners and centroid are all on the flat part but
//   which spans a dip deeper than the limit: not within (the corners alone would say it is);
// - the same triangle over the plate without the dip (it lies over many coplanar faces, which
//   no single face bounds: the Lipschitz step settles it), and lifted by half the limit:
//   within; lifted by more than the limit: not within;
// - the quick proof (no query) for a small face well inside the limit;
// - the result does not depend on the SMP backend.
// End to end: the bunny (an approximately symmetric scan whose mirrored copies used to pass
// over dips of the input: 0.0204 of the diagonal without this proof), with the file's normals
// as vtkFoldingTreeBuilder uses them, folded and unfolded is within the root epsilon of the
// input at every point (SymmetricHausdorffBounds: proved, to 1e-7 of the diagonal); without
// error budgets it is not.
//
//   TestMirroredFaceBound [BUNNY]
#include "CoreTestUtilities.h"
#include "FaceTree.h"
#include "MeshIO.h"
#include "MirroredFaceBound.h"
#include "SurfaceDistance.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <string>

using namespace foldingmeshes;

namespace
{
/// The unit square at z = 0 as an n x n grid (two triangles per cell); with depth > 0 the 3 x 3
/// grid points around (0.5, 0.5) are lowered by depth (n = 20: a dip 0.2 wide at its rim).
TriangleMesh Plate(int n, double depth)
{
  TriangleMesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      m.points.emplace_back(double(i) / n, double(j) / n, 0.0);
  for (int i = n / 2 - 1; i <= n / 2 + 1; ++i)
    for (int j = n / 2 - 1; j <= n / 2 + 1; ++j)
      m.points[i * (n + 1) + j].z() = -depth;
  auto id = [n](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      m.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  return m;
}

/// Tests the triangle whose mirror image through x = -1 is `image`.
bool Within(const PreparedMesh& mesh,
  const std::array<Vec3, 3>& image,
  double limit,
  double cornerDistance = 1.0)
{
  Plane plane;
  plane.origin = Vec3(-1.0, 0.0, 0.0);
  plane.normal = Vec3::UnitX();
  std::vector<Vec3> points;
  for (const Vec3& x : image)
    points.push_back(plane.Reflect(x));
  const FaceTree tree(mesh);
  const FaceTreeQuery queries(tree);
  // cornerDistance 1: the quick proof never applies (it is tested on its own below).
  return MirroredFacesWithin(
    mesh,
    [&]() -> const ClosestFaceQuery& { return queries; },
    plane,
    { Triangle{ 0, 1, 2 } },
    points,
    std::vector<double>(3, cornerDistance),
    { limit },
    6)[0];
}
}

int main(int argc, char* argv[])
{
  const double limit = 0.05;
  const PreparedMesh flat = coretest::Prepare(Plate(20, 0.0));
  const PreparedMesh dip = coretest::Prepare(Plate(20, 0.3));
  // Corners and centroid (0.383, 0.417) off the dip (|x - 0.5|, |y - 0.5| <= 0.1); the
  // triangle covers (0.5, 0.5), 0.099 above the dip's walls.
  const std::array<Vec3, 3> big = { Vec3(0.05, 0.05, 0), Vec3(0.95, 0.25, 0), Vec3(0.15, 0.95, 0) };
  {
    const SurfaceDistanceQuery toDip(TriangleMesh{ dip.points, dip.triangles });
    const Vec3 centroid = (big[0] + big[1] + big[2]) / 3.0;
    EXPECT(toDip.Distance(big[0]) < 1e-12 && toDip.Distance(big[1]) < 1e-12 &&
        toDip.Distance(big[2]) < 1e-12 && toDip.Distance(centroid) < 1e-12,
      "setup: the triangle's corners and centroid are not on the flat part");
    EXPECT(toDip.Distance(Vec3(0.5, 0.5, 0.0)) > limit,
      "setup: the dip is not deeper than the limit under the triangle");
  }
  EXPECT(!Within(dip, big, limit), "a triangle spanning a deep dip was proved within the limit");
  EXPECT(Within(flat, big, limit), "a triangle lying on a flat plate was not proved within");
  auto lifted = [&](double h)
  {
    std::array<Vec3, 3> up = big;
    for (Vec3& x : up)
      x.z() += h;
    return up;
  };
  EXPECT(Within(flat, lifted(0.5 * limit), limit),
    "a triangle half the limit above the plate was not proved within");
  EXPECT(!Within(flat, lifted(1.2 * limit), limit), "a triangle above the limit was proved within");
  {
    // The quick proof: corners at most 0.01 away, edges 0.02: 0.01 + 0.02 / sqrt(3) < 0.05, no
    // tree needed (the provider fails the test if it is called).
    Plane plane;
    plane.origin = Vec3(-1.0, 0.0, 0.0);
    const std::vector<Vec3> points = { plane.Reflect(Vec3(0.5, 0.5, 0.01)),
      plane.Reflect(Vec3(0.52, 0.5, 0.01)),
      plane.Reflect(Vec3(0.5, 0.52, 0.01)) };
    bool called = false;
    const FaceTree tree(flat);
    const FaceTreeQuery queries(tree);
    const std::vector<char> ok = MirroredFacesWithin(
      flat,
      [&]() -> const ClosestFaceQuery&
      {
        called = true;
        return queries;
      },
      plane,
      { Triangle{ 0, 1, 2 } },
      points,
      std::vector<double>(3, 0.01),
      { limit },
      6);
    EXPECT(ok[0] && !called, "the quick proof did not settle a small face well inside the limit");
  }
  {
    vtkSMPTools::SetBackend("Sequential");
    const bool one = Within(dip, big, limit);
    vtkSMPTools::SetBackend("STDThread");
    vtkSMPTools::Initialize(2);
    const bool two = Within(dip, big, limit);
    EXPECT(one == two, "the result depends on the SMP backend");
  }
  if (argc > 1)
  {
    std::string error;
    const vtkSmartPointer<vtkPolyData> data = ReadMesh(argv[1], error);
    REQUIRE(data, argv[1] << ": " << error);
    const TriangleMesh bunny = coretest::ToTriangleMesh(data);
    double bounds[6];
    data->GetBounds(bounds);
    const double diagonal =
      Vec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
    const double eps = 0.02 * diagonal, tol = 1e-7 * diagonal;
    // The file's normals, as vtkFoldingTreeBuilder uses them.
    std::vector<Vec3> normals;
    if (vtkDataArray* n = data->GetPointData()->GetNormals())
      for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
        normals.emplace_back(n->GetComponent(i, 0), n->GetComponent(i, 1), n->GetComponent(i, 2));
    REQUIRE(normals.size() == bunny.points.size(), "bunny: the file has no point normals");
    // The budgets alone, without the verification that would repair a break afterwards.
    auto proved = [&](FoldingTreeOptions options)
    {
      options.epsilon = eps;
      options.verifyBound = false;
      FoldingTree tree;
      REQUIRE(BuildFoldingTree(bunny, normals, options, tree, error), "bunny: " << error);
      const UnfoldedMesh u = coretest::Unfold(tree);
      return SymmetricHausdorffBounds(
        bunny, TriangleMesh{ u.points, u.triangles }, tol, 50000000, eps);
    };
    const HausdorffBounds with = proved(FoldingTreeOptions());
    EXPECT(with.upper <= eps + tol,
      "bunny: unfold(fold(M)) is up to " << with.upper / diagonal
                                         << " of the diagonal from M, above the root epsilon");
    FoldingTreeOptions unbounded;
    unbounded.errorBudget = false;
    const HausdorffBounds without = proved(unbounded);
    EXPECT(without.lower > eps,
      "bunny without error budgets: within epsilon too (" << without.lower / diagonal
                                                          << "): the check proves nothing");
    std::printf("bunny: proved within %.5f of the diagonal (without budgets: at least %.5f)\n",
      with.upper / diagonal,
      without.lower / diagonal);
  }
  return coretest::Finish("TestMirroredFaceBound");
}
