// Folding tree construction (the paper's section 4.2), in preorder, on plain triangle meshes.
//
// Choices beyond the paper (all documented on the options below):
// - "no meaningful symmetry" is a stop criterion of its own (the paper's three criteria
//   never stop on an asymmetric region), and re-detecting an ancestor's fold plane is not
//   meaningful;
// - S is trimmed to its mirror-consistent part and the plane polished on S before folding,
//   so that S' U reflect(S') reproduces S (the unfolding error stays within epsilon and the
//   seam with the remaining faces matches);
// - vertices within a small snap distance of the plane count as on it (fold lines close);
// - the tear stack is exact through nested folds (MirroredFlag), not just inherited;
// - a hard depth bound (64 levels: the per-vertex flags are uint64 bit sets);
// - regions above sampledSearchAboveFaces search their candidate planes on a sampled copy
//   (speed; the paper runs its single start on the full region);
// - the default stop criteria: the paper's default is the area alone (section 5); here the
//   face count (50) and the number of folds (8) are on too. The fold count never triggers on
//   the shared meshes (folds halve the area, and the 5% area stop comes first); the face
//   count keeps small regions whole: with the area alone dino stores 2906 faces instead of
//   3339 (62.9% vs 57.3%), bearing, cow, queen and triceratops 0.2-0.7 points more, the other
//   24 shared meshes the same, at more points in the unfolded mesh (dino +2.0% vs +1.2%,
//   queen +5.3% vs +4.3%; 2026-12-02). Switch UseMinimumFaces off for the paper's setting;
//   a vertex on an ancestor's fold plane goes to the planes' intersection only within
//   epsilon of its orthogonal projection (see slideOntoPlane).
#ifndef foldingmeshes_FoldingTreeBuilder_h
#define foldingmeshes_FoldingTreeBuilder_h

#include "ClosestFaceQuery.h"
#include "FoldingTree.h"
#include "RotationalSymmetry.h"
#include "SymmetryDetection.h"
#include "Trace.h"

#include <functional>
#include <string>
#include <vector>

namespace foldingmeshes
{
/// Which half of a symmetric region a fold keeps.
enum class KeepSide
{
  MoreFaces, ///< the paper's choice: preserves detail
  FewerFaces ///< the paper's alternative: minimises storage
};

/// Rebuilds with pinned faces before the verification pins every face (verifyBound).
constexpr int MaximumVerificationRounds = 4;
/// A first proof that misses epsilon by at most this factor (a near miss: the tree is about
/// right, its budgets a little too loose) rebuilds the tree at a smaller epsilon instead of
/// pinning faces: epsilon * epsilon / bound * NearMissEpsilonMargin, no pins. Should that tree
/// miss its smaller epsilon too, the rounds go on at epsilon with the first tree's pins (the
/// near miss does not count among the MaximumVerificationRounds).
constexpr double NearMissBoundRatio = 1.25;
constexpr double NearMissEpsilonMargin = 0.97;
/// Builds FoldingTreeOptions::verifyBound adds at most to close the holes a closed input came
/// back with (faces pinned where they are; the bound's rounds come on top) ...
constexpr int MaximumClosingRounds = 2;
/// ... each kept only when it stores at most this share of the input's faces more than the
/// tree with the holes, or MaximumClosingFaces more (a small mesh comes back closed even if
/// that means storing it whole: a 192-face box with a bump, 64 open edges). A procedural
/// chess piece with unevenly spaced rings came back with 208 open edges, and the tree closing
/// them stored all 1188 faces instead of 200: it keeps its holes (docs/builder.md).
constexpr double MaximumClosingShare = 0.1;
constexpr int MaximumClosingFaces = 250;
/// A first tree with rotation nodes whose unfolded area is above this many times the input's
/// (surface laid twice within epsilon: a bearing moved, with the face and area stops off,
/// 1.36) is rebuilt with the planes alone; where the first tree was closed (as the input),
/// the planes' tree is kept only where it is within epsilon, closed, lays less surface twice
/// and stores at most the closing rounds' allowance more (docs/builder.md, step 8 of
/// "Rotation nodes").
constexpr double RotationAreaRatioLimit = 1.1;

/// FoldingTreeOptions::rotationNodesWhenAxial: the largest gap between two eigenvalues of the
/// surface's second moments, as a share of the larger, that still counts as axially symmetric.
constexpr double AxialMomentsGap = 0.02;

struct FoldingTreeOptions
{
  /// Root tolerance as an absolute length (required, > 0). The paper's default is 2% of the
  /// bounding-box diagonal; the caller computes it. Halved below every folding node.
  double epsilon = 0.0;
  /// Detection settings for every node. `epsilon` and `progress` are overwritten per node,
  /// `sampledSearchAboveFaces` by the option below; `refineSampledFinalists` and
  /// `distancesUpTo3Sigma` are off (the builder polishes the plane on S itself and uses the
  /// region, not the distances).
  SymmetryOptions symmetry;
  /**
   * Regions with more faces than this search their candidate planes on a sampled copy
   * (DetectSymmetry) and only score the copy's finalists on the full region, without the
   * fine and polish iterations there: the trim and the polish of the plane on S below refine
   * it anyway (vtkFoldingTreeBuilder::SampledSearchAboveFaces). Half the build time
   * of the shared meshes at the same mean compression (docs/benchmarks.md); 0: every node, a very
   * large value: none.
   */
  int sampledSearchAboveFaces = 1000;

