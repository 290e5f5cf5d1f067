// Certified bounds on the Hausdorff distance between triangle surfaces (SurfaceDistance.h):
// branch and bound over subdivided triangles, bounded by dist(c) + r (Lipschitz), by the
// corners' distances to the triangle closest to c (convexity), and across that triangle's
// edges by the two triangles there, space split between them by a plane.
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
  int face;        ///< the triangle of `from` it is part of
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

/// The faces of `to` across each edge: the faces sharing edge k (corners k and k + 1) of
/// face f, with the index of that edge in them. Vertices are matched by position, so an
/// unwelded copy (a cut open seam, duplicated points) has its neighbours too.
class EdgeNeighbors
{
public:
  struct Across
  {
    int face; ///< the other face
    int edge; ///< the shared edge's index in it (its corners edge, edge + 1)
  };

  explicit EdgeNeighbors(const SurfaceDistanceQuery& to)
  {
    const std::vector<Vec3>& points = to.Points();
    const std::vector<Triangle>& triangles = to.Triangles();
    // Canonical point ids: the lowest id at the same position (non-finite points: their own).
    std::vector<int> order, canonical(points.size());
    for (size_t i = 0; i < points.size(); ++i)
    {
      canonical[i] = static_cast<int>(i);
      if (points[i].allFinite())
        order.push_back(static_cast<int>(i));
    }
    auto less = [&](int i, int j)
    {
      const Vec3 &p = points[i], &q = points[j];
      return p[0] != q[0] ? p[0] < q[0]
        : p[1] != q[1]    ? p[1] < q[1]
        : p[2] != q[2]    ? p[2] < q[2]
                          : i < j;
    };
    std::sort(order.begin(), order.end(), less);
    for (size_t k = 1; k < order.size(); ++k)
      if (points[order[k]] == points[order[k - 1]])
        canonical[order[k]] = canonical[order[k - 1]];
    // Edges by their canonical ends; the faces of one edge are each other's neighbours.
    struct Edge
    {
      int lo, hi, slot; ///< slot: 3 * face + edge
    };
    std::vector<Edge> edges;
    edges.reserve(3 * triangles.size());
    for (size_t f = 0; f < triangles.size(); ++f)
      for (int k = 0; k < 3; ++k)
      {
        const int a = canonical[triangles[f][k]], b = canonical[triangles[f][(k + 1) % 3]];
        if (a != b)
          edges.push_back(Edge{ std::min(a, b), std::max(a, b), static_cast<int>(3 * f) + k });
      }
    std::sort(edges.begin(),
      edges.end(),
      [](const Edge& x, const Edge& y) {
        return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.slot < y.slot;
      });
    this->Offsets.assign(3 * triangles.size() + 1, 0);
    std::vector<std::pair<int, Across>> pairs;
    for (size_t begin = 0, end = 0; begin < edges.size(); begin = end)
    {
      for (end = begin + 1; end < edges.size() && edges[end].lo == edges[begin].lo &&
           edges[end].hi == edges[begin].hi;
           ++end)
        ;
      // A non-manifold edge's faces are all candidates, a few of them at most.
      const size_t last = std::min(end, begin + MaximumFacesPerEdge);
      for (size_t i = begin; i < last; ++i)
        for (size_t j = begin; j < last; ++j)
          if (j != i)
            pairs.emplace_back(edges[i].slot, Across{ edges[j].slot / 3, edges[j].slot % 3 });
    }
    std::sort(pairs.begin(),
      pairs.end(),
      [](const std::pair<int, Across>& x, const std::pair<int, Across>& y)
      { return x.first != y.first ? x.first < y.first : x.second.face < y.second.face; });
    for (const auto& p : pairs)
      ++this->Offsets[p.first + 1];
    for (size_t i = 1; i < this->Offsets.size(); ++i)
      this->Offsets[i] += this->Offsets[i - 1];
    this->Faces.reserve(pairs.size());
    for (const auto& p : pairs)
      this->Faces.push_back(p.second);
  }

