// PointKdTree against brute force: random clouds, clustered clouds, a lattice with exact ties
// (the smallest index must win, whatever the build order), duplicates, an empty tree and a
// single point.
#include "CoreTestUtilities.h"
#include "PointKdTree.h"

#include <limits>
#include <random>
#include <vector>

using foldingmeshes::PointKdTree;
using foldingmeshes::Vec3;

namespace
{
int BruteNearest(const std::vector<Vec3>& points, const Vec3& q)
{
  int best = -1;
  double bestD2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
  {
    const double d2 = (points[i] - q).squaredNorm();
    if (d2 < bestD2)
    {
      best = i;
      bestD2 = d2;
    }
  }
  return best;
}

void Check(const std::vector<Vec3>& points, const std::vector<Vec3>& queries, const char* label)
{
  const PointKdTree tree(points);
  EXPECT(tree.NumberOfPoints() == static_cast<int>(points.size()), label << ": size");
  int wrong = 0;
  for (const Vec3& q : queries)
    wrong += tree.Nearest(q) != BruteNearest(points, q);
  EXPECT(wrong == 0, label << ": " << wrong << " of " << queries.size() << " queries differ");
}
}

int main()
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random = [&](int n, double scale)
  {
    std::vector<Vec3> v(n);
    for (Vec3& p : v)
      p = scale * Vec3(u(rng), u(rng), u(rng));
    return v;
  };

  Check(random(2000, 1.0), random(3000, 1.5), "uniform");

  // Two tight clusters far apart, queries everywhere.
  std::vector<Vec3> clusters = random(500, 0.01);
  for (Vec3 p : random(500, 0.01))
    clusters.push_back(p + Vec3(5, 0, 0));
  Check(clusters, random(1000, 6.0), "clusters");

  // A lattice with duplicates: queries on lattice points and midpoints have exact ties.
  std::vector<Vec3> lattice;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k)
        lattice.emplace_back(i, j, k);
  for (int i = 0; i < 50; ++i)
    lattice.push_back(lattice[(i * 37) % 216]);
  std::vector<Vec3> ties;
  for (int i = 0; i < 11; ++i)
    for (int j = 0; j < 11; ++j)
      for (int k = 0; k < 11; ++k)
        ties.emplace_back(0.5 * i, 0.5 * j, 0.5 * k);
  Check(lattice, ties, "lattice ties");

  EXPECT(PointKdTree({}).Nearest(Vec3::Zero()) == -1, "empty tree must return -1");
  EXPECT(PointKdTree({ Vec3(1, 2, 3) }).Nearest(Vec3(-5, 0, 9)) == 0, "single point");
  return coretest::Finish("TestPointKdTree");
}
