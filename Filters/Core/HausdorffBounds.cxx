// Certified bounds on the Hausdorff distance between triangle surfaces (SurfaceDistance.h):
// branch and bound over subdivided triangles, bounded by dist(c) + r (Lipschitz) and by the
// corners' distances to the triangle closest to c (convexity).
#include "SurfaceDistance.h"

#include "ParallelTasks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

namespace foldingmeshes
{
namespace
{
/// A (sub)triangle of `from` and its bound.
struct Piece
{
  std::array<Vec3, 3> corner;
  double bound;    ///< dist(centroid) + largest corner distance to the centroid
  long long order; ///< creation number: ties in the heap are taken oldest first
};

struct ByBound
{
  bool operator()(const Piece& a, const Piece& b) const
  {
    return a.bound != b.bound ? a.bound < b.bound : a.order > b.order;
  }
};

Vec3 Centroid(const std::array<Vec3, 3>& c)
{
  return (c[0] + c[1] + c[2]) / 3.0;
}

double Radius(const std::array<Vec3, 3>& c, const Vec3& centroid)
{
  return std::sqrt(std::max({ (c[0] - centroid).squaredNorm(),
    (c[1] - centroid).squaredNorm(),
    (c[2] - centroid).squaredNorm() }));
}

/// The bound of piece `corner` whose centroid is at distance dc from `to`, closest to face f.
double Bound(const std::array<Vec3, 3>& corner,
  const Vec3& centroid,
  double dc,
  int f,
  const SurfaceDistanceQuery& to)
{
  double bound = dc + Radius(corner, centroid);
  if (f >= 0)
    bound = std::min(bound,
      std::max({ to.FaceDistance(corner[0], f),
        to.FaceDistance(corner[1], f),
        to.FaceDistance(corner[2], f) }));
  return bound;
}

/// Pieces split per round at most: enough work per parallel pass, few extra splits past the
/// point where the bound is settled.
constexpr size_t BatchPieces = 4096;
}

HausdorffBounds DirectedHausdorffBounds(const TriangleMesh& from,
  const SurfaceDistanceQuery& to,
  double tolerance,
  long long maxEvaluations,
  double floor)
{
  HausdorffBounds result;
  if (from.triangles.empty())
    return result;
  // Round 0: the vertices and centroids (the sampled measure), one piece per triangle.
  std::vector<Vec3> samples = SurfaceSamplePoints(from);
  std::vector<double> d;
  std::vector<int> face;
  to.Closest(samples, d, face);
  result.evaluations = static_cast<long long>(samples.size());
  for (double x : d)
    result.lower = std::max(result.lower, x);
  if (!std::isfinite(result.lower))
  {
    result.upper = result.lower;
    return result;
  }
  std::priority_queue<Piece, std::vector<Piece>, ByBound> heap;
  long long created = 0;
  const size_t firstCentroid = samples.size() - from.triangles.size();
  for (size_t f = 0; f < from.triangles.size(); ++f)
  {
    const Triangle& t = from.triangles[f];
    Piece piece{ { from.points[t[0]], from.points[t[1]], from.points[t[2]] }, 0.0, created++ };
    piece.bound = Bound(
      piece.corner, samples[firstCentroid + f], d[firstCentroid + f], face[firstCentroid + f], to);
    heap.push(piece);
  }
  std::vector<Piece> split;
  std::vector<std::array<Vec3, 3>> children;
  auto open = [&]()
  { return !heap.empty() && heap.top().bound > std::max(result.lower, floor) + tolerance; };
  while (open() && result.evaluations < maxEvaluations)
  {
    split.clear();
    while (open() && split.size() < BatchPieces)
    {
      split.push_back(heap.top());
      heap.pop();
    }
    // Four children each: their centroids bound them, their new corners (the midpoints) are
    // measured points.
    children.clear();
    samples.clear();
    for (const Piece& piece : split)
    {
      const auto& c = piece.corner;
      const Vec3 m01 = 0.5 * (c[0] + c[1]), m12 = 0.5 * (c[1] + c[2]), m20 = 0.5 * (c[2] + c[0]);
      for (const std::array<Vec3, 3>& child : { std::array<Vec3, 3>{ c[0], m01, m20 },
             std::array<Vec3, 3>{ m01, c[1], m12 },
             std::array<Vec3, 3>{ m20, m12, c[2] },
             std::array<Vec3, 3>{ m12, m20, m01 } })
      {
        children.push_back(child);
        samples.push_back(Centroid(child));
      }
      samples.push_back(m01);
      samples.push_back(m12);
      samples.push_back(m20);
    }
    to.Closest(samples, d, face);
    result.evaluations += static_cast<long long>(samples.size());
    for (double x : d)
      result.lower = std::max(result.lower, x);
    std::vector<double> bounds(children.size());
    ForRanges(static_cast<vtkIdType>(children.size()),
      0,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType c = begin; c < end; ++c)
        {
          const size_t at = 7 * (c / 4) + c % 4;
          bounds[c] = Bound(children[c], samples[at], d[at], face[at], to);
        }
      });
    for (size_t c = 0; c < children.size(); ++c)
      heap.push(Piece{ children[c], bounds[c], created++ });
  }
  result.upper = std::max(result.lower, heap.empty() ? 0.0 : heap.top().bound);
  return result;
}

HausdorffBounds SymmetricHausdorffBounds(const TriangleMesh& a,
  const TriangleMesh& b,
  double tolerance,
  long long maxEvaluations,
  double floor)
{
  HausdorffBounds result;
  const bool aEmpty = a.triangles.empty(), bEmpty = b.triangles.empty();
  if (aEmpty || bEmpty)
  {
    result.lower = result.upper = aEmpty && bEmpty ? 0.0 : std::numeric_limits<double>::infinity();
    return result;
  }
  const SurfaceDistanceQuery toA(a), toB(b);
  // The second direction needs no bound below what the first one measured.
  const HausdorffBounds ab = DirectedHausdorffBounds(a, toB, tolerance, maxEvaluations, floor);
  const HausdorffBounds ba =
    DirectedHausdorffBounds(b, toA, tolerance, maxEvaluations, std::max(floor, ab.lower));
  result.lower = std::max(ab.lower, ba.lower);
  result.upper = std::max(ab.upper, ba.upper);
  result.evaluations = ab.evaluations + ba.evaluations;
  return result;
}
}
