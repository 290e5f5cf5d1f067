// Unfolder: thinning of the mirrored copy made at a folding node, so that the node's result
// has about the face count of its region S: an approximate fold whose two halves were
// tessellated differently keeps the half with more faces (the paper's rule), and its mirror
// image would double that half's density. A rotation node's k copies of its sector likewise (a
// sector cut along its half-planes holds more faces than its share of the region). See
// UnfoldOptions::matchDiscardedDensity.
#include "FoldingTreeUnfolderInternal.h"
#include "FoldingTreeUnfolderVertexRemoval.h"
#include "Trace.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <tuple>
#include <utility>

namespace foldingmeshes
{
namespace unfolder_detail
{
namespace
{
/// New faces may be no sharper than this (radians), unless the old star was sharper.
const double ThinningMinimumAngle = 20.0 * M_PI / 180.0;
/// Ears are chosen by their departure from the old star and their shape (RingRules).
const double ThinningShapeWeight = 0.2;

/// The area of the faces of v that are still there.
double StarArea(const Piece& piece, const VertexRemover& remover, int v)
{
  double area = 0.0;
  for (int f : remover.FacesOf(v))
    if (remover.Alive(f))
    {
      const Triangle& t = piece.triangles[f];
      const std::vector<Vec3>& x = piece.points;
      area += 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
    }
  return area;
}

/**
 * What the thinning at a folding node may touch: the points of the copy mirrored there that
 * no later step needs as they are. Every other point is fixed (the kept half, the fold
 * line), and no new edge joins two fixed points, so the fold line keeps its edges. At a
 * rotation node (`thinnedCopies`): the points of all k copies of its sector, none fixed (its
 * seams are interior once stitched).
 */
struct ThinningScope
{
  std::vector<char> mirrored; ///< per copy: mirrored at this node (or thinned: thinnedCopies)
  std::vector<char> fixed;    ///< per point: not the copy's
  std::vector<char> open;     ///< per point: on an open edge
  std::vector<const Plane*> planesAbove;
  double tolerance = 0.0;

  ThinningScope(const FoldingTree& tree,
    const FoldingNode& node,
    const std::vector<UnfoldCopy>& copies,
    const Piece& piece,
    double planeTolerance,
    const std::vector<char>* thinnedCopies)
    : tolerance(planeTolerance * tree.diagonal)
  {
    const uint64_t bit = uint64_t(1) << node.depth;
    for (size_t c = 0; c < copies.size(); ++c)
      this->mirrored.push_back(thinnedCopies ? c < thinnedCopies->size() && (*thinnedCopies)[c] != 0
                                             : (copies[c].mirrorMask & bit) != 0);
    const int n = piece.NumberOfPoints();
    this->fixed.assign(n, 1);
    for (int v = 0; v < n; ++v)
      this->fixed[v] = !this->mirrored[piece.pointCopy[v]];
    this->open = BorderPoints(piece.triangles, piece.points.size());
    for (int a = node.parent; a >= 0; a = tree.nodes[a].parent)
      if (tree.nodes[a].kind == FoldingNodeKind::Folding)
        this->planesAbove.push_back(&tree.nodes[a].plane);
  }

  bool MirroredHere(int copy) const { return this->mirrored[copy] != 0; }