  const Across* Begin(int face, int edge) const
  {
    return this->Faces.data() + this->Offsets[3 * face + edge];
  }
  const Across* End(int face, int edge) const
  {
    return this->Faces.data() + this->Offsets[3 * face + edge + 1];
  }

private:
  static constexpr size_t MaximumFacesPerEdge = 4;
  std::vector<int> Offsets;
  std::vector<Across> Faces;
};

/// The unit direction perpendicular to edge (a, b) towards o (zero if there is none).
Vec3 Inward(const Vec3& a, const Vec3& b, const Vec3& o)
{
  const Vec3 e = b - a, w = o - a;
  const double ee = e.squaredNorm();
  if (!(ee > 0.0))
    return Vec3::Zero();
  const Vec3 u = w - (w.dot(e) / ee) * e;
  const double n = u.norm();
  return n > 0.0 && std::isfinite(n) ? Vec3(u / n) : Vec3::Zero();
}

/// The bound of piece `corner` whose centroid is at distance dc from `to`, closest to face f:
/// the least of dist(c) + r, max_i dist(v_i, f) and, for a piece reaching over an edge of f,
/// the two-face bound of every face g across that edge (see SurfaceDistance.h).
double Bound(const std::array<Vec3, 3>& corner,
  const Vec3& centroid,
  double dc,
  int f,
  const SurfaceDistanceQuery& to,
  const EdgeNeighbors& neighbors)
{
  double bound = dc + Radius(corner, centroid);
  if (f < 0)
    return bound;
  const std::array<double, 3> df = {
    to.FaceDistance(corner[0], f), to.FaceDistance(corner[1], f), to.FaceDistance(corner[2], f)
  };
  bound = std::min(bound, std::max({ df[0], df[1], df[2] }));
  const std::vector<Vec3>& points = to.Points();
  const std::vector<Triangle>& triangles = to.Triangles();
  const Triangle& t = triangles[f];
  for (int k = 0; k < 3 && bound > dc; ++k)
  {
    const Vec3 &a = points[t[k]], &b = points[t[(k + 1) % 3]];
    const Vec3 u = Inward(a, b, points[t[(k + 2) % 3]]);
    if (!((corner[0] - a).dot(u) < 0.0 || (corner[1] - a).dot(u) < 0.0 ||
          (corner[2] - a).dot(u) < 0.0))
      continue; // the piece does not reach over this edge
    for (const EdgeNeighbors::Across* g = neighbors.Begin(f, k); g != neighbors.End(f, k); ++g)
    {
      // Space split by the plane through the edge between the two faces, normal m: on its
      // side s >= 0 dist <= dist to f, on s <= 0 dist <= dist to g; both convex, so on the
      // piece's part on each side the bound is the largest value at that part's corners -
      // the piece's corners there and the points where its edges cross the plane.
      const Triangle& tg = triangles[g->face];
      const Vec3 m = u -
        Inward(points[tg[g->edge]], points[tg[(g->edge + 1) % 3]], points[tg[(g->edge + 2) % 3]]);
      std::array<double, 3> s;
      for (int i = 0; i < 3; ++i)
        s[i] = (corner[i] - a).dot(m);
      if (!std::isfinite(s[0] + s[1] + s[2]))
        continue;
      double value = 0.0;
      for (int i = 0; i < 3 && value < bound; ++i)
      {
        if (s[i] >= 0.0)
          value = std::max(value, df[i]);
        if (s[i] <= 0.0)
          value = std::max(value, to.FaceDistance(corner[i], g->face));
      }
      for (int i = 0; i < 3 && value < bound; ++i)
      {
        const int j = (i + 1) % 3;
        if ((s[i] < 0.0) == (s[j] < 0.0) || s[i] == 0.0 || s[j] == 0.0)
          continue;
        const Vec3 x = corner[i] + (s[i] / (s[i] - s[j])) * (corner[j] - corner[i]);
        value = std::max({ value, to.FaceDistance(x, f), to.FaceDistance(x, g->face) });
      }
      bound = std::min(bound, value);
    }
  }
  return bound;
}

/// Pieces split per round at most: enough work per parallel pass, few extra splits past the
/// point where the bound is settled.
constexpr size_t BatchPieces = 4096;
}

