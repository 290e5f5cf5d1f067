// Internal to FoldingTreeUnfolder*.cxx (no public API): Piece, tear lists, the Unfolder class.
#ifndef foldingmeshes_FoldingTreeUnfolderInternal_h
#define foldingmeshes_FoldingTreeUnfolderInternal_h

#include "FlatEdgeHash.h"
#include "FoldingTreeUnfolder.h"
#include "MeshPreparation.h"
#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace foldingmeshes
{
namespace unfolder_detail
{
/// Pending flags of a vertex copy (MirroredFlag): (2 * level + flag, reflections still
/// required), flag 0 tear, 1 plane. An entry with no reflection left applies to the copy.
using TearList = std::vector<std::pair<int, uint64_t>>;

inline void Normalize(TearList& t)
{
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
}

inline bool IsTear(const TearList& t, int level)
{
  for (const auto& e : t)
    if (e.first == 2 * level && e.second == 0)
      return true;
  return false;
}

inline bool IsOnPlane(const TearList& t, int level)
{
  for (const auto& e : t)
    if (e.first == 2 * level + 1 && e.second == 0)
      return true;
  return false;
}

/// A partial result of the postorder traversal.
struct Piece
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::vector<int> pointOrig;
  std::vector<int> pointCopy;
  std::vector<TearList> tear;
  std::vector<uint64_t> onPlane;
  std::vector<double> budget; ///< how far the point may still move (infinite: unknown)
  /// Copy of a point on the input's own border: 0 no, 1 yes, 2 unknown (older tree files).
  std::vector<char> border;
  /// 1: a copy of a leaf point the builder projected onto a fold plane (FoldingLeafMesh::
  /// projected); such points may be removed again (FoldingTreeUnfolderProjectedPoints.cxx).
  /// 2: such a point its fold tried to remove and could not (retried after the traversal).
  std::vector<char> projected;
  std::vector<int> faceOrig;
  std::vector<int> faceCopy;
  std::vector<char> faceFilled;

  int NumberOfPoints() const { return static_cast<int>(points.size()); }
  int NumberOfFaces() const { return static_cast<int>(triangles.size()); }

  /// Appends point v of `from` with everything it carries.
  void AppendPoint(const Piece& from, int v)
  {
    points.push_back(from.points[v]);
    pointOrig.push_back(from.pointOrig[v]);
    pointCopy.push_back(from.pointCopy[v]);
    tear.push_back(from.tear[v]);
    onPlane.push_back(from.onPlane[v]);
    budget.push_back(from.budget[v]);
    border.push_back(from.border[v]);
    projected.push_back(from.projected[v]);
  }

  void Append(const Piece& o)
  {
    const int offset = NumberOfPoints();
    points.insert(points.end(), o.points.begin(), o.points.end());
    pointOrig.insert(pointOrig.end(), o.pointOrig.begin(), o.pointOrig.end());
    pointCopy.insert(pointCopy.end(), o.pointCopy.begin(), o.pointCopy.end());
    tear.insert(tear.end(), o.tear.begin(), o.tear.end());
    onPlane.insert(onPlane.end(), o.onPlane.begin(), o.onPlane.end());
    budget.insert(budget.end(), o.budget.begin(), o.budget.end());
    border.insert(border.end(), o.border.begin(), o.border.end());
    projected.insert(projected.end(), o.projected.begin(), o.projected.end());
    for (const Triangle& t : o.triangles)
      triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    faceOrig.insert(faceOrig.end(), o.faceOrig.begin(), o.faceOrig.end());
    faceCopy.insert(faceCopy.end(), o.faceCopy.begin(), o.faceCopy.end());
    faceFilled.insert(faceFilled.end(), o.faceFilled.begin(), o.faceFilled.end());
  }
};

/**
 * Ear clipping of the polygon `poly` (indices into `points`) by the lowest cost: cuts off,
 * again and again, the ear (a, b, c) with the lowest cost(a, b, c) among those whose diagonal
 * a-c allowed(a, c) accepts (the first in polygon order on a tie), calling cut(a, b, c)
 * (which records the triangle and makes a-c unavailable), until a triangle is left in poly
 * (true) or no ear is allowed (false; poly keeps what is left). cost must depend on its three
 * points only: it is measured once per ear.
 */
template <typename Allowed, typename Cost, typename Cut>
bool ClipCheapestEars(std::vector<int>& poly, Allowed allowed, Cost cost, Cut cut)
{
  // The cost of the ear starting at each position of poly, once measured (a cut changes the
  // two ears through the new diagonal; the others keep their three points).
  std::vector<double> earCost(poly.size(), 0.0);
  std::vector<char> measured(poly.size(), 0);
  while (poly.size() > 3)
  {
    const int m = static_cast<int>(poly.size());
    int best = -1;
    double bestCost = std::numeric_limits<double>::infinity();
    for (int i = 0; i < m; ++i)
    {
      const int a = poly[i], b = poly[(i + 1) % m], c = poly[(i + 2) % m];
      if (!allowed(a, c))
        continue;
      if (!measured[i])
      {
        earCost[i] = cost(a, b, c);
        measured[i] = 1;
      }
      const double value = earCost[i];
      if (value < bestCost)
      {
        bestCost = value;
        best = i;
      }
    }
    if (best < 0)
      return false;
    cut(poly[best], poly[(best + 1) % m], poly[(best + 2) % m]);
    const int cutAt = (best + 1) % m;
    poly.erase(poly.begin() + cutAt);
    earCost.erase(earCost.begin() + cutAt);
    measured.erase(measured.begin() + cutAt);
    const int n = m - 1;
    const int first = cutAt == 0 ? n - 1 : cutAt - 1; // where poly[best] is now
    measured[first] = 0;
    measured[(first + n - 1) % n] = 0;
  }
  return poly.size() == 3;
}

/// ClipCheapestEars with the length of the new diagonal as the cost.
template <typename Allowed, typename Cut>
bool ClipShortestEars(const std::vector<Vec3>& points,
  std::vector<int>& poly,
  Allowed allowed,
  Cut cut)
{
  return ClipCheapestEars(
    poly, allowed, [&](int a, int, int c) { return (points[a] - points[c]).norm(); }, cut);
}

/**
 * Whether the fill of a boundary loop (triangles over the loop's vertices, or a fan around a
 * new point) stays within `tolerance` of the surface (FoldingTreeUnfolderHoles.cxx): every
 * point of every new face provably within it of the loop's edges (a narrow crack), or
 * the loop small and flat (see there).
 */
bool FillWithinTolerance(const std::vector<Vec3>& points,
  const std::vector<int>& loop,
  const std::vector<Triangle>& fill,
  double tolerance);

// ---- the stages of a seam's stitch (FoldingTreeUnfolderStitching.cxx) ----

/// Two vertices proposed for merging, a < b, at `distance`; sameChild: of one child.
struct StitchProposal
{
  double distance;
  int a, b;
  bool sameChild;
};

/// Merged vertices: rep[v] is v's cluster root (v itself when not merged), count[r] the
/// members of root r, spread[r] the farthest any member moved, children[r] the sorted child
/// ids the cluster spans.
struct StitchClusters
{
  std::vector<int> rep;
  std::vector<int> count;
  std::vector<double> spread;
  std::unordered_map<int, std::vector<int>> children;
};

/// The piece after the merge, with per point what the zipper, the gap filling and the
/// smoothing need: the children a point belongs to, whether it was merged, whether it was a
/// stitch candidate, and how far smoothing may move it (rough; 0: fixed); per face its child.
struct SeamPiece
{
  Piece piece;
  std::vector<int> faceChild;
  std::vector<std::vector<int>> children;
  std::vector<char> matched, candidate;
  std::vector<double> rough;
};

/// Each candidate (`tears`) paired with its nearest candidate of another child within `tol`
/// (lowest distance, then id), and with every candidate of its own child within
/// `sameChildDistance`; sorted by (distance, a, b).
std::vector<StitchProposal> ProposeStitches(const std::vector<Vec3>& points,
  const std::vector<int>& tears,
  const std::vector<int>& childOf,
  double tol,
  double sameChildDistance);

/// Union-find over the proposals in order: two clusters merge unless they share a child
/// (proposals of one child excepted).
StitchClusters ClusterStitches(const std::vector<StitchProposal>& proposals,
  const std::vector<int>& childOf,
  int n);

/// Moves each cluster to its mean, else to one of its members (lowest id first), whichever
/// keeps every member within its error budget; a cluster with no such place is dissolved
/// (SeamReport::budgetRejectedClusters). Spends the budgets, merges the tear lists into the
/// roots and counts the stitched vertices.
void PlaceClusters(Piece& piece, StitchClusters& clusters, SeamReport& seam);

/// Removes the points of `merged` no face uses, with their per-point data.
void DropUnusedPoints(SeamPiece& merged);

/**
 * The paper's constrained Laplacian smoothing of the seam (section 4.3): `iterations` steps of
 * x <- (1 - lambda) x + lambda * mean of its neighbours for the vertices with rough > 0, each
 * kept within min(rough, budget) of where it started (rough: the distance its stitch moved
 * it), the others fixed, so sharp features along a seam are not eroded. Spends the budgets;
 * returns the number of vertices with rough > 0.
 */
int ConstrainedLaplacianSmoothing(Piece& out,
  std::vector<double> rough,
  int iterations,
  double lambda);

/// Per point, the faces using it in increasing order (once per use), each list allocated once.
inline std::vector<std::vector<int>> FacesOfPoints(const std::vector<Triangle>& triangles,
  size_t points)
{
  std::vector<int> uses(points, 0);
  for (const Triangle& t : triangles)
    for (int v : t)
      ++uses[v];
  std::vector<std::vector<int>> faces(points);
  for (size_t v = 0; v < points; ++v)
    faces[v].reserve(static_cast<size_t>(uses[v]));
  for (size_t f = 0; f < triangles.size(); ++f)
    for (int v : triangles[f])
      faces[v].push_back(static_cast<int>(f));
  return faces;
}

/// Hash of an edge (pair of point ids), for the hash tables keyed by edges with other values.
struct EdgeHash
{
  size_t operator()(const std::pair<int, int>& e) const
  {
    return std::hash<long long>()(
      (static_cast<long long>(e.first) << 32) ^ static_cast<unsigned int>(e.second));
  }
};
/// The repair's and stitcher's edge sets (flat: no allocation per edge).
using EdgeSet = FlatEdgeSet;

/// The postorder unfolding of a folding tree (see UnfoldFoldingTree). The traversal, the
/// copies and the fold lines are in FoldingTreeUnfolder.cxx (the removal of projected
/// points in FoldingTreeUnfolderProjectedPoints.cxx, the thinning of mirrored copies in
/// FoldingTreeUnfolderDensity.cxx, both with FoldingTreeUnfolderVertexRemoval.h); the seam
/// repair in FoldingTreeUnfolderStitching.cxx (vertex pairing, clusters, smoothing, final
/// weld) and FoldingTreeUnfolderSeamGaps.cxx (zipper, gap filling); the final repair in
/// FoldingTreeUnfolderRepair.cxx, FoldingTreeUnfolderBoundaryLoops.cxx and
/// FoldingTreeUnfolderHoles.cxx. The order of the stages: UnfoldFoldingTree.
struct LoopFill;
struct LoopShape;

class Unfolder
{
public:
  Unfolder(const FoldingTree& tree, const UnfoldOptions& options, UnfoldedMesh& result)
    : Tree(tree)
    , Options(options)
    , Result(result)
  {
  }

  bool Aborted = false;

  Piece Unfold(int index);

private:
  Piece FromLeaf(int index);
  void Reflect(const FoldingNode& node, Piece& piece);
  void Turn(int index, Piece& piece);
  void CountTears(const FoldingNode& node, Piece& piece, SeamReport& seam);
  static void Consume(Piece& piece, int code);

  // FoldingTreeUnfolderProjectedPoints.cxx
public:
  /// Removes the projected points of `piece` (UnfoldOptions::removeProjectedPoints) that can
  /// go: after the reflection at a folding `node`, those on its plane; after the stitching
  /// at a segmentation `node`, those on no fold plane (copies a fold below mirrored off the
  /// fold line they were projected onto, which no fold tries); with node == nullptr (after
  /// the traversal) any. `added` (optional, per point) is compacted with the points. Returns
  /// the number removed.
  int RemoveProjectedPoints(const FoldingNode* node, Piece& piece, std::vector<char>* added);

  // FoldingTreeUnfolderDensity.cxx
  /// Thins the copy mirrored at `node` (UnfoldOptions::matchDiscardedDensity) towards the face
  /// count of the node's region (the comment in FoldingTreeUnfolderDensity.cxx); returns the
  /// number of points removed. The final pass (after the repair; `pointFloor` >= 0)
  /// counts no projected point as pending (unless removeProjectedPoints is off), stops before the
  /// points used by faces drop below `pointFloor`, grants no budget where it is unknown and leaves
  /// the points flagged in `added` (kept in step with the points) alone. `thinnedCopies` (per
  /// copy, nonzero: thinned) replaces the copies mirrored at `node`: a rotation node's copies of
  /// its sector (Turn).
  int MatchDiscardedDensity(const FoldingNode& node,
    Piece& piece,
    std::vector<char>* added = nullptr,
    int pointFloor = -1,
    const std::vector<char>* thinnedCopies = nullptr);
  /// The faces of the result of `node` (after its reflection) above its region's count,
  /// less two per projected point still to be removed later (UnfoldedMesh::foldExcessFaces).
  static int FoldExcessFaces(const FoldingNode& node, const Piece& piece);

private:
  static void CountGaps(const Piece& piece, const std::vector<char>& isTear, SeamReport& seam);

  // FoldingTreeUnfolderSeamGaps.cxx
  static int Zip(Piece& out,
    std::vector<int>& faceChild,
    std::vector<std::vector<int>>& children,
    std::vector<char>& matched,
    const std::vector<char>& isTear,
    double tol,
    std::vector<double>& rough);
  void FillSeamGaps(Piece& out,
    std::vector<int>& faceChild,
    const std::vector<std::vector<int>>& children,
    const std::vector<char>& isTear,
    double tol,
    SeamReport& seam) const;

  // FoldingTreeUnfolderStitching.cxx
  void Stitch(const FoldingNode& node,
    Piece& piece,
    const std::vector<int>& childOf,
    SeamReport& seam,
    double toleranceShare = 1.0);

public:
  void WeldBoundaries(Piece& piece, SeamReport& seam);
  // FoldingTreeUnfolderRepair.cxx
  void Repair(Piece& piece, RepairReport& report);

private:
  void StitchVertices(Piece& piece,
    const std::vector<char>& candidate,
    const std::vector<int>& childOf,
    double tol,
    double epsilon,
    bool fill,
    SeamReport& seam,
    double sameChildDistance = 0.0);

  /// The piece with each stitch cluster one vertex: faces remapped, collapsed and duplicate
  /// faces dropped (but the input's own duplicates), unused points dropped; rough = the
  /// cluster's spread where it exceeds `roughAbove`.
  SeamPiece MergeClusters(const Piece& piece,
    const std::vector<char>& candidate,
    const std::vector<int>& childOf,
    const StitchClusters& clusters,
    double roughAbove,
    SeamReport& seam) const;
  int InputNonManifoldFaces(const Piece& piece, int a, int b) const;
  bool InputDuplicate(const Piece& piece,
    const Triangle& t,
    const std::pair<int, std::array<int, 3>>& face,
    const std::vector<std::pair<int, std::array<int, 3>>>& same) const;
  int DropNonManifoldFaces(Piece& piece) const;
  static int OrientComponents(Piece& piece, int& dropped);
  static std::vector<std::vector<int>> BoundaryLoops(const Piece& piece,
    bool undirectedRest,
    size_t& reportOnly);
  static bool TriangulateLoop(const Piece& piece,
    const std::vector<int>& loop,
    const EdgeSet& existing,
    std::vector<Triangle>& triangles);
  int FillLoops(Piece& piece, RepairReport& report, bool apply);
  // FillLoops' steps (FoldingTreeUnfolderHoles.cxx: LoopFill is one pass's state, LoopShape
  // what a loop's edges are).
  LoopShape MeasureLoop(const Piece& piece,
    const std::vector<int>& loop,
    const LoopFill& pass) const;
  int CloseBorderGaps(Piece& piece, const std::vector<int>& loop, LoopFill& pass) const;
  void CountBorderLoop(const Piece& piece,
    const std::vector<int>& loop,
    const LoopShape& shape,
    LoopFill& pass) const;
  int FillOpenLoop(Piece& piece,
    const std::vector<int>& loop,
    const LoopShape& shape,
    LoopFill& pass) const;
  bool FillWithinTolerance(const Piece& piece,
    const std::vector<int>& loop,
    const std::vector<Triangle>& fill) const;
  bool IsInputBorderEdge(const Piece& piece, int a, int b) const;
  static void AddPoint(Piece& piece, const Vec3& x, int like);
  static void RemoveLastPoint(Piece& piece);

  const FoldingTree& Tree;
  const UnfoldOptions& Options;
  UnfoldedMesh& Result;
  int Done = 0;
};
} // namespace unfolder_detail
} // namespace foldingmeshes

#endif
