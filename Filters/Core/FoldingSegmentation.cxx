#include "FoldingSegmentation.h"

#include "ParallelFor.h"
#include "PointKdTree.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

constexpr double Pi = 3.14159265358979323846;

/**
 * The kept centroids of a rotation node in cylindrical coordinates about its axis, for a lower
 * bound on the distance from a point turned back to the nearest of them: they lie in an arc of
 * angles [first, first + width] (the complement of the widest gap between them), so a point at
 * distance r from the axis whose angle is Delta outside that arc is at least
 * r sin(min(Delta, 90 degrees)) from every one of them (the distance across the axis alone).
 */
class KeptArc
{
public:
  KeptArc(const RotationAxis& axis, const std::vector<Vec3>& centroids)
    : Frame(RotationAxis{ axis.origin, axis.direction.normalized() })
  {
    std::vector<double> angles;
    angles.reserve(centroids.size());
    for (const Vec3& c : centroids)
      angles.push_back(this->Frame.Angle(c));
    std::sort(angles.begin(), angles.end());
    if (angles.size() < 2)
      return;
    // The widest gap between neighbouring angles (the last to the first across 2 pi too).
    double gap = angles.front() + 2.0 * Pi - angles.back();
    size_t after = 0; // the arc starts at angles[after]
    for (size_t i = 1; i < angles.size(); ++i)
      if (angles[i] - angles[i - 1] > gap)
      {
        gap = angles[i] - angles[i - 1];
        after = i;
      }
    this->First = angles[after];
    this->Width = 2.0 * Pi - gap;
    this->Bounded = this->Width < Pi; // else the bound is too weak to matter
  }
  /// A lower bound on the distance from p to the kept centroids (0 where none is known).
  double LowerBound(const Vec3& p) const
  {
    if (!this->Bounded)
      return 0.0;
    const double twoPi = 2.0 * Pi;
    double into = std::fmod(this->Frame.Angle(p) - this->First, twoPi); // past the arc's start
    if (into < 0.0)
      into += twoPi;
    const double outside = std::min(into - this->Width, twoPi - into); // <= 0: within
    // A margin far above the rounding of the angles and the turn (the bound only skips
    // queries that cannot win, never one that ties).
    const double delta = std::min(outside, 0.5 * Pi) - 1e-9;
    return delta > 0.0 ? this->Frame.Radius(p) * std::sin(delta) * (1.0 - 1e-9) : 0.0;
  }
  /// The size of the coordinates about the axis' origin (for rounding margins).
  double OriginNorm() const { return this->Frame.Axis.origin.norm(); }

private:
  const AxisFrame Frame;
  double First = 0.0, Width = 2.0 * Pi;
  bool Bounded = false;
};
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
    const KeptArc arc = rotation ? KeptArc(node.axis, centroids) : KeptArc(RotationAxis(), {});
    // The faces to label (each once: a face cut into pieces is discarded once per piece).
    std::vector<int> faces;
    for (int f : node.discardedOriginalFaces)
      if (ValidFace(f, nf) && labels.role[f] == -1)
      {
        labels.role[f] = -2; // listed
        faces.push_back(f);
      }
    // In parallel: each face's labels depend on the kept faces' only (labelled before).
    ParallelForRanges(static_cast<vtkIdType>(faces.size()),
      64,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<Vec3> backs; // per turn: the face's centroid turned back
        std::vector<double> bounds;
        for (vtkIdType i = begin; i < end; ++i)
        {
          const int f = faces[i];
          const Vec3 c = Centroid(points, triangles[f]);
          int nearest = -1;
          if (!rotation)
            nearest = search.Nearest(node.plane.Reflect(c));
          // A rotation: the nearest kept centroid over the turns back, the first on ties.
          // The turn whose point lies nearest the kept arc is asked first; a turn whose point's
          // bound (KeptArc, from the point turned, so whatever the turn's rounding) exceeds
          // what that one found cannot win and is not asked: the same answer.
          const size_t turns = turnsBack.size();
          backs.resize(turns);
          bounds.resize(turns);
          size_t first = 0;
          for (size_t t = 0; t < turns; ++t)
          {
            backs[t] = turnsBack[t].Point(c);
            bounds[t] = arc.LowerBound(backs[t]);
            if (bounds[t] < bounds[first])
              first = t;
          }
          int firstCandidate = -1;
          double reach = std::numeric_limits<double>::infinity();
          if (turns > 0)
          {
            firstCandidate = search.Nearest(backs[first]);
            if (firstCandidate >= 0)
              reach = (centroids[firstCandidate] - backs[first]).norm();
          }
          // Far above the rounding of the distances (relative to the coordinates' size).
          const double margin = 1e-9 * reach + 1e-12 * (c.norm() + arc.OriginNorm());
          double best = 0.0;
          for (size_t t = 0; t < turns; ++t)
          {
            if (t != first && bounds[t] > reach + margin)
              continue;
            const int candidate = t == first ? firstCandidate : search.Nearest(backs[t]);
            const double d = candidate >= 0 ? (centroids[candidate] - backs[t]).norm() : 0.0;
            if (candidate >= 0 && (nearest < 0 || d < best))
            {
              nearest = candidate;
              best = d;
            }
          }
          labels.role[f] = static_cast<int>(
            rotation ? FoldingFaceRole::TurnedAway : FoldingFaceRole::MirroredAway);
          labels.depth[f] = node.depth;
          labels.leaf[f] = nearest >= 0 ? labels.leaf[partners[nearest]] : -1;
        }
      });
  }
  return labels;
}
}