  // ---- stop criteria: a region becomes a leaf when any enabled one holds ----
  bool useMinimumFaces = true;
  int minimumFaces = 50; ///< leaf when the region has fewer faces
  bool useMinimumAreaFraction = true;
  double minimumAreaFraction = 0.05; ///< leaf when area < this * original area (paper default)
  bool useMaximumFolds = true;
  int maximumFolds = 8; ///< leaf when this many folds are already above the region
  /**
   * Leaf when there is no meaningful symmetric region: S (after trimming, below) covers less
   * than symmetry.minimumSymmetricAreaFraction of the region's area or has fewer than
   * minimumFaces faces, or its plane is a fold plane already used on the path from the root
   * (a half re-detecting its own fold plane only finds a strip along the cut). Switched off,
   * any non-empty S is folded. Either way a fold that would remove no face (every face of S
   * straddles the plane, e.g. a single triangle) is not made: S stays a leaf (NoSymmetry) -
   * it would store as much as before, and repeated without stop criteria never end.
   */
  bool requireMeaningfulSymmetry = true;
  /**
   * Also require DetectSymmetry's residual rule (`found`: area-weighted RMS of d over S
   * <= FoundResidualRatio * epsilon), so that only clear symmetries are folded. Off (default,
   * as in the paper): every region whose vertices all mirror within epsilon is folded when it
   * passes the rule above - a loose but epsilon-symmetric region still folds within the error
   * bound, and compresses (triceratops 48% -> 56%, horse 48% -> 66%). Only with
   * requireMeaningfulSymmetry.
   */
  bool requireTightSymmetry = false;
  /// Hard bound on the tree depth (clamped to MaximumFoldingTreeLevels - 1); bounds recursion.
  int maximumDepth = 48;

