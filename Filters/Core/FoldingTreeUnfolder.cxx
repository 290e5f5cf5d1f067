// Folding-tree unfolding: postorder traversal, mirrored copies, on-plane merging, reports.
#include "FoldingTreeUnfolder.h"
#include "EdgeTable.h"
#include "FoldingTreeUnfolderInternal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

namespace foldingmeshes
{
namespace unfolder_detail
{
namespace
{
/// A rotation node's points within this share of the diagonal of its axis are on it (Turn;
/// the builder's sector cut moves its poles onto the axis, 1e-6 of the diagonal around it).
constexpr double PoleOfDiagonal = 1e-9;
}

Piece Unfolder::Unfold(int index)
{
  const FoldingNode& node = this->Tree.nodes[index];
  Piece piece;
  if (this->Aborted)
    return piece;
  switch (node.kind)
  {
    case FoldingNodeKind::Leaf:
      piece = this->FromLeaf(index);
      break;
    case FoldingNodeKind::Folding:
      piece = this->Unfold(node.children[0]);
      this->Reflect(node, piece);
      break;
    case FoldingNodeKind::Rotation:
      piece = this->Unfold(node.children[0]);
      this->Turn(index, piece);
      break;
    case FoldingNodeKind::Segmentation:
    {
      std::vector<int> childOfPoint;
      for (size_t c = 0; c < node.children.size(); ++c)
      {
        const Piece child = this->Unfold(node.children[c]);
        piece.Append(child);
        childOfPoint.insert(childOfPoint.end(), child.points.size(), static_cast<int>(c));
      }
      SeamReport seam;
      seam.node = index;
      seam.depth = node.depth;
      if (this->Options.stitch)
        this->Stitch(node, piece, childOfPoint, seam);
      else
        this->CountTears(node, piece, seam);
      this->Result.seams.push_back(seam);
      if (this->Options.stitch && this->Options.removeProjectedPoints)
        this->Result.removedProjectedPoints += this->RemoveProjectedPoints(&node, piece, nullptr);
      break;
    }
  }
  ++this->Done;
  if (this->Options.progress &&
    !this->Options.progress(static_cast<double>(this->Done) / this->Tree.NumberOfNodes()))
    this->Aborted = true;
  return piece;
}

Piece Unfolder::FromLeaf(int index)
{
  const FoldingLeafMesh& m = this->Tree.nodes[index].mesh;
  UnfoldCopy copy;
  copy.leaf = index;
  const int id = static_cast<int>(this->Result.copies.size());
  this->Result.copies.push_back(copy);
  Piece piece;
  piece.points = m.points;
  piece.triangles = m.triangles;
  piece.pointOrig = m.originalPointIds;
  piece.pointCopy.assign(m.points.size(), id);
  piece.tear.assign(m.points.size(), {});
  for (int v = 0; v < m.NumberOfPoints(); ++v)
    for (int level = 0; level < MaximumFoldingTreeLevels; ++level)
      if (m.tearMask[v] & (uint64_t(1) << level))
        piece.tear[v].push_back({ 2 * level, 0 });
  for (const MirroredFlag& t : m.mirroredFlags)
    piece.tear[t.point].push_back(
      { 2 * t.level + (t.flag == LevelFlag::Plane ? 1 : 0), t.mirrorMask });
  for (TearList& t : piece.tear)
    Normalize(t);
  piece.onPlane = m.planeMask;
  if (m.errorBudget.empty() || !this->Options.respectErrorBudget)
    piece.budget.assign(m.points.size(), std::numeric_limits<double>::infinity());
  else
    piece.budget = m.errorBudget;
  if (m.inputBoundary.empty())
    piece.border.assign(m.points.size(), 2);
  else
    piece.border = m.inputBoundary;
  piece.projected = m.projected;
  piece.faceOrig = m.originalFaceIds;
  piece.faceCopy.assign(m.triangles.size(), id);
  piece.faceFilled.assign(m.triangles.size(), 0);
  return piece;
}

void Unfolder::Reflect(const FoldingNode& node, Piece& piece)
{
  const Plane& p = node.plane;
  const uint64_t bit = uint64_t(1) << node.depth;
  const double tolerance = this->Options.planeTolerance * this->Tree.diagonal;
  // Mirrored copies.
  std::map<int, int> mirrorCopy;
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() - 2.0 * p.normal * p.normal.transpose();
  const Vec3 shift = 2.0 * p.normal.dot(p.origin) * p.normal;
  for (int c : piece.faceCopy)
    mirrorCopy[c] = -1;
  for (int c : piece.pointCopy)
    mirrorCopy[c] = -1;
  for (auto& entry : mirrorCopy)
  {
    UnfoldCopy copy = this->Result.copies[entry.first];
    copy.mirrorMask |= bit;
    copy.mirrored = !copy.mirrored;
    copy.linear = R * copy.linear;
    copy.translation = R * copy.translation + shift;
    entry.second = static_cast<int>(this->Result.copies.size());
    this->Result.copies.push_back(copy);
  }
  const int n = piece.NumberOfPoints();
  // Open boundary edges lying within the fold-line slab: the copies of fold-line vertices
  // made by approximate symmetries below this node are off the plane by less than the
  // node's epsilon (the error budget of its subtree).
  std::vector<char> inSlab(n, 0);
  if (this->Options.foldLineToleranceScale > 0.0)
  {
    const double slab = this->Options.foldLineToleranceScale * node.epsilon;
    for (const Edge& e : OpenEdges(piece.triangles))
    {
      const int a = e.first, b = e.second;
      if (std::abs(p.SignedDistance(piece.points[a])) <= slab &&
        std::abs(p.SignedDistance(piece.points[b])) <= slab)
        inSlab[a] = inSlab[b] = 1;
    }
  }
  std::vector<int> mirror(n);
  for (int v = 0; v < n; ++v)
  {
    const double s = p.SignedDistance(piece.points[v]);
    if ((piece.onPlane[v] & bit) || IsOnPlane(piece.tear[v], node.depth) ||
      std::abs(s) <= tolerance || (inSlab[v] && std::abs(s) <= piece.budget[v]))
    {
      // Both copies: the reflection at this fold does not matter. Onto the plane, or as
      // far towards it as the error budget allows (flagged copies of fold-line vertices
      // made by approximate folds below may lie off it).
      const double move =
        std::abs(s) <= tolerance ? std::abs(s) : std::min(std::abs(s), piece.budget[v]);
      if (move > 0.0)
        piece.points[v] -= (s > 0 ? move : -move) * p.normal;
      piece.budget[v] = std::max(0.0, piece.budget[v] - move);
      piece.onPlane[v] |= bit;
      for (auto& e : piece.tear[v])
        e.second &= ~bit;
      Normalize(piece.tear[v]);
      mirror[v] = v;
      ++this->Result.planeMergedVertices;
      continue;
    }
    TearList kept, reflected;
    for (const auto& e : piece.tear[v])
      if (e.second & bit)
        reflected.push_back({ e.first, e.second & ~bit });
      else
        kept.push_back(e);
    piece.tear[v] = std::move(kept);
    mirror[v] = piece.NumberOfPoints();
    piece.points.push_back(p.Reflect(piece.points[v]));
    piece.pointOrig.push_back(piece.pointOrig[v]);
    piece.pointCopy.push_back(mirrorCopy[piece.pointCopy[v]]);
    piece.tear.push_back(std::move(reflected));
    piece.onPlane.push_back(0); // the copy's own fold-line flags come from `reflected`
    piece.budget.push_back(piece.budget[v]);
    piece.border.push_back(piece.border[v]);
    piece.projected.push_back(piece.projected[v]);
  }
  const int nf = piece.NumberOfFaces();
  for (int f = 0; f < nf; ++f)
  {
    const Triangle t = piece.triangles[f];
    if (mirror[t[0]] == t[0] && mirror[t[1]] == t[1] && mirror[t[2]] == t[2])
    {
      ++this->Result.droppedMirrorFaces;
      continue;
    }
    piece.triangles.push_back({ mirror[t[0]], mirror[t[2]], mirror[t[1]] });
    piece.faceOrig.push_back(piece.faceOrig[f]);
    piece.faceCopy.push_back(mirrorCopy[piece.faceCopy[f]]);
    piece.faceFilled.push_back(piece.faceFilled[f]);
  }
  Consume(piece, 2 * node.depth + 1);
  if (this->Options.removeProjectedPoints)
    this->Result.removedProjectedPoints += this->RemoveProjectedPoints(&node, piece, nullptr);
  if (this->Options.matchDiscardedDensity)
    this->Result.thinnedCopyPoints += this->MatchDiscardedDensity(node, piece);
  this->Result.foldExcessFaces += std::max(0, FoldExcessFaces(node, piece));
}

/// The sector turned k - 1 times by 360/k degrees about the axis (copies keep their
/// orientation), then the seams between the sectors stitched like a segmentation's, within
/// RotationStitchShare(k) of its tolerance: the builder flagged the seam vertices with the node's
/// tear bit and made them meet.
void Unfolder::Turn(int index, Piece& piece)
{
  const FoldingNode& node = this->Tree.nodes[index];
  const int k = node.rotationOrder;
  // Points on the axis (the builder moves a sector's poles onto it) stay where they are in
  // every copy: turned, they would differ by rounding, and the stitch, which pairs each seam
  // vertex with its nearest one of another copy, could then weld the k poles into two points
  // (a fan of 6 turned copies came back with a doubled pole and three faces over the hole).
  // A seam vertex near the axis - a pole read back from a compact file, off the axis by up to
  // the quantisation error - goes onto it first, when its budget allows the move: within half
  // of StitchToleranceScale times the node's epsilon (at least five times the sectors' stitch
  // tolerance, which pairs the k copies of a point only where they lie that close together), so
  // that the k copies of a pole meet on the axis however far quantisation moved it.
  const double onAxis = PoleOfDiagonal * this->Tree.diagonal;
  const double nearAxis = 0.5 * this->Options.stitchToleranceScale * node.epsilon;
  const Vec3 direction = node.axis.direction.normalized(); // read trees: unit within 1e-6
  std::vector<char> pole(piece.points.size(), 0);
  for (int v = 0; v < piece.NumberOfPoints(); ++v)
  {
    const Vec3 r = piece.points[v] - node.axis.origin;
    const Vec3 off = r - r.dot(direction) * direction;
    const double d = off.norm();
    pole[v] = d <= onAxis;
    if (!pole[v] && this->Options.stitch && d <= nearAxis && d <= piece.budget[v] &&
      IsTear(piece.tear[v], node.depth))
    {
      piece.points[v] -= off;
      piece.budget[v] -= d;
      pole[v] = 1;
    }
  }
  const Piece sector = piece;
  std::vector<int> sectorOf(piece.points.size(), 0);
  for (int j = 1; j < k; ++j)
  {
    const AxisTurn turn(node.axis, 2.0 * EIGEN_PI * j / k);
    std::map<int, int> turnedCopy;
    for (int c : sector.faceCopy)
      turnedCopy[c] = -1;
    for (int c : sector.pointCopy)
      turnedCopy[c] = -1;
    for (auto& entry : turnedCopy)
    {
      UnfoldCopy copy = this->Result.copies[entry.first];
      copy.linear = turn.matrix * copy.linear;
      copy.translation = turn.Point(copy.translation);
      entry.second = static_cast<int>(this->Result.copies.size());
      this->Result.copies.push_back(copy);
    }
    Piece turned = sector;
    for (size_t v = 0; v < turned.points.size(); ++v)
      if (!pole[v])
        turned.points[v] = turn.Point(turned.points[v]);
    for (int& c : turned.pointCopy)
      c = turnedCopy[c];
    for (int& c : turned.faceCopy)
      c = turnedCopy[c];
    piece.Append(turned);
    sectorOf.insert(sectorOf.end(), sector.points.size(), j);
  }
  SeamReport seam;
  seam.node = index;
  seam.depth = node.depth;
  if (this->Options.stitch)
    this->Stitch(node, piece, sectorOf, seam, RotationStitchShare(k));
  else
    this->CountTears(node, piece, seam);
  this->Result.seams.push_back(seam);
  if (this->Options.stitch && this->Options.removeProjectedPoints)
    this->Result.removedProjectedPoints += this->RemoveProjectedPoints(&node, piece, nullptr);
  // A cut sector holds more faces than its share of the region (the pieces of the faces its
  // half-planes cut), and so does each of its k copies: all of them are thinned towards the
  // region's face count, within the same error budgets as a fold's mirrored copy (each copy's
  // points carry the sector's budgets, charged for the turns; the seams, interior since the
  // stitch, with them).
  if (this->Options.matchDiscardedDensity)
  {
    const std::vector<char> everyCopy(this->Result.copies.size(), 1);
    this->Result.thinnedCopyPoints +=
      this->MatchDiscardedDensity(node, piece, nullptr, -1, &everyCopy);
  }
  this->Result.foldExcessFaces += std::max(0, FoldExcessFaces(node, piece));
}

void Unfolder::CountTears(const FoldingNode& node, Piece& piece, SeamReport& seam)
{
  std::vector<char> isTear(piece.points.size());
  for (int v = 0; v < piece.NumberOfPoints(); ++v)
    seam.tearVertices += isTear[v] = IsTear(piece.tear[v], node.depth);
  seam.unmatchedTearVertices = seam.tearVertices;
  this->CountGaps(piece, isTear, seam);
  Consume(piece, 2 * node.depth);
  this->Result.unmatchedTearVertices += seam.unmatchedTearVertices;
  this->Result.gapEdges += seam.gapEdges;
  this->Result.gapLength += seam.gapLength;
}

/// Drops the entries of a processed level and flag (code = 2 * level + flag).
void Unfolder::Consume(Piece& piece, int code)
{
  for (TearList& t : piece.tear)
    t.erase(
      std::remove_if(
        t.begin(), t.end(), [&](const std::pair<int, uint64_t>& e) { return e.first == code; }),
      t.end());
}

/// Boundary edges whose two vertices are tear vertices.
void Unfolder::CountGaps(const Piece& piece, const std::vector<char>& isTear, SeamReport& seam)
{
  for (const Edge& e : OpenEdges(piece.triangles))
    if (isTear[e.first] && isTear[e.second])
    {
      ++seam.gapEdges;
      seam.gapLength += (piece.points[e.first] - piece.points[e.second]).norm();
    }
}
} // namespace unfolder_detail

using unfolder_detail::Piece;
using unfolder_detail::Unfolder;

namespace
{
/// Open, non-manifold and misoriented edges of the result (an edge used twice in the same
/// direction is misoriented).
void CountEdgeDefects(UnfoldedMesh& result)
{
  for (const auto& e : EdgeFaces(result.triangles))
  {
    int forward = 0;
    for (size_t i = 0; i < e.second.size(); ++i)
    {
      if (i > 0 && e.second[i] == e.second[i - 1])
        continue; // a degenerate face on the edge twice: count its traversals once
      const Triangle& t = result.triangles[e.second[i]];
      for (int k = 0; k < 3; ++k)
        forward += t[k] == e.first.first && t[(k + 1) % 3] == e.first.second;
    }
    const int uses = static_cast<int>(e.second.size());
    result.openEdges += uses == 1;
    result.nonManifoldEdges += uses > 2;
    result.misorientedEdges += uses == 2 && forward != 1;
  }
}

/// The finished piece as the result: geometry, ids, copies, the edge and fill counts.
void StoreResult(Piece& piece, UnfoldedMesh& result)
{
  result.projectedPoints = static_cast<int>(piece.projected.size()) -
    static_cast<int>(std::count(piece.projected.begin(), piece.projected.end(), char(0)));
  result.points = std::move(piece.points);
  result.triangles = std::move(piece.triangles);
  result.pointOriginalIds = std::move(piece.pointOrig);
  result.pointCopy = std::move(piece.pointCopy);
  result.faceOriginalIds = std::move(piece.faceOrig);
  result.faceCopy = std::move(piece.faceCopy);
  result.faceFilled = std::move(piece.faceFilled);
  result.pointMirrored.resize(result.points.size());
  for (size_t v = 0; v < result.points.size(); ++v)
    result.pointMirrored[v] = result.copies[result.pointCopy[v]].mirrored;
  CountEdgeDefects(result);
  for (const SeamReport& seam : result.seams)
    result.budgetRejectedClusters += seam.budgetRejectedClusters;
  result.budgetRejectedClusters += result.weld.budgetRejectedClusters;
  result.filledFaces =
    static_cast<int>(std::count(result.faceFilled.begin(), result.faceFilled.end(), char(1)));
  result.faceLeaf.resize(result.triangles.size());
  result.faceMirrored.resize(result.triangles.size());
  for (size_t f = 0; f < result.triangles.size(); ++f)
  {
    result.faceLeaf[f] = result.copies[result.faceCopy[f]].leaf;
    result.faceMirrored[f] = result.copies[result.faceCopy[f]].mirrored;
  }
}
}

/**
 * The unfolder's stages, in order - the one place that says which runs when, and why there.
 *
 * 1. The traversal (Unfolder::Unfold, postorder; the paper's section 4.3). A leaf gives its
 *    mesh. A folding node reflects its child's result (Reflect): the copy is mirrored and
 *    reversed, the fold line merged with its image, then the points the builder projected onto
 *    this plane are removed again (RemoveProjectedPoints) and the mirrored copy is thinned
 *    towards the node's face count (MatchDiscardedDensity) - at the fold, because only there
 *    are the plane and the copy known. A segmentation node stitches its children's seams
 *    (Stitch -> StitchVertices: proposals, clusters, placement within the error budgets,
 *    merge, zipper, gap filling, constrained Laplacian smoothing), then removes the projected
 *    points whose rings the seams closed. A rotation node (issue 22) turns its child's result
 *    k - 1 times by 360/k degrees about its axis (Turn; orientation kept), stitches the seams
 *    between neighbouring sectors the same way (the sectors play the children) and thins the
 *    k copies towards the region's face count, as a fold's mirrored copy.
 * 2. The weld (WeldBoundaries): open edges between copies of different subtrees meet only at
 *    the root, so the last stitch runs over the whole mesh, within the budgets left.
 * 3. The repair (Repair: degenerate and non-manifold faces dropped, orientation made
 *    consistent, holes filled within the tolerance): after the weld, so that it only sees
 *    what no stitch could close. Its new points are flagged (UnfoldedMesh::pointAdded).
 * 4. Projected points once more: those whose rings were still open at their fold (cracks
 *    closed by the weld or the repair since, tear or fold-line flags of levels above).
 * 5. The root's copy thinned once more towards the root's face count, which the seams and
 *    the repair's fills raise (never below the input's point count).
 * 6. The result: geometry, ids, copies and the edge counts (StoreResult).
 */
bool UnfoldFoldingTree(const FoldingTree& tree,
  const UnfoldOptions& options,
  UnfoldedMesh& result,
  std::string& error)
{
  result = UnfoldedMesh();
  error = tree.Validate();
  if (!error.empty())
  {
    error = "invalid folding tree: " + error;
    return false;
  }
  Unfolder unfolder(tree, options, result);
  Piece piece = unfolder.Unfold(0);                                  // 1
  if (!unfolder.Aborted && options.stitch && options.weldBoundaries) // 2
  {
    result.weld.node = -1;
    unfolder.WeldBoundaries(piece, result.weld);
  }
  const int pointsBeforeRepair = piece.NumberOfPoints();
  if (!unfolder.Aborted && options.stitch && options.closeHoles) // 3
    unfolder.Repair(piece, result.repair);
  result.pointAdded.assign(piece.points.size(), 0);
  for (int v = pointsBeforeRepair; v < piece.NumberOfPoints(); ++v)
    result.pointAdded[v] = 1;
  if (!unfolder.Aborted && options.removeProjectedPoints) // 4
    result.removedProjectedPoints +=
      unfolder.RemoveProjectedPoints(nullptr, piece, &result.pointAdded);
  if (!unfolder.Aborted && options.matchDiscardedDensity && // 5
    tree.nodes[0].kind == FoldingNodeKind::Folding && tree.numberOfOriginalPoints > 0)
    result.thinnedCopyPoints += unfolder.MatchDiscardedDensity(
      tree.nodes[0], piece, &result.pointAdded, tree.numberOfOriginalPoints);
  result.aborted = unfolder.Aborted;
  StoreResult(piece, result); // 6
  return true;
}
}