  /// A point no later step needs as it is: not on an open edge (a seam stitched later, the
  /// input's border), no pending tear or fold-line flag (MirroredFlag), not flagged as on the
  /// input's border, not on a plane of a fold above.
  bool IsFree(const Piece& piece, int v) const
  {
    if (this->open[v] || !piece.tear[v].empty() || piece.border[v] == 1)
      return false;
    for (const Plane* p : this->planesAbove)
      if (std::abs(p->SignedDistance(piece.points[v])) <= this->tolerance)
        return false;
    return true;
  }
};

/// Points used by a face.
int UsedPoints(const Piece& piece)
{
  std::vector<char> used(piece.points.size(), 0);
  for (const Triangle& t : piece.triangles)
    for (int v : t)
      used[v] = 1;
  return static_cast<int>(std::count(used.begin(), used.end(), char(1)));
}

/// Drops the removed points; the points whose budget was `unknown` get none again, and
/// `added` (optional) is compacted with the points. Returns the points removed.
int CompactThinned(VertexRemover& remover,
  Piece& piece,
  const std::vector<char>& unknown,
  std::vector<char>* added)
{
  const size_t n = unknown.size();
  // Bit 0: the budget was unknown; bit 1: the point is flagged in `added`.
  std::vector<char> flags(n, 0);
  for (size_t v = 0; v < n; ++v)
    flags[v] = static_cast<char>(unknown[v] | (added && (*added)[v] ? 2 : 0));
  const int removed = remover.Compact(&flags);
  if (added)
    added->resize(flags.size());
  for (size_t v = 0; v < flags.size(); ++v)
  {
    if (flags[v] & 1)
      piece.budget[v] = std::numeric_limits<double>::infinity();
    if (added)
      (*added)[v] = (flags[v] & 2) ? 1 : 0;
  }
  return removed;
}
} // namespace

int Unfolder::FoldExcessFaces(const FoldingNode& node, const Piece& piece)
{
  // Projected points not tried yet (kept for the stitching above, on a plane of a fold
  // above, or copies of such points) go later, at a fold above or in the final pass of
  // RemoveProjectedPoints, each with two faces; those a fold could not remove stay.
  const int pending =
    static_cast<int>(std::count(piece.projected.begin(), piece.projected.end(), char(1)));
  return piece.NumberOfFaces() - 2 * pending - node.numberOfFaces;
}

// (Over 100 lines because the lazy priority queue shares its state - the removal tried,
// the versions, the budgets granted - with the cost that orders it; the scope, the point
// count and the compaction are named helpers.)
int Unfolder::MatchDiscardedDensity(const FoldingNode& node,
  Piece& piece,
  std::vector<char>* added,
  int pointFloor,
  const std::vector<char>* thinnedCopies)
{
  // The pass after the final repair (pointFloor >= 0): no projected point is removed later,
  // so those left count as pending only where they are kept on purpose (removeProjectedPoints
  // off: not made up for by thinning the copy).
  const bool finalPass = pointFloor >= 0;
  int excess = finalPass && this->Options.removeProjectedPoints
    ? piece.NumberOfFaces() - node.numberOfFaces
    : FoldExcessFaces(node, piece);
  // Diagnostics: one line per call, finished where the thinning stops.
  const TraceSink& trace = this->Options.trace;
  std::string line;
  if (trace)
    line = FormatTrace("[density] %s at depth %d: %s %d faces (%d %s discarded), result %d "
                       "faces, %d above it (pending projected points apart)",
      node.kind == FoldingNodeKind::Rotation ? "rotation" : "fold",
      node.depth,
      node.kind == FoldingNodeKind::Rotation ? "region" : "S",
      node.numberOfFaces,
      node.discardedFaces,
      node.kind == FoldingNodeKind::Rotation ? "pieces" : "faces",
      piece.NumberOfFaces(),
      excess);
  if (excess < 2)
  {
    if (trace)
      trace(line);
    return 0;
  }
  const int n = piece.NumberOfPoints();
  const ThinningScope scope(
    this->Tree, node, this->Result.copies, piece, this->Options.planeTolerance, thinnedCopies);
  const std::vector<char>& fixed = scope.fixed;
  const double tolerance = scope.tolerance;
  auto mirroredHere = [&](int copy) { return scope.MirroredHere(copy); };
  auto isFree = [&](int v) { return scope.IsFree(piece, v); };
  // Points the final repair added (fan centres) are not the copy's.
  std::vector<char> candidate(n, 0);
  for (int v = 0; v < n; ++v)
    candidate[v] = !fixed[v] && !piece.projected[v] && isFree(v) && !(added && (*added)[v]);

  VertexRemover remover(piece, tolerance);
  RingRules rules;
  rules.minimumAngle = ThinningMinimumAngle;
  rules.shapeWeight = ThinningShapeWeight;
  rules.noNewEdgeBetween = &fixed;
  RingRemoval removal;
  const char* why = "";
  // A removal of v (into `removal`): its star all of the copy, its ring of free points, the
  // surface moved within the error limit.
  // A point that comes back to the top of the queue unchanged - its star (starVersion) and the
  // budgets of its star's points (their epochs) as when it was measured - gets the removal
  // measured then (Try depends on nothing else; points never move here). `version` stamps
  // the queue entries (an entry of an older stamp is stale); a point measured and put back
  // with its cost gets a new stamp but keeps its measurement.
  std::vector<int> version(n, 0), starVersion(n, 0), budgetEpoch(n, 0);
  struct Measured
  {
    int starVersion = -1;
    std::vector<int> epochs; ///< of v and its ring, in that order
    RingRemoval removal;
  };
  std::vector<Measured> measured(n);
  auto unchanged = [&](int v)
  {
    const Measured& m = measured[v];
    if (m.starVersion != starVersion[v] || m.epochs.empty() || m.epochs[0] != budgetEpoch[v])
      return false;
    for (size_t i = 0; i < m.removal.ring.size(); ++i)
      if (m.epochs[i + 1] != budgetEpoch[m.removal.ring[i]])
        return false;
    return true;
  };
  auto attempt = [&](int v) -> bool
  {
    if (unchanged(v))
    {
      removal = measured[v].removal;
      return true;
    }
    for (int f : remover.FacesOf(v))
      if (remover.Alive(f) && !mirroredHere(piece.faceCopy[f]))
        return false;
    if (!remover.Try(v, remover.Limit(v, node.epsilon), rules, removal, why))
      return false;
    for (int a : removal.ring)
      if (!isFree(a))
        return false;
    Measured& m = measured[v];
    m.starVersion = starVersion[v];
    m.epochs.assign(1, budgetEpoch[v]);
    for (int a : removal.ring)
      m.epochs.push_back(budgetEpoch[a]);
    m.removal = removal;
    return true;
  };
  // The order: the densest spot first (the star's area relative to the copy's mean star
  // area), then the least departure relative to the limit; index order on ties.
  double meanArea = 0.0;
  int counted = 0;
  for (int v = 0; v < n; ++v)
    if (candidate[v])
    {
      meanArea += StarArea(piece, remover, v);
      ++counted;
    }
  if (counted == 0 || meanArea <= 0.0)
  {
    if (trace)
      trace(line + ": no candidate");
    return 0;
  }
  meanArea /= counted;
  auto cost = [&](int v)
  {
    return StarArea(piece, remover, v) / meanArea +
      (removal.limit > 0.0 ? removal.moved / removal.limit : 0.0);
  };
  // Without budgets (respectErrorBudget off, older trees) the node's epsilon is the budget of
  // every point for this thinning, so that removals next to each other cannot add up beyond
  // it; the points keep no budget afterwards. The final pass grants nothing there (the fold's
  // thinning in the traversal had the epsilon already): only planar stars qualify.
  std::vector<char> unknown(n, 0);
  for (int v = 0; v < n; ++v)
    if (!std::isfinite(piece.budget[v]))
    {
      unknown[v] = 1;
      piece.budget[v] = finalPass ? 0.0 : node.epsilon;
    }
  // (cost, point, version): entries of points whose star changed since are stale. A point
  // enters with its area term alone, a lower bound of its cost: it is measured when it comes
  // first, and goes back with its cost unless that is still the lowest.
  using Entry = std::tuple<double, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int v = 0; v < n; ++v)
    if (candidate[v])
      queue.push({ StarArea(piece, remover, v) / meanArea, v, 0 });
  int usedPoints = UsedPoints(piece);
  std::vector<int> ring;
  while (!queue.empty() && excess >= 2 && usedPoints > pointFloor)
  {
    const Entry top = queue.top();
    queue.pop();
    const int v = std::get<1>(top);
    if (remover.Removed(v) || std::get<2>(top) != version[v] || !attempt(v))
      continue;
    // Measured (again: the budgets of its ring may have been charged since).
    const double now = cost(v);
    if (now > std::get<0>(top))
    {
      queue.push({ now, v, ++version[v] });
      continue;
    }
    remover.Apply(removal);
    excess -= 2;
    --usedPoints;
    ring = removal.ring;
    for (int a : ring)
    {
      ++budgetEpoch[a]; // Apply charged their budgets
      ++starVersion[a]; // and replaced faces of their stars
    }
    for (int a : ring)
      if (candidate[a])
        queue.push({ StarArea(piece, remover, a) / meanArea, a, ++version[a] });
  }
  if (trace)
    trace(
      line + FormatTrace(": removed %d points, %d faces above S left", remover.Count(), excess));
  return CompactThinned(remover, piece, unknown, added);
}
} // namespace unfolder_detail
} // namespace foldingmeshes