  KeepSide keepSide = KeepSide::MoreFaces;
  /// Link parts closer than the node epsilon (LinkNearbyParts) for detection and for the
  /// connected components of the remaining faces, as vtkSymmetryPlaneDetector does.
  bool connectNearbyParts = true;
  /**
   * Trim S to its mirror-consistent part before folding: faces of S one of whose mirrored
   * vertices is not within epsilon of S itself (only of faces outside S, e.g. an attachment
   * next to its mirror position) move to the remaining faces (repeated until stable, then the
   * largest connected part is kept). Without it S' U reflect(S') may overlap the attachment
   * and leave holes where S was not symmetric.
   */
  bool trimToMirrorConsistent = true;
  /**
   * Polish the detected plane on the (trimmed) S alone, every vertex weighted by its area
   * (Gauss-Newton point-to-tangent-plane fit against S itself; kept only if the residual
   * drops), then trim again. Detection's robust weights, lowered near the remaining faces,
   * can leave the plane a fraction of a degree off, which the unfolding error inherits.
   */
  bool polishPlane = true;
  /**
   * Keep unfold(tree) within epsilon of the input (the paper's bound). Halving epsilon
   * below folds alone does not: the copies made by k nested folds can each be off by the
   * fold's tolerance, epsilon (1 + 1/2 + ...) < 2 epsilon in all. With errorBudget on, every
   * point carries a budget, epsilon at the root. A fold charges each kept point what its
   * copies add there - the distance of its mirror image to the input; for a discarded point,
   * the distance of its mirror image to the region, charged to the kept point nearest to
   * that image - plus how far projecting it onto the plane moved it off the region (the
   * moved faces' centroids included), and limits it by the budget of the point its mirror
   * image lands on; the kept point keeps the rest. Trimming (trimToMirrorConsistent) keeps a
   * face of S only if every vertex's mirror distance is below min(epsilon, those budgets),
   * so exact symmetries cost nothing and approximate ones stop where the budget is used up.
   * The budgets left are stored in the leaves (FoldingLeafMesh::errorBudget) and bound the
   * unfolder's vertex moves. Budgets are per point; for the faces between them, trimming
   * also proves the mirror image of every face the fold keeps within the least limit of its
   * vertices at every point (MirroredFacesWithin), so a copy cannot pass over a dip or a
   * crease of the input between its corners.
   */
  bool errorBudget = true;
  /**
   * Make unfold(tree) <= epsilon a proved fact, not a hope: after building, unfold the tree
   * (default UnfoldOptions) and bound the Hausdorff distance to the input over every point of
   * both surfaces (FoldingTreeVerification.h). The budgets above keep the folds' own errors
   * within epsilon, but the unfolder's seam fills and repairs between parts, where the
   * input bends between sample points, can still leave it (an artist-like figure: 0.0216 of
   * the diagonal at epsilon 0.02). Where a point is not proved within epsilon, the input
   * faces there (and two rings around them) are pinned - kept out of every symmetric region,
   * stored as they are - and the tree is built again; after MaximumVerificationRounds such
   * rounds every face is pinned (a single leaf: the input itself, distance 0). The result:
   * FoldingTree::verifiedBound, pinnedFaces, verificationRounds. Costs one unfold and one
   * proof per round (docs/benchmarks.md); the progress callback sees the first build only.
   * A first tree with rotation nodes that misses is rebuilt with the planes alone first.
   */
  bool verifyBound = true;
  /// The plain closest-face queries of the builder (e.g. a VTK cell locator the user set on
  /// the filter): verifyBound's distances and the mirrored-face proof of every fold
  /// (MirroredFacesWithin, over the fold's region S); empty: the core's FaceTree. The same
  /// distances either way (exact point-to-triangle distances; TestCellLocatorDistances), so
  /// the same trees but where triangles tie for the closest.
  ClosestFaceQueryFactory verificationQueries;
  /**
   * How a vertex of a kept face lying on the discarded side reaches the fold plane. By
   * default it is projected orthogonally (the paper's choice), which can move it off the
   * surface by up to an edge length times the sine of the angle between surface and plane;
   * with errorBudget on, a vertex whose projection would exceed the error budget left there
   * slides instead: along one of its edges to a kept-side vertex, to where that edge crosses
   * the plane (the crossing nearest to its orthogonal projection), so it stays on the input
   * surface. slideOntoPlane on slides every such vertex. Vertices already on an ancestor's
   * fold plane are projected onto the intersection of the planes (the ancestor's fold line
   * stays closed) when that point is within epsilon of the orthogonal projection; farther
   * (the ancestor's plane only touches a corner of the vertex's faces), orthogonally, and
   * the vertex leaves the ancestor's plane.
   */
  bool slideOntoPlane = false;
  /**
   * Vertices within planeSnapFraction * epsilon of a fold plane count as lying on it: they
   * are snapped onto it (and flagged in planeMask) so the unfolder closes the fold line.
   */
  double planeSnapFraction = 0.01;
  /**
   * Rotation nodes (issue 22): at a node with no fold and no rotation above it, find the
   * region's rotational symmetry (DetectRotationalSymmetry, orders 2 .. maximumRotationOrder)
   * and, when turning one sector of 360/k degrees k times reproduces the region (or the part
   * of it the turns map onto itself) within epsilon and the error budgets, keep that sector only
   * (FoldingNodeKind::Rotation; its subtree is built with epsilon / 2 and may fold again: a
   * dihedral part becomes rotation + fold). Where a fold passes too, both subtrees are built and
   * the one storing fewer faces kept (ties: the fold); so is a sector of the next smaller order
   * that passes (ties: the larger order). The rule for the order, the sector cut
   * and the seams: FoldingTreeRotation.cxx. A tree with rotation nodes that verifyBound finds
   * beyond epsilon, or with holes where the input is closed, is rebuilt with the planes alone
   * (docs/builder.md); so is one whose unfolded area is above RotationAreaRatioLimit times the
   * input's, the planes' tree kept only where it lays less surface twice. Off by default
   * (docs/benchmarks.md: the 29 shared meshes' builds take 70% longer, 16.7 -> 28.5 s);
   * rotationNodesWhenAxial, on by default, turns them on where the input's moments allow a
   * rotational symmetry of the whole surface.
   */
  bool rotationNodes = false;
  /// With rotationNodes false: rotation nodes on for an input whose surface's second moments
  /// are axially symmetric (AxiallySymmetricSecondMoments within AxialMomentsGap), which a
  /// rotational symmetry of order 3 or more of the whole surface implies; off for the others,
  /// at no cost. On the 29 shared meshes it turns them on for the bearing, mech and queen only
  /// (gaps 0.0000-0.0052; the next, 0.178), whose trees it makes smaller (docs/builder.md).
  /// On by default (since 2026-12-07): it makes no tree of the 29 shared meshes larger.
  bool rotationNodesWhenAxial = true;
  int maximumRotationOrder = DefaultMaximumRotationOrder;

