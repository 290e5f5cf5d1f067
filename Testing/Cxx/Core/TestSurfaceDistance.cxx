// SurfaceDistance (the project's one Hausdorff measure) on meshes with known distances:
// - a flat grid and the same grid moved by t along its normal: every point distance is t,
//   Hausdorff and mean are t, both ways;
// - a grid and a grid twice as long in the same plane: the short one lies on the long one
//   (distance 0), the long one's far end is 1 away (Hausdorff 1, one-sided);
// - a cube [-1, 1]^3 and the cube scaled by s: every point of the small cube is s - 1 from
//   the big one; the big cube's corners are sqrt(3) (s - 1) from the small one (Hausdorff);
// - random points against a bumpy procedural mesh: equal to the brute-force minimum over all
//   triangles (ClosestPointTriangle);
// - the comparison is symmetric, does not depend on the SMP backend, and handles empty meshes;
// - a query factory (a VTK cell locator in the filters) answers every query, asked within a
//   radius the face tree bounds (the same distances), and unbounded where it finds nothing
//   within that radius; on a turned cylinder of long slivers (a rotated box frame) the factory
//   gets the surface turned into that frame and the distances stay the tree's;
// - SymmetricHausdorffBounds (over whole surfaces): exact cases bracketed within the
//   tolerance; a coarse plate over a plate with a dip between its samples, where the sampled
//   measure misses the farthest point: the bounds bracket a dense brute-force measure, the
//   upper bound holds with a coarse tolerance too, and nothing depends on the SMP backend.
#include "CoreTestUtilities.h"
#include "FaceTree.h"
#include "PointTriangleDistance.h"
#include "ProceduralMeshes.h"
#include "SurfaceDistance.h"

#include <Eigen/Geometry>

#include <vtkSMPTools.h>

#include <atomic>

#include <cmath>
#include <limits>
#include <random>

using namespace foldingmeshes;

namespace
{
/// An n x n grid of squares (4 triangles each, around a centre point) on [0, lx] x [0, 1], z = 0.
TriangleMesh Grid(int n, double lx)
{
  TriangleMesh m;
  auto at = [&](double x, double y)
  {
    m.points.emplace_back(x, y, 0.0);
    return static_cast<int>(m.points.size()) - 1;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const double x0 = lx * i / n, x1 = lx * (i + 1) / n, y0 = double(j) / n,
                   y1 = double(j + 1) / n;
      const int a = at(x0, y0), b = at(x1, y0), c = at(x1, y1), d = at(x0, y1);
      const int e = at(0.5 * (x0 + x1), 0.5 * (y0 + y1));
      m.triangles.push_back({ a, b, e });
      m.triangles.push_back({ b, c, e });
      m.triangles.push_back({ c, d, e });
      m.triangles.push_back({ d, a, e });
    }
  return m;
}

/// The surface of [-h, h]^3, n x n squares of 4 triangles per face.
TriangleMesh Cube(int n, double h)
{
  TriangleMesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : { -1.0, 1.0 })
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      auto at = [&](double a, double b)
      {
        Vec3 p;
        p[axis] = side * h;
        p[u] = a;
        p[v] = b;
        m.points.push_back(p);
        return static_cast<int>(m.points.size()) - 1;
      };
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
          const double a0 = -h + 2 * h * i / n, a1 = -h + 2 * h * (i + 1) / n;
          const double b0 = -h + 2 * h * j / n, b1 = -h + 2 * h * (j + 1) / n;
          const int p = at(a0, b0), q = at(a1, b0), r = at(a1, b1), s = at(a0, b1);
          const int c = at(0.5 * (a0 + a1), 0.5 * (b0 + b1));
          m.triangles.push_back({ p, q, c });
          m.triangles.push_back({ q, r, c });
          m.triangles.push_back({ r, s, c });
          m.triangles.push_back({ s, p, c });
        }
    }
  return m;
}

TriangleMesh Moved(TriangleMesh m, const Vec3& t, double scale = 1.0)
{
  for (Vec3& p : m.points)
    p = scale * p + t;
  return m;
}

double MaxAbsDifference(const std::vector<double>& d, double value)
{
  double worst = 0.0;
  for (double x : d)
    worst = std::max(worst, std::abs(x - value));
  return worst;
}
}

