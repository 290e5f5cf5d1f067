// NoRingTriangleWithin, the early refusal of the unfolder's vertex removals
// (FoldingTreeUnfolderVertexRemoval.h): it may refuse a removal only where the budget check
// would fail too, so it must answer "some triangle within reach" whenever any triangle of
// three ring points, in any of the three vertex orders a re-triangulation creates it in (the
// ring's cyclic order, starting at any of its points), is within reach - measured with the
// same ClosestPointTriangle. The closest point's rounding depends on the vertex order: a
// first version measured one order only, with a 1e-9 relative margin, and a review found
// triangles where the orders differ by far more at distances of 1e-9 (the unfolder's slack).
// Checked: that triangle (a wrap-around ear's order is the nearest), random rings of 3-12
// points at such distances and at ordinary ones (the answer flips exactly at the smallest
// distance over all orders), and a ring whose triangles are all farther.
#include "CoreTestUtilities.h"
#include "FoldingTreeUnfolderVertexRemoval.h"
#include "PointTriangleDistance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace foldingmeshes;
using foldingmeshes::unfolder_detail::NoRingTriangleWithin;

namespace
{
double Distance(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
  return std::sqrt(ClosestPointTriangle(x, a, b, c).squaredDistance);
}

/// The smallest distance of x to a triangle of ring points over the cyclic orders.
double Nearest(const Vec3& x, const std::vector<Vec3>& points, const std::vector<int>& ring)
{
  double best = std::numeric_limits<double>::infinity();
  const size_t m = ring.size();
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j)
      for (size_t k = j + 1; k < m; ++k)
      {
        const Vec3 &p = points[ring[i]], &q = points[ring[j]], &r = points[ring[k]];
        best = std::min({ best, Distance(x, p, q, r), Distance(x, q, r, p), Distance(x, r, p, q) });
      }
  return best;
}

/// At the nearest distance the answer is "within", just below it "none within".
void CheckFlip(const Vec3& x,
  const std::vector<Vec3>& points,
  const std::vector<int>& ring,
  const std::string& name)
{
  const double nearest = Nearest(x, points, ring);
  EXPECT(!NoRingTriangleWithin(x, points, ring, nearest),
    name << ": a triangle at " << nearest << " is within that reach");
  const double below = std::nextafter(nearest, 0.0);
  EXPECT(NoRingTriangleWithin(x, points, ring, below),
    name << ": nothing is nearer than " << nearest << ", yet a triangle is within " << below);
}
}

int main()
{
  // The review's triangle: x lies about 1e-9 from it, and the orders (c, a, b) and (a, b, c)
  // give distances 1e-16 apart (relative 1e-8 here, far above a 1e-9 margin).
  const std::vector<Vec3> review{ Vec3(
                                    0.71790568464900339, 0.7557450347400968, 0.59618878077843318),
    Vec3(0.39744545441573392, 0.30852871662747394, 0.83216837237574992),
    Vec3(0.30400516442581721, 0.99526182677866437, 0.99365272821278006),
    Vec3(0.4254309217065565, 0.37676736369454, 0.81487044965124378) };
  const Vec3& x = review[3];
  const double abc = Distance(x, review[0], review[1], review[2]);
  const double cab = Distance(x, review[2], review[0], review[1]);
  std::printf("review triangle: (a, b, c) %.17g, (c, a, b) %.17g\n", abc, cab);
  EXPECT(abc > 0.5e-9 && abc < 2e-9, "the review's point lies about 1e-9 from its triangle");
  CheckFlip(x, review, { 0, 1, 2 }, "review triangle");
  EXPECT(!NoRingTriangleWithin(x, review, { 0, 1, 2 }, std::min(abc, cab)),
    "review triangle: within the smaller of the two orders' distances");

  // Random rings around a point, the point moved off their plane by 1e-9 .. 1e-1 of the
  // coordinates (the unfolder's slack is 1e-9 of the diagonal).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial)
  {
    const int m = 3 + trial % 10;
    const double scale = std::pow(10.0, trial % 4);
    std::vector<Vec3> points;
    for (int i = 0; i < m; ++i)
    {
      const double angle = 2.0 * M_PI * (i + 0.3 * u(rng)) / m;
      points.push_back(scale * Vec3(std::cos(angle), std::sin(angle), 0.05 * u(rng)));
    }
    const double height = scale * std::pow(10.0, -1.0 - trial % 9);
    points.push_back(scale * Vec3(0.1 * u(rng), 0.1 * u(rng), 0.0) + Vec3(0, 0, height));
    std::vector<int> ring(m);
    for (int i = 0; i < m; ++i)
      ring[i] = i;
    CheckFlip(points[m], points, ring, "random ring " + std::to_string(trial));
  }

  // A point far above a small ring: no triangle within a reach below its height.
  const std::vector<Vec3> square{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0) };
  EXPECT(NoRingTriangleWithin(Vec3(0.5, 0.5, 3.0), square, { 0, 1, 2, 3 }, 2.9),
    "a point 3 above the square has no triangle within 2.9");
  EXPECT(!NoRingTriangleWithin(Vec3(0.5, 0.5, 3.0), square, { 0, 1, 2, 3 }, 3.0),
    "a point 3 above the square has a triangle within 3");
  return coretest::Finish("TestRingTriangleRefusal");
}