// (Over 100 lines because the subdivision loop - heap of pieces, settled bounds, parallel
// batches, the stop level - is one algorithm whose parts share the heap and the bounds.)
HausdorffBounds DirectedHausdorffBounds(const TriangleMesh& from,
  const SurfaceDistanceQuery& to,
  double tolerance,
  long long maxEvaluations,
  double floor,
  std::vector<int>* unproved)
{
  // Faces with a piece whose final bound is above floor + tolerance.
  std::vector<char> beyond(unproved ? from.triangles.size() : 0, 0);
  if (unproved)
    unproved->clear();
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
  const EdgeNeighbors neighbors(to);
  std::priority_queue<Piece, std::vector<Piece>, ByBound> heap;
  long long created = 0;
  // Pieces whose bound is settled (at most the stop level, which only grows: they are never
  // split) leave the heap; only the largest of their bounds is kept. Memory: the open pieces.
  double settled = 0.0;
  auto stopLevel = [&]() { return std::max(result.lower, floor) + tolerance; };
  auto keep = [&](const Piece& piece)
  {
    if (piece.bound > stopLevel())
      heap.push(piece);
    else
    {
      settled = std::max(settled, piece.bound);
      if (unproved && piece.bound > floor + tolerance)
        beyond[piece.face] = 1;
    }
  };
  const size_t firstCentroid = samples.size() - from.triangles.size();
  auto corners = [&](size_t f) -> std::array<Vec3, 3>
  {
    const Triangle& t = from.triangles[f];
    return { from.points[t[0]], from.points[t[1]], from.points[t[2]] };
  };
  // The triangles' bounds in parallel, kept in triangle order (the same heap for any thread
  // count).
  std::vector<double> firstBounds(from.triangles.size());
  ForRanges(static_cast<vtkIdType>(from.triangles.size()),
    0,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
        firstBounds[f] = Bound(corners(f),
          samples[firstCentroid + f],
          d[firstCentroid + f],
          face[firstCentroid + f],
          to,
          neighbors);
    });
  for (size_t f = 0; f < from.triangles.size(); ++f)
    keep(Piece{ corners(f), firstBounds[f], created++, static_cast<int>(f) });
  std::vector<Piece> split;
  std::vector<std::array<Vec3, 3>> children;
  auto open = [&]() { return !heap.empty() && heap.top().bound > stopLevel(); };
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
          bounds[c] = Bound(children[c], samples[at], d[at], face[at], to, neighbors);
        }
      });
    for (size_t c = 0; c < children.size(); ++c)
      keep(Piece{ children[c], bounds[c], created++, split[c / 4].face });
  }
  result.converged = !open();
  result.upper = std::max({ result.lower, settled, heap.empty() ? 0.0 : heap.top().bound });
  if (unproved)
  {
    for (; !heap.empty(); heap.pop())
      if (heap.top().bound > floor + tolerance)
        beyond[heap.top().face] = 1;
    unproved->clear();
    for (size_t f = 0; f < beyond.size(); ++f)
      if (beyond[f])
        unproved->push_back(static_cast<int>(f));
  }
  return result;
}

HausdorffBounds SymmetricHausdorffBounds(const TriangleMesh& a,
  const TriangleMesh& b,
  double tolerance,
  long long maxEvaluations,
  double floor,
  const ClosestFaceQueryFactory& factory)
{
  HausdorffBounds result;
  const bool aEmpty = a.triangles.empty(), bEmpty = b.triangles.empty();
  if (aEmpty || bEmpty)
  {
    result.lower = result.upper = aEmpty && bEmpty ? 0.0 : std::numeric_limits<double>::infinity();
    return result;
  }
  const SurfaceDistanceQuery toA(a, factory), toB(b, factory);
  // The second direction needs no bound below what the first one measured.
  const HausdorffBounds ab = DirectedHausdorffBounds(a, toB, tolerance, maxEvaluations, floor);
  const HausdorffBounds ba =
    DirectedHausdorffBounds(b, toA, tolerance, maxEvaluations, std::max(floor, ab.lower));
  result.lower = std::max(ab.lower, ba.lower);
  result.upper = std::max(ab.upper, ba.upper);
  result.evaluations = ab.evaluations + ba.evaluations;
  result.converged = ab.converged && ba.converged;
  return result;
}
}
