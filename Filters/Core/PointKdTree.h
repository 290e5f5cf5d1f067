// A static k-d tree over 3-D points for exact nearest-point lookups: the nearest point, the
// nearest within a radius (optionally among the points a predicate accepts), every point within
// a radius.
#ifndef foldingmeshes_PointKdTree_h
#define foldingmeshes_PointKdTree_h

#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
/**
 * Built once over a point set (copied); the answers are the points' ids: their indices into the
 * vector given to the constructor, or the ids given with them. Every answer is defined by the
 * points alone - the lowest (distance, id) - so it does not depend on the build order, and the
 * queries are const and thread-safe.
 *
 * The tree splits at the median of the longest side of its boxes, down to leaves of at most
 * LeafPoints points, and a search skips a subtree whose box lies farther than the best distance
 * so far with a relative margin of 1e-12, far above the rounding of the distances, so it never
 * skips a point whose computed distance could tie.
 */
class PointKdTree
{
public:
  /// Over every point; ids are the indices into `points`.
  explicit PointKdTree(std::vector<Vec3> points);
  /// Over points[ids[k]]; the answers are those ids.
  PointKdTree(const std::vector<Vec3>& points, const std::vector<int>& ids);

  /// The lowest (squared distance, id) to `query`; -1 when the tree is empty.
  int Nearest(const Vec3& query) const;

  /**
   * The lowest (distance, id) among the points v with member(v) whose distance
   * (points[v] - x).norm() is at most `radius`; -1: none. (The nearest-within-a-radius rule of
   * the builder's partners: the same answer as testing every point.)
   */
  template <typename Member>
  int NearestWithinWhere(const Vec3& x, double radius, Member member) const;
  int NearestWithin(const Vec3& x, double radius) const
  {
    return this->NearestWithinWhere(x, radius, [](int) { return true; });
  }

  /// Calls visit(id) for every point whose distance to x is at most `radius`, in no
  /// particular order (callers that need an order sort).
  template <typename Visit>
  void ForEachWithin(const Vec3& x, double radius, Visit visit) const;

  int NumberOfPoints() const { return static_cast<int>(this->Points.size()); }

private:
  static constexpr int LeafPoints = 8;
  /// Relative margin on squared distances when skipping boxes and points (see the class).
  static constexpr double Margin = 1.0 + 1e-12;
  struct Node
  {
    Vec3 lo, hi;      ///< box of the node's points
    int first, count; ///< leaf: range in Points / Ids; inner: count == 0
    int left, right;  ///< inner: children
  };
  void Build();
  /// The subtree over order[first, first + count) (indices into Points, partitioned here).
  int BuildNode(std::vector<int>& order, int first, int count);
  static double BoxDistance2(const Node& n, const Vec3& p)
  {
    return (n.lo - p).cwiseMax(p - n.hi).cwiseMax(0.0).squaredNorm();
  }
  /// Visits the leaves whose boxes are not farther than sqrt(limit2()) from p (limit2 is read
  /// again at every node: it may shrink during the visit), nearer child first.
  template <typename Limit2, typename VisitLeaf>
  void Traverse(const Vec3& p, Limit2 limit2, VisitLeaf visitLeaf) const;

  std::vector<Vec3> Points; ///< in tree order
  std::vector<int> Ids;     ///< per Points entry, its id
  std::vector<Node> Nodes;
};

template <typename Limit2, typename VisitLeaf>
void PointKdTree::Traverse(const Vec3& p, Limit2 limit2, VisitLeaf visitLeaf) const
{
  if (this->Nodes.empty())
    return;
  int stack[128]; // depth <= log2(points / 4) + 1 with median splits: far below 64
  double stackDistance2[128];
  int top = 0;
  stack[top] = 0;
  stackDistance2[top++] = BoxDistance2(this->Nodes[0], p);
  while (top > 0)
  {
    --top;
    if (stackDistance2[top] > limit2() * Margin)
      continue;
    const Node& node = this->Nodes[stack[top]];
    if (node.count > 0)
    {
      visitLeaf(node.first, node.first + node.count);
      continue;
    }
    const double dl = BoxDistance2(this->Nodes[node.left], p);
    const double dr = BoxDistance2(this->Nodes[node.right], p);
    const bool leftFirst = dl <= dr;
    stack[top] = leftFirst ? node.right : node.left;
    stackDistance2[top++] = leftFirst ? dr : dl;
    stack[top] = leftFirst ? node.left : node.right;
    stackDistance2[top++] = leftFirst ? dl : dr;
  }
}

template <typename Member>
int PointKdTree::NearestWithinWhere(const Vec3& x, double radius, Member member) const
{
  int best = -1;
  if (!(radius >= 0.0)) // negative or NaN: no point is within it
    return best;
  double bestDistance = radius;
  this->Traverse(
    x,
    [&]() { return bestDistance * bestDistance; },
    [&](int first, int last)
    {
      // The predicate first (the callers' are table lookups, cheaper than a distance); a
      // point farther than the best so far (squared, with the margin) cannot win; the others
      // are judged by the rule's own distance, (p - x).norm().
      const double limit2 = bestDistance * bestDistance * Margin;
      for (int k = first; k < last; ++k)
      {
        const int v = this->Ids[k];
        if (!member(v))
          continue;
        const Vec3 e = this->Points[k] - x;
        if (e.squaredNorm() > limit2)
          continue;
        const double d = e.norm();
        if (d <= bestDistance && (best < 0 || d < bestDistance || v < best))
        {
          bestDistance = d;
          best = v;
        }
      }
    });
  return best;
}

template <typename Visit>
void PointKdTree::ForEachWithin(const Vec3& x, double radius, Visit visit) const
{
  if (!(radius >= 0.0))
    return;
  const double radius2 = radius * radius;
  this->Traverse(
    x,
    [&]() { return radius2; },
    [&](int first, int last)
    {
      for (int k = first; k < last; ++k)
        if ((this->Points[k] - x).norm() <= radius)
          visit(this->Ids[k]);
    });
}
}

#endif
