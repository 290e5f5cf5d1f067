#include "FoldingSegmentation.h"

#include "PointKdTree.h"

namespace foldingmeshes
{
namespace
{
Vec3 Centroid(const std::vector<Vec3>& points, const Triangle& t)
{
  return (points[t[0]] + points[t[1]] + points[t[2]]) / 3.0;
}

bool ValidFace(int f, int numberOfFaces)
{
  return f >= 0 && f < numberOfFaces;
}
}

FoldingSegmentation LabelFacesByLeaf(const FoldingTree& tree,
  const std::vector<Vec3>& points,
  const std::vector<Triangle>& triangles)
{
  const int nf = static_cast<int>(triangles.size());
  FoldingSegmentation labels;
  labels.leaf.assign(nf, -1);
  labels.depth.assign(nf, -1);
  labels.role.assign(nf, -1);

  // Stored faces: their leaf.
  for (int i = 0; i < tree.NumberOfNodes(); ++i)
  {
    const FoldingNode& node = tree.nodes[i];
    if (node.kind != FoldingNodeKind::Leaf)
      continue;
    const FoldingLeafMesh& m = node.mesh;
    uint64_t segmentations = 0; // tear bits of rotation nodes mark their seams, not boundaries
    for (int a = node.parent; a >= 0; a = tree.nodes[a].parent)
      if (tree.nodes[a].kind == FoldingNodeKind::Segmentation)
        segmentations |= uint64_t(1) << tree.nodes[a].depth;
    for (int t = 0; t < m.NumberOfFaces(); ++t)
    {
      const int f = m.originalFaceIds[t];
      if (!ValidFace(f, nf))
        continue;
      const Triangle& tri = m.triangles[t];
      const bool tear =
        (m.tearMask[tri[0]] | m.tearMask[tri[1]] | m.tearMask[tri[2]]) & segmentations;
      labels.leaf[f] = i;
      labels.depth[f] = node.depth;
      labels.role[f] = static_cast<int>(tear ? FoldingFaceRole::Boundary : FoldingFaceRole::Kept);
    }
  }

  // Mirrored-away and turned-away faces, deepest folds and rotations first (preorder: a
  // child's index exceeds its parent's), so that a partner removed by a deeper one is already
  // labelled. A turned-away face's partner: the kept face nearest to its centroid turned back
  // by one of the k - 1 turns.
  for (int i = tree.NumberOfNodes() - 1; i >= 0; --i)
  {
    const FoldingNode& node = tree.nodes[i];
    const bool rotation = node.kind == FoldingNodeKind::Rotation;
    if ((node.kind != FoldingNodeKind::Folding && !rotation) || node.children.empty())
      continue;
    const FoldingNode& kept = tree.nodes[node.children[0]];
    std::vector<int> partners;
    std::vector<Vec3> centroids;
    partners.reserve(kept.originalFaces.size());
    centroids.reserve(kept.originalFaces.size());
    for (int f : kept.originalFaces)
      if (ValidFace(f, nf) && labels.leaf[f] >= 0)
      {
        partners.push_back(f);
        centroids.push_back(Centroid(points, triangles[f]));
      }
    const PointKdTree search(centroids);
    std::vector<AxisTurn> turnsBack;
    for (int j = 1; rotation && j < node.rotationOrder; ++j)
      turnsBack.emplace_back(node.axis, -2.0 * EIGEN_PI * j / node.rotationOrder);
    for (int f : node.discardedOriginalFaces)
    {
      if (!ValidFace(f, nf) || labels.role[f] != -1)
        continue;
      const Vec3 c = Centroid(points, triangles[f]);
      int nearest = -1;
      if (!rotation)
        nearest = search.Nearest(node.plane.Reflect(c));
      double best = 0.0;
      for (const AxisTurn& turn : turnsBack)
      {
        const Vec3 back = turn.Point(c);
        const int candidate = search.Nearest(back);
        const double d = candidate >= 0 ? (centroids[candidate] - back).norm() : 0.0;
        if (candidate >= 0 && (nearest < 0 || d < best))
        {
          nearest = candidate;
          best = d;
        }
      }
      labels.role[f] =
        static_cast<int>(rotation ? FoldingFaceRole::TurnedAway : FoldingFaceRole::MirroredAway);
      labels.depth[f] = node.depth;
      labels.leaf[f] = nearest >= 0 ? labels.leaf[partners[nearest]] : -1;
    }
  }
  return labels;
}
}