/// A brute-force closest-face query (every triangle) that counts how it is asked and marks its
/// answers (distance + Marker, which the face tree never gives); with `refuseBounded`, its
/// bounded queries find nothing (the fallback must then ask unbounded).
constexpr double Marker = 1e-10;
class CountingQuery : public foldingmeshes::ClosestFaceQuery
{
public:
  CountingQuery(const TriangleMesh& m, bool refuseBounded, std::atomic<int>* counts)
    : Mesh(m)
    , RefuseBounded(refuseBounded)
    , Counts(counts)
  {
  }
  foldingmeshes::ClosestFaceHit Closest(const Vec3& p) const override
  {
    ++this->Counts[0];
    foldingmeshes::ClosestFaceHit hit;
    for (size_t f = 0; f < this->Mesh.triangles.size(); ++f)
    {
      const auto& t = this->Mesh.triangles[f];
      const auto cp = foldingmeshes::ClosestPointTriangle(
        p, this->Mesh.points[t[0]], this->Mesh.points[t[1]], this->Mesh.points[t[2]]);
      if (std::sqrt(cp.squaredDistance) < hit.distance)
        hit = { static_cast<int>(f), std::sqrt(cp.squaredDistance), cp.point };
    }
    hit.distance += Marker;
    return hit;
  }
  foldingmeshes::ClosestFaceHit ClosestWithin(const Vec3& p, double radius) const override
  {
    ++this->Counts[1];
    if (this->RefuseBounded || !std::isfinite(radius))
      return {};
    --this->Counts[0]; // counted as a bounded query only
    const foldingmeshes::ClosestFaceHit hit = this->Closest(p);
    return hit.distance < radius ? hit : foldingmeshes::ClosestFaceHit();
  }

private:
  const TriangleMesh Mesh;
  const bool RefuseBounded;
  std::atomic<int>* Counts; // [0] unbounded queries, [1] bounded ones
};

