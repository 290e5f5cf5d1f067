// A static k-d tree over 3-D points for exact nearest-neighbour queries.
#ifndef foldingmeshes_PointKdTree_h
#define foldingmeshes_PointKdTree_h

#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
/**
 * Built once over a point set; Nearest() returns the index (into the points given to the
 * constructor) of the point closest to a query. Ties are broken towards the smaller index,
 * so results do not depend on the build order. The points are copied.
 */
class PointKdTree
{
public:
  explicit PointKdTree(std::vector<Vec3> points);

  /// Index of the nearest point; -1 when the tree is empty.
  int Nearest(const Vec3& query) const;
  int NumberOfPoints() const { return static_cast<int>(this->Points.size()); }

private:
  struct Node
  {
    int point = -1; ///< index into Points of the splitting point
    int axis = 0;
    int left = -1; ///< node indices, -1 for none
    int right = -1;
  };
  int Build(std::vector<int>& order, int first, int last, int depth);
  void Search(int node, const Vec3& query, int& best, double& bestDistance2) const;

  std::vector<Vec3> Points;
  std::vector<Node> Nodes;
  int Root = -1;
};
}

#endif
