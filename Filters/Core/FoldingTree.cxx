#include "FoldingTree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace foldingmeshes
{
const char* ToString(FoldingNodeKind kind)
{
  switch (kind)
  {
    case FoldingNodeKind::Leaf:
      return "Leaf";
    case FoldingNodeKind::Folding:
      return "Folding";
    case FoldingNodeKind::Segmentation:
      return "Segmentation";
    case FoldingNodeKind::Rotation:
      return "Rotation";
  }
  return "Unknown";
}

const char* ToString(LeafReason reason)
{
  switch (reason)
  {
    case LeafReason::None:
      return "None";
    case LeafReason::MinimumFaces:
      return "MinimumFaces";
    case LeafReason::MinimumArea:
      return "MinimumArea";
    case LeafReason::MaximumFolds:
      return "MaximumFolds";
    case LeafReason::NoSymmetry:
      return "NoSymmetry";
    case LeafReason::MaximumDepth:
      return "MaximumDepth";
    case LeafReason::DetectionFailed:
      return "DetectionFailed";
    case LeafReason::Aborted:
      return "Aborted";
  }
  return "Unknown";
}

int FoldingTree::NumberOfLeaves() const
{
  return static_cast<int>(this->Leaves().size());
}

std::vector<int> FoldingTree::Leaves() const
{
  std::vector<int> leaves;
  for (int i = 0; i < this->NumberOfNodes(); ++i)
    if (this->nodes[i].kind == FoldingNodeKind::Leaf)
      leaves.push_back(i);
  return leaves;
}

int FoldingTree::StoredFaces() const
{
  int count = 0;
  for (const FoldingNode& node : this->nodes)
    if (node.kind == FoldingNodeKind::Leaf)
      count += node.mesh.NumberOfFaces();
  return count;
}

int FoldingTree::StoredPoints() const
{
  int count = 0;
  for (const FoldingNode& node : this->nodes)
    if (node.kind == FoldingNodeKind::Leaf)
      count += node.mesh.NumberOfPoints();
  return count;
}

double FoldingTree::Compression() const
{
  if (this->numberOfOriginalFaces <= 0)
    return 0.0;
  return 1.0 - static_cast<double>(this->StoredFaces()) / this->numberOfOriginalFaces;
}

int FoldingTree::Height() const
{
  int height = 0;
  for (const FoldingNode& node : this->nodes)
    if (node.kind == FoldingNodeKind::Leaf)
      height = std::max(height, node.depth + 1);
  return height;
}

int FoldingTree::NumberOfFolds() const
{
  int count = 0;
  for (const FoldingNode& node : this->nodes)
    count += node.kind == FoldingNodeKind::Folding;
  return count;
}

int FoldingTree::NumberOfRotations() const
{
  int count = 0;
  for (const FoldingNode& node : this->nodes)
    count += node.kind == FoldingNodeKind::Rotation;
  return count;
}

int FoldingTree::MaximumFoldsOnPath() const
{
  int folds = 0;
  for (const FoldingNode& node : this->nodes)
    if (node.kind == FoldingNodeKind::Leaf)
      folds = std::max(folds, node.foldsAbove);
  return folds;
}

// (Over 100 lines because it is one flat list of checks, one per invariant of FoldingTree,
// each with its own message; split up, the list would no longer read as one.)
std::string FoldingTree::Validate() const
{
  std::ostringstream os;
  const int n = this->NumberOfNodes();
  if (n == 0)
    return "the tree has no nodes";
  if (!std::isfinite(this->diagonal) || !(this->diagonal > 0.0))
    return "the diagonal must be a positive, finite length";
  if (!std::isfinite(this->rootEpsilon) || !(this->rootEpsilon > 0.0))
    return "the root epsilon must be a positive, finite length";
  if (!(std::abs(this->nodes[0].epsilon - this->rootEpsilon) <= 1e-9 * this->rootEpsilon))
    return "the root epsilon differs from the root node's epsilon";
  if (this->numberOfOriginalFaces < 0 || this->numberOfOriginalPoints < 0 ||
    this->numberOfDroppedFaces < 0)
    return "negative numbers of original faces, points or dropped faces";
  for (const InputNonManifoldEdge& e : this->inputNonManifoldEdges)
    if (e.a < 0 || e.a >= e.b || e.faces <= 2 ||
      (this->numberOfOriginalPoints > 0 && e.b >= this->numberOfOriginalPoints))
      return "an input non-manifold edge has invalid point ids (not 0 <= a < b < original "
             "points) or at most two faces";
  if (this->StoredFaces() == 0)
    return "the leaves store no triangles";
  for (int i = 0; i < n; ++i)
  {
    const FoldingNode& node = this->nodes[i];
    os.str("");
    os << "node " << i << " (" << ToString(node.kind) << "): ";
    if (i == 0 && (node.parent != -1 || node.depth != 0 || node.foldsAbove != 0))
      return os.str() + "the root must have no parent, depth 0 and no folds above";
    if (i > 0)
    {
      if (node.parent < 0 || node.parent >= i)
        return os.str() + "parent index out of range or not before the node (preorder)";
      const FoldingNode& parent = this->nodes[node.parent];
      if (std::find(parent.children.begin(), parent.children.end(), i) == parent.children.end())
        return os.str() + "not listed among its parent's children";
      if (node.depth != parent.depth + 1)
        return os.str() + "depth is not the parent's depth + 1";
      const int folds = parent.foldsAbove + (parent.kind == FoldingNodeKind::Folding ? 1 : 0);
      if (node.foldsAbove != folds)
        return os.str() + "foldsAbove does not count the folding nodes above it";
    }
    if (node.depth >= MaximumFoldingTreeLevels)
      return os.str() + "deeper than the supported number of levels";
    if (!(node.epsilon >= 0.0) || !std::isfinite(node.epsilon))
      return os.str() + "invalid epsilon";
    for (int c : node.children)
      if (c <= i || c >= n || this->nodes[c].parent != i)
        return os.str() + "child index out of range or child with another parent";
    switch (node.kind)
    {
      case FoldingNodeKind::Leaf:
      {
        if (!node.children.empty())
          return os.str() + "a leaf has children";
        const FoldingLeafMesh& m = node.mesh;
        const size_t np = m.points.size(), nt = m.triangles.size();
        if (m.originalPointIds.size() != np || m.tearMask.size() != np ||
          m.planeMask.size() != np || m.projected.size() != np ||
          (!m.errorBudget.empty() && m.errorBudget.size() != np) ||
          (!m.inputBoundary.empty() && m.inputBoundary.size() != np))
          return os.str() + "per-point arrays do not match the number of points";
        if (m.originalFaceIds.size() != nt)
          return os.str() + "per-triangle arrays do not match the number of triangles";
        for (const Triangle& t : m.triangles)
          for (int v : t)
            if (v < 0 || v >= static_cast<int>(np))
              return os.str() + "triangle point index out of range";
        for (const MirroredFlag& t : m.mirroredFlags)
          if (t.point < 0 || t.point >= static_cast<int>(np) || t.level < 0 ||
            t.level >= node.depth)
            return os.str() + "mirrored flag with a point or level out of range";
        for (const Vec3& p : m.points)
          if (!p.allFinite())
            return os.str() + "non-finite point";
        break;
      }
      case FoldingNodeKind::Folding:
        if (node.children.size() != 1)
          return os.str() + "a folding node must have exactly one child";
        if (!node.plane.origin.allFinite() || !node.plane.normal.allFinite() ||
          std::abs(node.plane.normal.norm() - 1.0) > 1e-6)
          return os.str() + "invalid plane (normal must be unit length)";
        break;
      case FoldingNodeKind::Segmentation:
        if (node.children.size() < 2)
          return os.str() + "a segmentation node must have at least two children";
        break;
      case FoldingNodeKind::Rotation:
        if (node.children.size() != 1)
          return os.str() + "a rotation node must have exactly one child";
        if (!node.axis.origin.allFinite() || !node.axis.direction.allFinite() ||
          std::abs(node.axis.direction.norm() - 1.0) > 1e-6)
          return os.str() + "invalid rotation axis (direction must be unit length)";
        if (node.rotationOrder < 2 || node.rotationOrder > MaximumRotationNodeOrder)
          return os.str() + "rotation order out of range (2 .. 360)";
        for (int a = node.parent; a >= 0; a = this->nodes[a].parent)
          if (this->nodes[a].kind == FoldingNodeKind::Rotation)
            return os.str() + "a rotation node below another rotation node (not supported)";
        break;
      default:
        return os.str() + "unknown node kind";
    }
  }

  // Level flags: bit d of a leaf's planeMask stands for the folding node at depth d on its
  // path, bit d of its tearMask for the segmentation or rotation node there (a rotation's
  // seams; the builder sets no others).
  // The bounding box of the stored points, to check the diagonal against.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  int foldsOnPath = 0;
  double sectorsOnPath = 1.0; // product of the rotation orders on a path
  for (int i = 0; i < n; ++i)
  {
    const FoldingNode& node = this->nodes[i];
    if (node.kind != FoldingNodeKind::Leaf)
      continue;
    uint64_t folds = 0, segmentations = 0;
    double sectors = 1.0;
    for (int a = node.parent; a >= 0; a = this->nodes[a].parent)
    {
      const FoldingNode& above = this->nodes[a];
      if (above.kind == FoldingNodeKind::Folding)
        folds |= uint64_t(1) << above.depth;
      else if (above.kind == FoldingNodeKind::Segmentation)
        segmentations |= uint64_t(1) << above.depth;
      else if (above.kind == FoldingNodeKind::Rotation)
      {
        segmentations |= uint64_t(1) << above.depth; // the seams between its sectors
        sectors *= above.rotationOrder;
      }
    }
    sectorsOnPath = std::max(sectorsOnPath, sectors);
    const FoldingLeafMesh& m = node.mesh;
    for (int v = 0; v < m.NumberOfPoints(); ++v)
    {
      if ((m.planeMask[v] & ~folds) || (m.tearMask[v] & ~segmentations))
      {
        os.str("");
        os << "node " << i << " (Leaf): point " << v
           << " has a PlaneMask or TearMask bit for a level without a folding or "
              "segmentation (or rotation) node above the leaf";
        return os.str();
      }
      lo = lo.cwiseMin(m.points[v]);
      hi = hi.cwiseMax(m.points[v]);
    }
    foldsOnPath = std::max(foldsOnPath, node.foldsAbove);
  }
  // The stored points lie within the input's bounding box (points projected onto fold planes
  // within epsilon of it), and every fold keeps a half whose diameter is at least a fifth of
  // its region's (a rotation node of order k a sector at least 1/k of it): the extent of the
  // stored points bounds the diagonal from both sides - from
  // below only when no input triangle was dropped (the diagonal is the input triangles', and a
  // dropped triangle with a repeated vertex may lie far from the stored ones).
  const double extent = (hi - lo).norm();
  if (extent > 4.0 * this->diagonal + 4.0 * this->rootEpsilon ||
    (this->numberOfDroppedFaces == 0 &&
      this->diagonal > 8.0 * std::pow(5.0, foldsOnPath) * sectorsOnPath * extent))
  {
    os.str("");
    os << "the diagonal " << this->diagonal << " does not match the extent of the stored points "
       << extent;
    return os.str();
  }
  return std::string();
}
}
