#include "PointKdTree.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace foldingmeshes
{
PointKdTree::PointKdTree(std::vector<Vec3> points)
  : Points(std::move(points))
{
  std::vector<int> order(this->Points.size());
  std::iota(order.begin(), order.end(), 0);
  this->Nodes.reserve(order.size());
  this->Root = this->Build(order, 0, static_cast<int>(order.size()), 0);
}

int PointKdTree::Build(std::vector<int>& order, int first, int last, int depth)
{
  if (first >= last)
    return -1;
  const int axis = depth % 3;
  const int middle = first + (last - first) / 2;
  std::nth_element(order.begin() + first,
    order.begin() + middle,
    order.begin() + last,
    [&](int a, int b)
    {
      const double pa = this->Points[a][axis], pb = this->Points[b][axis];
      return pa < pb || (pa == pb && a < b);
    });
  const int node = static_cast<int>(this->Nodes.size());
  this->Nodes.push_back(Node{ order[middle], axis, -1, -1 });
  const int left = this->Build(order, first, middle, depth + 1);
  const int right = this->Build(order, middle + 1, last, depth + 1);
  this->Nodes[node].left = left;
  this->Nodes[node].right = right;
  return node;
}

void PointKdTree::Search(int node, const Vec3& query, int& best, double& bestDistance2) const
{
  if (node < 0)
    return;
  const Node& n = this->Nodes[node];
  const double d2 = (this->Points[n.point] - query).squaredNorm();
  if (d2 < bestDistance2 || (d2 == bestDistance2 && n.point < best))
  {
    best = n.point;
    bestDistance2 = d2;
  }
  const double offset = query[n.axis] - this->Points[n.point][n.axis];
  const int nearSide = offset < 0 ? n.left : n.right;
  const int farSide = offset < 0 ? n.right : n.left;
  this->Search(nearSide, query, best, bestDistance2);
  // <= so that equally distant points with smaller indices on the far side are found.
  if (offset * offset <= bestDistance2)
    this->Search(farSide, query, best, bestDistance2);
}

int PointKdTree::Nearest(const Vec3& query) const
{
  int best = -1;
  double bestDistance2 = std::numeric_limits<double>::infinity();
  this->Search(this->Root, query, best, bestDistance2);
  return best;
}
}