int main()
{
  // Translated plate.
  {
    const double t = 0.0375;
    const TriangleMesh a = Grid(6, 1.0), b = Moved(a, Vec3(0, 0, t));
    const SurfaceComparison c = CompareSurfaces(a, b);
    EXPECT(std::abs(c.hausdorff - t) < 1e-12, "plate: Hausdorff " << c.hausdorff << " != " << t);
    EXPECT(std::abs(c.mean - t) < 1e-12, "plate: mean " << c.mean << " != " << t);
    EXPECT(MaxAbsDifference(c.aPointDistances, t) < 1e-12 &&
        MaxAbsDifference(c.bPointDistances, t) < 1e-12,
      "plate: point distances differ from the offset");
    EXPECT(c.samples == 2 * static_cast<int>(a.points.size() + a.triangles.size()),
      "plate: " << c.samples << " samples, not the vertices and centroids of both");
  }
  // A plate lying on a longer one.
  {
    const TriangleMesh a = Grid(4, 1.0), b = Grid(8, 2.0);
    const SurfaceComparison c = CompareSurfaces(a, b);
    EXPECT(c.aToB < 1e-12, "sub-plate: a -> b " << c.aToB << " != 0");
    EXPECT(std::abs(c.bToA - 1.0) < 1e-12, "sub-plate: b -> a " << c.bToA << " != 1");
    EXPECT(std::abs(c.hausdorff - 1.0) < 1e-12, "sub-plate: Hausdorff " << c.hausdorff);
    const SurfaceComparison r = CompareSurfaces(b, a);
    EXPECT(r.hausdorff == c.hausdorff && r.mean == c.mean && r.aToB == c.bToA,
      "sub-plate: the comparison is not symmetric");
  }
  // Cube in a scaled cube.
  {
    const double s = 1.15;
    const TriangleMesh small = Cube(3, 1.0), big = Moved(small, Vec3::Zero(), s);
    const SurfaceComparison c = CompareSurfaces(small, big);
    EXPECT(MaxAbsDifference(c.aPointDistances, s - 1.0) < 1e-12,
      "cube: a point of the small cube is not s - 1 from the big one");
    EXPECT(std::abs(c.aToB - (s - 1.0)) < 1e-12, "cube: small -> big " << c.aToB);
    EXPECT(std::abs(c.hausdorff - std::sqrt(3.0) * (s - 1.0)) < 1e-12,
      "cube: Hausdorff " << c.hausdorff << " != sqrt(3)(s - 1) " << std::sqrt(3.0) * (s - 1.0));
  }
  // Exactness against brute force, and independence of the SMP backend.
  {
    const testing::ProceduralMesh blob = testing::MakeBilateralBlob(1500);
    const TriangleMesh m = coretest::ToTriangleMesh(blob.mesh);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    std::vector<Vec3> queries(400);
    for (Vec3& q : queries)
      q = Vec3(u(random), u(random), u(random));
    const SurfaceDistanceQuery query(m);
    const std::vector<double> d = query.Distances(queries);
    int wrong = 0;
    for (size_t i = 0; i < queries.size(); ++i)
    {
      double best = std::numeric_limits<double>::infinity();
      for (const Triangle& t : m.triangles)
        best = std::min(best,
          std::sqrt(ClosestPointTriangle(queries[i], m.points[t[0]], m.points[t[1]], m.points[t[2]])
                      .squaredDistance));
      wrong += !(std::abs(best - d[i]) <= 1e-12 * (1.0 + best));
    }
    EXPECT(wrong == 0, "blob: " << wrong << " distances differ from brute force");
    const TriangleMesh moved = Moved(m, Vec3(0.01, -0.02, 0.005), 1.03);
    vtkSMPTools::SetBackend("Sequential");
    const SurfaceComparison one = CompareSurfaces(m, moved);
    vtkSMPTools::SetBackend("STDThread");
    vtkSMPTools::Initialize(2);
    const SurfaceComparison two = CompareSurfaces(m, moved);
    EXPECT(one.hausdorff == two.hausdorff && one.mean == two.mean &&
        one.aPointDistances == two.aPointDistances,
      "blob: results depend on the SMP backend");
    EXPECT(one.hausdorff > 0.0, "blob: moved mesh at distance 0");
  }
  // Bounds over whole surfaces.
  {
    const double t = 0.0375, tol = 1e-6;
    const TriangleMesh a = Grid(6, 1.0), b = Moved(a, Vec3(0, 0, t));
    const HausdorffBounds plate = SymmetricHausdorffBounds(a, b, tol);
    EXPECT(plate.lower <= t + 1e-12 && plate.upper >= t - 1e-12 && plate.upper - plate.lower <= tol,
      "bounds, plate: [" << plate.lower << ", " << plate.upper << "] around " << t);
    // The farthest points form a whole edge (x = 2): many pieces to settle, a coarser tolerance.
    const HausdorffBounds sub = SymmetricHausdorffBounds(Grid(4, 1.0), Grid(8, 2.0), 1e-3);
    EXPECT(std::abs(sub.lower - 1.0) < 1e-12 && sub.upper >= 1.0 && sub.upper - sub.lower <= 1e-3,
      "bounds, sub-plate: [" << sub.lower << ", " << sub.upper << "], expected 1");
  }
  {
    // b: the unit square at z = 0 with a pyramid dip of depth h at (0.43, 0.57); a: the square
    // in two triangles, whose vertices and centroids are all far from the dip. From a to b.
    const double h = 0.2;
    TriangleMesh a;
    a.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0) };
    a.triangles = { { 0, 1, 2 }, { 0, 2, 3 } };
    TriangleMesh b = a;
    b.points.push_back(Vec3(0.43, 0.57, -h));
    b.triangles = { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } };
    const SurfaceComparison sampled = CompareSurfaces(a, b);
    // Dense brute force: a lower bound of the true distance, within the grid's spacing.
    const SurfaceDistanceQuery toB(b);
    double dense = 0.0;
    {
      const int n = 400;
      std::vector<Vec3> points;
      for (const Triangle& tr : a.triangles)
        for (int i = 0; i <= n; ++i)
          for (int j = 0; i + j <= n; ++j)
            points.push_back((double(i) * a.points[tr[0]] + double(j) * a.points[tr[1]] +
                               double(n - i - j) * a.points[tr[2]]) /
              double(n));
      for (double x : toB.Distances(points))
        dense = std::max(dense, x);
    }
    const double tol = 1e-5;
    const HausdorffBounds bounds = DirectedHausdorffBounds(a, toB, tol);
    EXPECT(sampled.aToB < dense - 0.01,
      "dip: the sampled measure " << sampled.aToB << " does not miss the dip (dense " << dense
                                  << "): the case tests nothing");
    EXPECT(bounds.upper >= dense - 1e-12,
      "dip: upper bound " << bounds.upper << " below a measured distance " << dense);
    EXPECT(bounds.lower >= dense - tol - 1e-12 && bounds.upper - bounds.lower <= tol,
      "dip: bounds [" << bounds.lower << ", " << bounds.upper << "] not within " << tol
                      << " of the dense measure " << dense);
    const HausdorffBounds coarse = DirectedHausdorffBounds(a, toB, 0.05);
    EXPECT(coarse.upper >= dense - 1e-12 && coarse.evaluations < bounds.evaluations,
      "dip: coarse tolerance: upper " << coarse.upper << " (dense " << dense << "), "
                                      << coarse.evaluations << " evaluations vs "
                                      << bounds.evaluations);
    vtkSMPTools::SetBackend("Sequential");
    const HausdorffBounds one = DirectedHausdorffBounds(a, toB, tol);
    vtkSMPTools::SetBackend("STDThread");
    vtkSMPTools::Initialize(2);
    const HausdorffBounds two = DirectedHausdorffBounds(a, toB, tol);
    EXPECT(one.lower == two.lower && one.upper == two.upper && one.evaluations == two.evaluations,
      "dip: bounds depend on the SMP backend");
    const TriangleMesh empty;
    EXPECT(std::isinf(SymmetricHausdorffBounds(empty, b, tol).upper) &&
        SymmetricHausdorffBounds(empty, empty, tol).upper == 0.0,
      "bounds: empty meshes");
  }
  // A query factory: every distance through it, bounded by the tree's radius; unbounded
  // where the bounded query finds nothing.
  for (const bool refuse : { false, true })
  {
    const TriangleMesh surface = coretest::ToTriangleMesh(testing::MakeBilateralBlob(600).mesh);
    std::vector<Vec3> points;
    for (int i = 0; i < 200; ++i)
      points.push_back(Vec3(std::sin(1.7 * i), std::cos(2.3 * i), std::sin(0.9 * i + 1.0)));
    std::atomic<int> counts[2] = { 0, 0 };
    const SurfaceDistanceQuery plain(surface);
    const SurfaceDistanceQuery viaFactory(surface,
      [&](const TriangleMesh& m) { return std::make_unique<CountingQuery>(m, refuse, counts); });
    const std::vector<double> a = plain.Distances(points), b = viaFactory.Distances(points);
    // The factory's answers come back (the tree's distance + its marker), not the tree's own.
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
      worst = std::max(worst, std::abs(b[i] - (a[i] + Marker)));
    EXPECT(worst <= 1e-13,
      "factory query: not the factory's answers (the tree's distance + " << Marker << " off by "
                                                                         << worst << ")");
    EXPECT(counts[1] == static_cast<int>(points.size()) &&
        counts[0] == (refuse ? static_cast<int>(points.size()) : 0),
      "factory query (bounded queries refused: " << refuse << "): " << counts[1] << " bounded and "
                                                 << counts[0] << " unbounded queries for "
                                                 << points.size() << " points");
  }
  // Long slivers turned by a rigid motion (a rotated box frame): the factory's query holds the
  // surface turned into the tree's frame, is asked with the points turned alike, and its faces
  // are measured in the surface's own coordinates: the tree's distances.
  {
    TriangleMesh cylinder;
    const int segments = 300;
    const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
    for (int k = 0; k < segments; ++k)
      for (const double z : { -1.0, 1.0 })
      {
        const double a = 2.0 * 3.14159265358979323846 * k / segments;
        cylinder.points.push_back(turn * Vec3(0.05 * std::cos(a), 0.05 * std::sin(a), z));
      }
    for (int k = 0; k < segments; ++k)
    {
      const int a = 2 * k, b = 2 * ((k + 1) % segments);
      cylinder.triangles.push_back({ a, b, b + 1 });
      cylinder.triangles.push_back({ a, b + 1, a + 1 });
    }
    PreparedMesh prepared;
    prepared.points = cylinder.points;
    prepared.triangles = cylinder.triangles;
    for (const auto& t : cylinder.triangles)
      prepared.faceCentroids.push_back(
        (cylinder.points[t[0]] + cylinder.points[t[1]] + cylinder.points[t[2]]) / 3.0);
    prepared.faceDegenerate.assign(cylinder.triangles.size(), 0);
    prepared.vertexNormals.assign(cylinder.points.size(), Vec3::Zero());
    EXPECT(FaceTree(prepared).RotatedFrame(), "turned sliver cylinder: no rotated box frame");
    std::vector<Vec3> points;
    for (int i = 0; i < 300; ++i)
      points.push_back(Vec3(0.2 * std::sin(1.7 * i), 0.2 * std::cos(2.3 * i), std::sin(0.9 * i)));
    std::atomic<int> counts[2] = { 0, 0 };
    bool turned = false;
    const SurfaceDistanceQuery plain(cylinder);
    const SurfaceDistanceQuery viaFactory(cylinder,
      [&](const TriangleMesh& m)
      {
        turned = m.points.size() == cylinder.points.size() &&
          (m.points[0] - cylinder.points[0]).norm() > 1e-3;
        return std::make_unique<CountingQuery>(m, false, counts);
      });
    EXPECT(turned, "turned sliver cylinder: the factory got the surface unturned");
    std::vector<double> a, b;
    std::vector<int> fa, fb;
    plain.Closest(points, a, fa);
    viaFactory.Closest(points, b, fb);
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
      worst = std::max(worst, std::abs(b[i] - a[i]));
    EXPECT(worst <= 1e-12, "turned sliver cylinder: factory distances off the tree's by " << worst);
    EXPECT(counts[1] == static_cast<int>(points.size()) && counts[0] == 0,
      "turned sliver cylinder: " << counts[1] << " bounded and " << counts[0]
                                 << " unbounded queries for " << points.size() << " points");
  }
  // Empty meshes.
  {
    const TriangleMesh empty, plate = Grid(2, 1.0);
    EXPECT(std::isinf(CompareSurfaces(empty, plate).hausdorff), "empty vs plate not infinite");
    EXPECT(CompareSurfaces(empty, empty).hausdorff == 0.0, "empty vs empty not 0");
  }
  return coretest::Finish("TestSurfaceDistance");
}
