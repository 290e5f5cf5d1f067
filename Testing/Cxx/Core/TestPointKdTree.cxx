// PointKdTree against brute force: random clouds, clustered clouds, a lattice with exact ties
// (the smallest index must win, whatever the build order), duplicates, an empty tree and a
// single point; the same for the radius queries (NearestWithin, NearestWithinWhere,
// ForEachWithin) over all points and over a subset of ids, with radii at exact distances.
#include "CoreTestUtilities.h"
#include "PointKdTree.h"

#include <algorithm>
#include <cmath>
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

/// The radius rule by definition: the lowest (norm, id) among `ids` (increasing) with member.
template <typename Member>
int BruteWithin(const std::vector<Vec3>& points,
  const std::vector<int>& ids,
  const Vec3& x,
  double radius,
  Member member)
{
  int best = -1;
  double bestDistance = radius;
  for (int v : ids)
  {
    const double d = (points[v] - x).norm();
    if (member(v) && d <= bestDistance && (best < 0 || d < bestDistance))
    {
      best = v;
      bestDistance = d;
    }
  }
  return best;
}

/// The radius queries of a tree over `ids` of `points` (all points when ids is every index),
/// at each query with each radius, against BruteWithin and an exhaustive ForEachWithin.
void CheckWithin(const std::vector<Vec3>& points,
  const std::vector<int>& ids,
  const std::vector<Vec3>& queries,
  const std::vector<double>& radii,
  const char* label)
{
  const bool all = ids.size() == points.size();
  const PointKdTree tree = all ? PointKdTree(points) : PointKdTree(points, ids);
  auto odd = [](int v) { return v % 2 == 1; };
  int wrong = 0, wrongWhere = 0, wrongSets = 0, found = 0, foundWhere = 0;
  for (const Vec3& q : queries)
    for (double r : radii)
    {
      const int expected = BruteWithin(points, ids, q, r, [](int) { return true; });
      found += expected >= 0;
      wrong += tree.NearestWithin(q, r) != expected;
      const int expectedWhere = BruteWithin(points, ids, q, r, odd);
      foundWhere += expectedWhere >= 0;
      wrongWhere += tree.NearestWithinWhere(q, r, odd) != expectedWhere;
      std::vector<int> visited, within;
      tree.ForEachWithin(q, r, [&](int v) { visited.push_back(v); });
      std::sort(visited.begin(), visited.end());
      for (int v : ids)
        if ((points[v] - q).norm() <= r)
          within.push_back(v);
      wrongSets += visited != within;
    }
  EXPECT(wrong == 0, label << ": NearestWithin differs on " << wrong << " queries");
  EXPECT(wrongWhere == 0, label << ": NearestWithinWhere differs on " << wrongWhere << " queries");
  EXPECT(wrongSets == 0, label << ": ForEachWithin's set differs on " << wrongSets << " queries");
  EXPECT(found > 0 && foundWhere > 0,
    label << ": no query has a point within its radius (a test that tests nothing)");
}

std::vector<int> Every(size_t n, int step)
{
  std::vector<int> ids;
  for (int v = 0; v < static_cast<int>(n); v += step)
    ids.push_back(v);
  return ids;
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

  // Radius queries: a random cloud (all points, and every third id), the lattice with its
  // duplicates at radii equal to lattice distances (exact ties at the radius: <= counts).
  const std::vector<Vec3> cloud = random(3000, 1.0);
  const std::vector<Vec3> cloudQueries = random(400, 1.2);
  const std::vector<double> cloudRadii{ 0.0, 0.01, 0.05, 0.2, 3.0 };
  CheckWithin(cloud, Every(cloud.size(), 1), cloudQueries, cloudRadii, "cloud within");
  CheckWithin(cloud, Every(cloud.size(), 3), cloudQueries, cloudRadii, "cloud subset within");
  const std::vector<double> latticeRadii{ 0.0, 0.5, std::sqrt(0.75), 1.0, std::sqrt(2.0), 1.5 };
  CheckWithin(lattice, Every(lattice.size(), 1), ties, latticeRadii, "lattice within");
  CheckWithin(lattice, Every(lattice.size(), 3), ties, latticeRadii, "lattice subset within");
  // The lattice in a random order: duplicates and equally distant points now have their ids
  // in any order against their coordinates, so a rule that keeps the first found of a tie
  // (instead of the lowest id) fails.
  std::vector<Vec3> shuffled = lattice;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  Check(shuffled, ties, "shuffled lattice ties");
  CheckWithin(shuffled, Every(shuffled.size(), 1), ties, latticeRadii, "shuffled lattice within");
  CheckWithin(shuffled, Every(shuffled.size(), 3), ties, latticeRadii, "shuffled subset within");
  // A query on a point itself at radius 0 finds it (or the lowest id of its duplicates).
  const PointKdTree latticeTree(lattice);
  int selfWrong = 0;
  for (int v = 0; v < static_cast<int>(lattice.size()); ++v)
  {
    int lowest = v;
    for (int w = 0; w < v; ++w)
      if (lattice[w] == lattice[v])
      {
        lowest = w;
        break;
      }
    selfWrong += latticeTree.NearestWithin(lattice[v], 0.0) != lowest;
  }
  EXPECT(selfWrong == 0, "radius 0 on the points themselves: " << selfWrong << " wrong");
  EXPECT(PointKdTree({}).NearestWithin(Vec3::Zero(), 1.0) == -1, "empty tree within a radius");
  EXPECT(PointKdTree(lattice, {}).NearestWithin(Vec3::Zero(), 10.0) == -1, "empty subset");

  EXPECT(PointKdTree({}).Nearest(Vec3::Zero()) == -1, "empty tree must return -1");
  EXPECT(PointKdTree({ Vec3(1, 2, 3) }).Nearest(Vec3(-5, 0, 9)) == 0, "single point");
  return coretest::Finish("TestPointKdTree");
}
