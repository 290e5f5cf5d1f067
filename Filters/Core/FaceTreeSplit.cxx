// How a FaceTree divides its faces: the large faces held apart under the root, and each node's
// split by the surface area of its children's boxes.
#include "FaceTree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace foldingmeshes
{
namespace
{
/// Faces whose longest edge is more than this many times the median face's are large: the
/// root's first child holds them, so that their boxes do not swell the boxes of the rest.
constexpr double LargeFaceRatio = 8.0;
/// ... unless more than one face in this many is large (then they are not outliers).
constexpr size_t MaximumLargeShare = 8;
/// Bins of the face centroids per axis for the split's surface-area estimate (FaceTree::Split).
constexpr int SplitBins = 16;
/// A node's split is estimated from every stride-th face (in Order), stride = faces / this
/// (rounded down): nodes of up to 2,047 faces use them all, larger ones 1,024 to 2,047 of them.
constexpr int SplitSampleFaces = 1024;
}

int FaceTree::PutLargeFacesFirst()
{
  const int count = static_cast<int>(this->Order.size());
  if (count <= LeafSize)
    return 0;
  std::vector<double> longest(count);
  for (int k = 0; k < count; ++k)
  {
    const Triangle& t = this->Mesh.triangles[this->Order[k]];
    const Vec3 &a = this->Mesh.points[t[0]], &b = this->Mesh.points[t[1]],
               &c = this->Mesh.points[t[2]];
    longest[k] = std::max({ (b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm() });
  }
  std::vector<double> sorted = longest;
  std::nth_element(sorted.begin(), sorted.begin() + count / 2, sorted.end());
  // The face at count / 2 (the upper median for an even count); an infinite one: none large.
  const double limit = LargeFaceRatio * LargeFaceRatio * sorted[count / 2];
  const int large = static_cast<int>(
    std::count_if(longest.begin(), longest.end(), [&](double l) { return l > limit; }));
  if (large == 0 || static_cast<size_t>(large) * MaximumLargeShare > static_cast<size_t>(count))
    return 0;
  std::vector<int> reordered;
  reordered.reserve(count);
  for (const bool first : { true, false })
    for (int k = 0; k < count; ++k)
      if ((longest[k] > limit) == first)
        reordered.push_back(this->Order[k]);
  this->Order = std::move(reordered);
  return large;
}

int FaceTree::Split(int first,
  int count,
  int depth,
  const std::vector<FaceBox>& boxes,
  const std::vector<Vec3>& centroids,
  const Vec3& clo,
  const Vec3& chi)
{
  struct Bin
  {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::max());
    int count = 0;
    void Add(const Vec3& l, const Vec3& h, int n)
    {
      this->lo = this->lo.cwiseMin(l);
      this->hi = this->hi.cwiseMax(h);
      this->count += n;
    }
    double Area() const
    {
      const Vec3 e = (this->hi - this->lo).cwiseMax(0.0);
      return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
    }
  };
  const auto begin = this->Order.begin() + first, end = begin + count;
  const Vec3 extent = chi - clo;
  int axis = -1, boundary = 0;
  if (depth < this->AreaSplitDepth)
  {
    // Per axis: the faces in bins of their centroids, each bin's box and count.
    Bin bins[3][SplitBins];
    Vec3 scale = Vec3::Zero();
    for (int a = 0; a < 3; ++a)
      if (extent[a] > 0.0 && std::isfinite(SplitBins / extent[a]))
        scale[a] = SplitBins / extent[a];
    // The comparisons keep the cast in range (and would send a NaN to bin 0).
    auto binOf = [&](int f, int a)
    {
      const double t = (centroids[f][a] - clo[a]) * scale[a];
      return t >= SplitBins - 1 ? SplitBins - 1 : t >= 1.0 ? static_cast<int>(t) : 0;
    };
    // Large nodes: every stride-th face (in Order) stands for the others in the estimate.
    const int stride = std::max(1, count / SplitSampleFaces);
    for (int k = first; k < first + count; k += stride)
      for (int a = 0; a < 3; ++a)
      {
        const int f = this->Order[k];
        bins[a][binOf(f, a)].Add(boxes[f].lo, boxes[f].hi, 1);
      }
    // The boundary between bins of least area x faces summed over the two sides (ties: the
    // lowest axis, then the lowest boundary).
    double best = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
    {
      Bin above[SplitBins + 1];
      for (int b = SplitBins - 1; b >= 0; --b)
      {
        above[b] = above[b + 1];
        above[b].Add(bins[a][b].lo, bins[a][b].hi, bins[a][b].count);
      }
      Bin below;
      for (int j = 1; j < SplitBins; ++j)
      {
        below.Add(bins[a][j - 1].lo, bins[a][j - 1].hi, bins[a][j - 1].count);
        if (below.count == 0 || above[j].count == 0)
          continue;
        const double cost = below.Area() * below.count + above[j].Area() * above[j].count;
        if (cost < best)
        {
          best = cost;
          axis = a;
          boundary = j;
        }
      }
    }
    if (axis >= 0)
      return static_cast<int>(
        std::partition(begin, end, [&](int f) { return binOf(f, axis) < boundary; }) - begin);
  }
  // The sampled centroids in one bin on every axis (or deep): the median along the longest axis.
  extent.maxCoeff(&axis);
  std::nth_element(begin,
    begin + count / 2,
    end,
    [&](int a, int b)
    {
      const double ca = centroids[a][axis], cb = centroids[b][axis];
      return ca != cb ? ca < cb : a < b;
    });
  return count / 2;
}
}
