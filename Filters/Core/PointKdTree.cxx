#include "PointKdTree.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace foldingmeshes
{
PointKdTree::PointKdTree(std::vector<Vec3> points)
  : Points(std::move(points))
{
  this->Ids.resize(this->Points.size());
  std::iota(this->Ids.begin(), this->Ids.end(), 0);
  this->Build();
}

PointKdTree::PointKdTree(const std::vector<Vec3>& points, const std::vector<int>& ids)
  : Ids(ids)
{
  this->Points.reserve(ids.size());
  for (int v : ids)
    this->Points.push_back(points[v]);
  this->Build();
}

void PointKdTree::Build()
{
  if (this->Points.empty())
    return;
  // Leaves hold 4 to 8 points (median splits): fewer than n / 2 nodes.
  this->Nodes.reserve(this->Points.size() / 2 + 1);
  std::vector<int> order(this->Points.size());
  std::iota(order.begin(), order.end(), 0);
  this->BuildNode(order, 0, static_cast<int>(order.size()));
  // The points and ids in tree order, so that a leaf's points lie side by side.
  std::vector<Vec3> points(order.size());
  std::vector<int> ids(order.size());
  for (size_t k = 0; k < order.size(); ++k)
  {
    points[k] = this->Points[order[k]];
    ids[k] = this->Ids[order[k]];
  }
  this->Points = std::move(points);
  this->Ids = std::move(ids);
}

int PointKdTree::BuildNode(std::vector<int>& order, int first, int count)
{
  const int index = static_cast<int>(this->Nodes.size());
  Node node{ this->Points[order[first]], this->Points[order[first]], first, count, -1, -1 };
  for (int k = first + 1; k < first + count; ++k)
  {
    node.lo = node.lo.cwiseMin(this->Points[order[k]]);
    node.hi = node.hi.cwiseMax(this->Points[order[k]]);
  }
  this->Nodes.push_back(node);
  if (count <= LeafPoints)
    return index;
  // The median along the box's longest side; ties by id, so the tree is a function of the
  // points and ids alone.
  int axis = 0;
  (node.hi - node.lo).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order.begin() + first,
    order.begin() + first + half,
    order.begin() + first + count,
    [&](int a, int b)
    {
      const double pa = this->Points[a][axis], pb = this->Points[b][axis];
      return pa < pb || (pa == pb && this->Ids[a] < this->Ids[b]);
    });
  const int left = this->BuildNode(order, first, half);
  const int right = this->BuildNode(order, first + half, count - half);
  this->Nodes[index].count = 0;
  this->Nodes[index].left = left;
  this->Nodes[index].right = right;
  return index;
}

int PointKdTree::Nearest(const Vec3& query) const
{
  int best = -1;
  double bestDistance2 = std::numeric_limits<double>::infinity();
  this->Traverse(
    query,
    [&]() { return bestDistance2; },
    [&](int first, int last)
    {
      for (int k = first; k < last; ++k)
      {
        const double d2 = (this->Points[k] - query).squaredNorm();
        const int v = this->Ids[k];
        if (d2 < bestDistance2 || (d2 == bestDistance2 && v < best))
        {
          best = v;
          bestDistance2 = d2;
        }
      }
    });
  return best;
}
}
