// Points bucketed in a uniform grid for nearest-point lookups within a radius.
#ifndef foldingmeshes_PointBuckets_h
#define foldingmeshes_PointBuckets_h

#include "TriangleMesh.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace foldingmeshes
{
/**
 * Nearest of some points (indices into a point array, bucketed in cubes of size `cell`) to x
 * within a radius of at most `cell`: the lowest (distance, index) among the points of the 27
 * cells around x - whatever the order of the points and of the hash map, so lookups give the
 * same answer for any insertion order and thread count. Read-only lookups are thread-safe.
 */
struct PointBuckets
{
  /// Hash of three integers: a cell key, or a triangle's sorted corner ids.
  struct KeyHash
  {
    template <typename Integer>
    size_t operator()(const std::array<Integer, 3>& k) const
    {
      const uint64_t h = static_cast<uint64_t>(k[0]) * 0x9E3779B97F4A7C15ull ^
        static_cast<uint64_t>(k[1]) * 0xC2B2AE3D27D4EB4Full ^
        static_cast<uint64_t>(k[2]) * 0x165667B19E3779F9ull;
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  double cell = 1.0;
  std::unordered_map<std::array<long long, 3>, std::vector<int>, KeyHash> cells;
  std::array<long long, 3> Key(const Vec3& x) const
  {
    return { static_cast<long long>(std::floor(x.x() / cell)),
      static_cast<long long>(std::floor(x.y() / cell)),
      static_cast<long long>(std::floor(x.z() / cell)) };
  }
  void Add(const Vec3& x, int id) { cells[Key(x)].push_back(id); }
  /// Calls f(v) for every bucketed point v in the 27 cells around x (all those within `cell`
  /// of x, and some farther), in no particular order: callers that need an order sort.
  template <typename Visit>
  void ForEachNear(const Vec3& x, Visit f) const
  {
    const auto c = Key(x);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz)
        {
          auto it = cells.find({ c[0] + dx, c[1] + dy, c[2] + dz });
          if (it != cells.end())
            for (int v : it->second)
              f(v);
        }
  }
  int Nearest(const std::vector<Vec3>& points, const Vec3& x, double radius) const
  {
    return this->NearestWhere(points, x, radius, [](int) { return true; });
  }
  /// Nearest among the bucketed points v with member(v): the answer Nearest gives for buckets
  /// of those points alone (a point set that shrank keeps its buckets).
  template <typename Member>
  int NearestWhere(const std::vector<Vec3>& points,
    const Vec3& x,
    double radius,
    Member member) const
  {
    int best = -1;
    double bestDistance = radius;
    this->ForEachNear(x,
      [&](int v)
      {
        if (!member(v))
          return;
        const double d = (points[v] - x).norm();
        if (d <= bestDistance && (best < 0 || d < bestDistance || v < best))
        {
          bestDistance = d;
          best = v;
        }
      });
    return best;
  }
};
}

#endif