  /// With verifyBound, the plane detection of every region is kept for the call: a region
  /// detected on again (the same points, triangles, input ids where the input has normals,
  /// epsilon and detection options, bit for bit - e.g. the root when the tree is built again
  /// with pins) takes the kept result instead of running it again: the same tree, sooner
  /// (FoldingTreeDetectionCache.h). False: every region detects anew (the tests compare both).
  bool reuseDetections = true;

  /// Called with overall progress in [0,1]; return false to abort (the tree built so far is
  /// returned with `aborted` set; unfinished regions become Aborted leaves).
  std::function<bool(double)> progress;
  /// Diagnostics (Trace.h; empty: none): each fold's errors and budgets, and the detection's
  /// runs (passed on to `symmetry.trace` for every node).
  TraceSink trace;
};

/**
 * Builds the folding tree of `input` (paper §4.2), in preorder:
 * 1. A region that meets a stop criterion becomes a leaf.
 * 2. Otherwise the region is prepared (PrepareMesh: welding, orientation; LinkNearbyParts)
 *    and DetectSymmetry finds S and p with the node's epsilon. S is trimmed, p polished and
 *    S trimmed again (see trimToMirrorConsistent, polishPlane); with trimming on, detection's
 *    two runner-up planes (SymmetryResult::finalists) get the same treatment - each with
 *    its largest connected region of faces whose vertices mirror within epsilon - and the
 *    plane with the largest trimmed S wins (trimming can halve a region whose mirror image
 *    is partly outside it; ties: detection's plane). Input-degenerate faces whose vertices
 *    all belong to S join S.
 * 3. The remaining faces split into connected components R1..Rn (edge adjacency plus the
 *    proximity links). n == 0 (global symmetry): the node is a Folding node. n > 0: a
 *    Segmentation node with children fold(S) (a Folding node one level down) and a subtree
 *    per Ri in order of their lowest face id; vertices used by faces of two different
 *    children get this node's tear bit.
 * 4. fold(S): faces are counted on each side of p by centroid and the side chosen by
 *    keepSide is kept (ties: the side the canonical normal points to; counted by the last
 *    trim, whose face proof covered that side, when errorBudget is on); the stored plane's
 *    normal points into the kept side. Vertices within the snap distance of p are "on" p.
 *    A face is kept if a vertex is strictly on the kept side, or if all its vertices are on
 *    p (a face lying in the plane; the unfolder does not duplicate it); all other faces are
 *    removed. Vertices of kept faces that are on p or on the discarded side are projected
 *    onto p - and onto every ancestor fold plane they lie on (closest point of the
 *    intersection, unless that is ill-conditioned: planes through nearly the same line, or
 *    farther than epsilon from the orthogonal projection; then onto p only, dropping the
 *    flags it no longer satisfies) - and flagged in
 *    planeMask. Faces collapsed by the projection (two vertices welded) count as removed
 *    (FoldingNode::discardedOriginalFaces). Removed tear vertices are recorded on the kept
 *    boundary vertices that mirror onto them, and kept boundary vertices whose mirror
 *    copies (through this fold and any ancestor folds below a given ancestor) land on that
 *    ancestor's fold plane get the plane flag for that copy (MirroredFlag). The kept half
 *    is built recursively with epsilon / 2 and one more fold; it may fold again.
 * Original ids: each leaf point knows the input point it comes from (for points welded by
 * PrepareMesh, the first input point of the group), each leaf triangle its input triangle.
 * Input triangles with a repeated vertex index are dropped and counted
 * (FoldingTree::numberOfDroppedFaces); other zero-area triangles are kept.
 * `inputNormals` (empty, or one per input point) are used for detection as in PrepareMesh.
 * Deterministic for given options. Returns false with `error` set on invalid input or
 * options (the tree is then empty); an abort returns true with tree.aborted set.
 */
bool BuildFoldingTree(const TriangleMesh& input,
  const std::vector<Vec3>& inputNormals,
  const FoldingTreeOptions& options,
  FoldingTree& tree,
  std::string& error);
}

#endif
