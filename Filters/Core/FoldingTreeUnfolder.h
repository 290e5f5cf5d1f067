// Reconstruction of a mesh from its folding tree (the paper's section 4.3): postorder
// unfolding, closing of fold lines, stitching and smoothing of segmentation tears.
#ifndef foldingmeshes_FoldingTreeUnfolder_h
#define foldingmeshes_FoldingTreeUnfolder_h

#include "FoldingTree.h"
#include "Trace.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace foldingmeshes
{
struct UnfoldOptions
{
  /// Stitch and smooth the tears at segmentation nodes; false gives the raw union.
  bool stitch = true;
  /// Tear vertices of different children closer than stitchToleranceScale * (the
  /// segmentation node's epsilon) may be merged; between a rotation node's sectors, a tenth of
  /// that, sin(180/k) of it above order 31 (RotationStitchShare in RotationAxis.h).
  double stitchToleranceScale = 1.0;
  /// After vertex pairing, insert each tear vertex still without a partner into the nearest
  /// open seam edge of another child within the tolerance (splitting that triangle), which
  /// closes seams whose two sides are tessellated differently.
  bool zipper = true;
  /// Then fill the small boundary loops left between two children along the seam (saw-tooth
  /// gaps of approximately symmetric folds) by ear clipping, when the fill stays within the
  /// stitching tolerance of the loop (the final repair's test, FillWithinTolerance: a narrow
  /// crack, or small and flat); see SeamReport::filledFaces.
  bool fillSeamGaps = true;
  /// Constrained Laplacian smoothing of the seam after stitching: only the merged vertices
  /// whose cluster spread exceeds exactStitchFraction * epsilon move (exactly coincident
  /// partners - the usual case for symmetric tessellations - are left where they are), and
  /// zipped ones; each iteration moves them by smoothingWeight towards the mean of their
  /// 1-ring, never farther in total than the stitch itself moved them (cluster spread, half
  /// the zipped gap), so sharp edges along a seam are not eroded.
  int smoothingIterations = 3;
  double smoothingWeight = 0.5;
  double exactStitchFraction = 1e-3;
  /// Besides the vertices flagged in planeMask, vertices within planeTolerance * diagonal of
  /// a fold plane are merged with their mirror images.
  double planeTolerance = 1e-9;
  /// ... and so are the end points of open boundary edges lying within
  /// foldLineToleranceScale * (the folding node's epsilon) of the plane: copies of fold-line
  /// vertices made by approximate symmetries deeper in the tree (not flagged: the builder
  /// only flags copies within its snap distance). 0 turns this off.
  double foldLineToleranceScale = 0.5;
  /**
   * After the reflection at a folding node, remove the vertices the builder projected onto
   * its plane (FoldingLeafMesh::projected, with the planeMask bit of the node's depth): the
   * fold rule keeps a face straddling the plane with its far vertices projected onto it, so
   * without this every such face comes back as two (itself and its mirror image) and every
   * projected vertex is an extra vertex on the fold line. Each removed vertex's closed 1-ring
   * is re-triangulated (ear clipping, the ear that departs least from the old star first),
   * which gives back edges across the fold line as in the input; where the star does not
   * project one-to-one onto the plane perpendicular to its mean normal (a sharp crease), the
   * vertex is collapsed into a ring vertex instead (using at most a tenth of the limit below).
   * A vertex stays when it is not interior (its ring is not one closed loop), carries a tear
   * or fold-line flag of a level above, lies on a plane of a fold above or on the input's
   * border, or when the new faces would repeat an edge or a face, flip (every ear convex and
   * empty in the projection; a collapsed face not turned by 90 degrees or more), be
   * degenerate, or move the surface by more
   * than the error budget left at the vertex and its ring (sampled: the vertex, the star's
   * face centroids and spoke midpoints against the new faces, the new faces' centroids and
   * diagonal midpoints against the star; the ring's budgets are charged what it moved). With
   * the budget used up only stars planar within planeTolerance * diagonal qualify (the same
   * polygon, triangulated differently); without budgets (respectErrorBudget off, older trees)
   * the folding node's epsilon is the limit. Copies that a fold below mirrored off the fold
   * line they were projected onto (on no fold plane) are tried after the stitching at each
   * segmentation node, once their ring is closed. Points are tried in index order
   * (deterministic).
   * See UnfoldedMesh::removedProjectedPoints.
   */
  bool removeProjectedPoints = true;
  /**
   * After the reflection at a folding node (and the removal of its projected points), thin
   * the mirrored copy until the node's result has the face count of its region S
   * (FoldingNode::numberOfFaces; two faces fewer counted for each projected point still to be
   * removed at a fold above or after the traversal): an approximate fold whose halves are
   * tessellated differently keeps the half with more faces, and its mirror image would
   * double that half's density where the discarded half (FoldingNode::discardedFaces) was
   * coarser. Interior vertices of the copy are removed one at a time by the machinery of
   * removeProjectedPoints (FoldingTreeUnfolderVertexRemoval.h: the closed 1-ring
   * re-triangulated by ear clipping, here by least departure and good shape, a crease
   * collapse where the star does not project one-to-one, the same checks against flips,
   * repeated edges and degenerate faces, the move bounded by the error budget left at the
   * vertex and its ring, which is charged what moved; without budgets the node's epsilon),
   * and no new face may have an angle below 20 degrees unless the old star had a smaller one.
   * The kept half is never changed: a vertex qualifies when it belongs to the copy, its star
   * lies in the copy, neither it nor a ring vertex is on an open edge (seams stitched later,
   * the input's border), carries a tear or fold-line flag (MirroredFlag) or lies on a plane of
   * a fold above, and it is not a projected point; no new edge joins two points of the kept
   * half or the fold line. So seams and fold lines stay as they are. Order: the densest spot
   * first (the star's area relative to the copy's mean star area at the start), plus the
   * surface move relative to the limit; index order on ties; a priority queue in which the
   * ring of a removed vertex is re-queued and each vertex is measured again when it comes
   * first. Deterministic (serial). When the root is a folding node, its copy is thinned once
   * more after the final repair (closeHoles) and the last removal of projected points,
   * towards the root's face count, which seams and the repair's fills elsewhere raise, and
   * where points of the copy on seam gaps that only the repair closed were on open edges at
   * the fold (a blob whose halves are tessellated 1.3 times apart: +9.6% points -> +0.7%);
   * that pass stops before the points used by faces drop below the input's point count, and
   * where a budget is unknown it only re-triangulates planar stars. A rotation node's k copies
   * of its sector are thinned the same way, after its seams are stitched (they are thinned
   * with the copies, interior by then), towards its region's face count (a sector cut along its
   * half-planes holds more faces than its share). See
   * UnfoldedMesh::thinnedCopyPoints and foldExcessFaces.
   */
  bool matchDiscardedDensity = true;
  /**
   * Bound every vertex move (fold-line merges, stitching, zipper, smoothing, boundary weld)
   * by the leaf point's error budget (FoldingLeafMesh::errorBudget, written by the builder):
   * what the folds above left of the root epsilon there, so unfold(fold(M)) stays within it.
   * A stitch cluster goes to its mean, else to one of its members, whichever moves no member
   * beyond its budget; if none does, it is not merged (SeamReport::budgetRejectedClusters).
   * Leaves without budgets (older files) are not bounded.
   */
  bool respectErrorBudget = true;
  /**
   * After the traversal, stitch the whole result once more: every vertex on an open edge may
   * merge with (or be zipped into) one of another copy within weldToleranceScale * the root
   * epsilon - closing seams whose vertices carry no tear flag (e.g. copies of seams across
   * approximate folds), and two of one copy within min(0.01, weldToleranceScale) * the root
   * epsilon (the sides of a fold-line sliver, or an input crack that narrow). Moves are
   * bounded by the error budgets; no gaps are filled (an open
   * loop there may be the input's own border). See UnfoldedMesh::weld.
   */
  bool weldBoundaries = true;
  double weldToleranceScale = 0.5;
  /**
   * Finally (with stitch on) repair the mesh (see RepairReport, FoldingTreeUnfolderRepair.cxx
   * and FoldingTreeUnfolderHoles.cxx): drop degenerate faces and the faces that make an edge
   * non-manifold (gap fills first, then the faces most folded against the rest), orient each
   * connected component consistently (patches of consistently oriented faces flipped greedily,
   * largest first; faces at a one-sided conflict dropped), and fill every boundary loop that
   * is not the input's own border - an edge between copies of input border points
   * (FoldingLeafMesh::inputBoundary) whose input ids form an input border edge
   * (FoldingTree::inputBorderEdges); without flags (older tree files) nothing is filled - by a
   * minimal-area triangulation of its vertices (a fan around a new point at its centroid when
   * every diagonal would repeat an edge), when every point of every new face lies within
   * holeToleranceScale * root epsilon of the loop (proved, ProvedLoopDeviation), or the loop is
   * small and flat, and it has at most maximumHoleEdges edges. A gap that opens into the input's
   * border is closed by a chord between two border vertices (within 2 * that tolerance). Loops left
   * open are reported; `trace` receives where the open, non-manifold and misoriented edges
   * are before and after.
   */
  bool closeHoles = true;
  double holeToleranceScale = 1.0;
  int maximumHoleEdges = 400;
  /// Called with progress in [0,1]; return false to abort.
  std::function<bool(double)> progress;
  /// Diagnostics (Trace.h; empty: none): the repair's edge classes and loops, the removal of
  /// projected points and the thinning of mirrored copies, one line per step.
  TraceSink trace;
};

/**
 * One copy of a leaf in the unfolded mesh: the leaf's points mapped by x -> linear * x +
 * translation, the composition of the reflections applied on the way up (identity for the
 * leaf itself). mirrorMask has bit d set when the copy was reflected by the folding node at
 * depth d; `mirrored` is true for an odd number of reflections (then the orientation of
 * the copy's triangles was reversed, and 3-component vectors must be multiplied by
 * `linear` - a reflection, determinant -1 - to follow the geometry).
 * Points moved by plane merging or stitching differ from the affine map by at most the
 * stitching tolerance.
 */
struct UnfoldCopy
{
  int leaf = -1; ///< node index of the leaf
  uint64_t mirrorMask = 0;
  bool mirrored = false;
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();
};

/// What happened at one segmentation node.
struct SeamReport
{
  int node = -1;
  int depth = 0;
  int tearVertices = 0;     ///< vertices carrying this level's tear bit before stitching
  int stitchedVertices = 0; ///< of those, merged with a partner of another child or zipped
  int zippedVertices = 0;   ///< of those, inserted into an open seam edge of another child
  int unmatchedTearVertices = 0;
  int gapEdges = 0; ///< boundary edges left between two tear vertices of this level
  double gapLength = 0.0;
  int filledLoops = 0; ///< seam gaps closed by new triangles
  int filledFaces = 0; ///< triangles added for them (before copies made above)
  int smoothedVertices = 0;
  int droppedFaces = 0;               ///< faces collapsed or duplicated by the merge
  double maximumStitchDistance = 0.0; ///< largest distance of a merged vertex to its cluster mean
  int budgetRejectedClusters = 0;     ///< clusters left unmerged: no place within the budgets
};

/// The final repair (UnfoldOptions::closeHoles). Loops are counted after the repair.
struct RepairReport
{
  int droppedFaces = 0; ///< faces removed at non-manifold edges
  int flippedFaces = 0; ///< faces reversed to orient their component consistently
  int filledLoops = 0;  ///< boundary loops closed by new faces
  int filledFaces = 0;
  /// Loops that no triangulation of their own vertices closes without repeating an edge are
  /// filled by a fan around a new point at their centroid (point data of the nearest vertex).
  int addedPoints = 0;
  /// Loops left open because they are the input's own border (an edge between two copies of
  /// input border points): kept, as they must be.
  int borderLoops = 0;
  int borderEdges = 0;
  double borderLength = 0.0;
  /// Loops left open without border information (trees written before inputBoundary).
  int unknownLoops = 0;
  int unknownEdges = 0;
  double unknownLength = 0.0;
  /// Gaps that could not be closed: no triangulation, too long, or the fill would leave the
  /// tolerance (holeToleranceScale).
  int openLoops = 0;
  int openEdges = 0;
  double openLength = 0.0;
};

struct UnfoldedMesh
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;

  std::vector<int> pointOriginalIds; ///< input point id of the leaf point copied
  std::vector<int> pointCopy;        ///< index into copies (a merged point: the lowest one)
  std::vector<char> pointMirrored;   ///< the copy was reflected an odd number of times
  /// 1: a point added by the repair (RepairReport::addedPoints) at the centroid of a loop; not
  /// an image of a leaf point (its ids and copy are those of the nearest loop vertex).
  std::vector<char> pointAdded;

  /// Input triangle id of the stored (leaf) triangle copied: a mirrored copy carries the id
  /// of the kept face it reflects (the tree does not store which face was discarded).
  std::vector<int> faceOriginalIds;
  std::vector<int> faceLeaf; ///< node index of the leaf the face comes from
  std::vector<int> faceCopy; ///< index into copies
  std::vector<char> faceMirrored;
  /// 1: a triangle added to fill a seam gap or a hole (not a copy of a leaf triangle; its ids
  /// and copy are those of a neighbouring face, for attributes); a triangle re-triangulated
  /// after a point removal only where every face of the removed star was.
  std::vector<char> faceFilled;

  std::vector<UnfoldCopy> copies;

  // Report.
  int planeMergedVertices = 0; ///< vertices shared by a copy and its mirror image (fold lines)
  int droppedMirrorFaces = 0;  ///< faces lying in a fold plane, not duplicated
  /// Vertices projected onto a fold plane by the builder and removed again after the
  /// reflection (UnfoldOptions::removeProjectedPoints), and the copies of projected points
  /// left in the result (not removable, or the option off).
  int removedProjectedPoints = 0;
  int projectedPoints = 0;
  /// Vertices removed from mirrored copies and from rotation nodes' copies of their sectors
  /// (UnfoldOptions::matchDiscardedDensity), and the faces the folding and rotation nodes'
  /// results still had above their regions' face counts after it (less two per projected point
  /// still to be removed; summed over those nodes, as left by the thinning in the traversal: a
  /// folding root's second pass after the repair is counted in thinnedCopyPoints only; with the
  /// thinning off, the excess it would have removed).
  int thinnedCopyPoints = 0;
  int foldExcessFaces = 0;
  std::vector<SeamReport> seams; ///< one per segmentation node (postorder)
  /// The final boundary weld (weldBoundaries): tearVertices = vertices on open edges before.
  SeamReport weld;
  RepairReport repair;      ///< the final repair (closeHoles)
  int stitchedVertices = 0; ///< sums over the seams
  int unmatchedTearVertices = 0;
  int gapEdges = 0;
  double gapLength = 0.0;
  int filledFaces = 0; ///< faces of the result added by seam gap filling (faceFilled)
  /// The final mesh: edges used by one triangle, and by more than two.
  int openEdges = 0;
  int nonManifoldEdges = 0;
  /// Edges of two faces that traverse them in the same direction (orientation flips at a
  /// stitched seam).
  int misorientedEdges = 0;
  int budgetRejectedClusters = 0; ///< over all seams and the weld
  bool aborted = false;

  int NumberOfPoints() const { return static_cast<int>(points.size()); }
  int NumberOfFaces() const { return static_cast<int>(triangles.size()); }
};

/**
 * unfold(T) by a postorder traversal (paper §4.3):
 * - leaf: its mesh (one copy);
 * - folding node: unfold(child) U reflect(unfold(child), p). The reflected triangles are
 *   reversed, so the result stays consistently oriented. Vertices on p are not duplicated:
 *   the mirrored triangles use them, and they are projected exactly onto p, so the fold
 *   line is closed. "On p": flagged (planeMask bit of the node's depth, or a MirroredFlag
 *   whose reflections have all been applied to this copy), within planeTolerance, or an end
 *   point of an open edge lying within foldLineToleranceScale * epsilon of p (and within
 *   its error budget, respectErrorBudget). Triangles
 *   whose three vertices are on p are not duplicated. Per-vertex flags follow the copies
 *   exactly (MirroredFlag): a mirrored copy does not inherit its original's flags. Then
 *   the builder's projected points on p are removed (removeProjectedPoints) and the
 *   mirrored copy is thinned to the face count of the node's region (matchDiscardedDensity).
 * - segmentation node: the union of the children; then (stitch on) each vertex carrying the
 *   node's tear bit proposes the nearest tear vertex of another child within the tolerance;
 *   proposals are accepted by increasing distance (union-find) unless they would merge two
 *   vertices of the same child; each cluster becomes one vertex at its mean (or at a member,
 *   or stays unmerged, whichever keeps every move within the error budgets); collapsed and
 *   duplicate triangles are dropped; tear vertices still alone are zipped into open seam
 *   edges of other children (UnfoldOptions::zipper); small seam loops are filled
 *   (fillSeamGaps); the seam is smoothed. Tear vertices
 *   left unmatched and the boundary edges between tear vertices are reported per node
 *   (SeamReport) and in total - never hidden.
 * - rotation node: the child's result turned k - 1 times by 360/k degrees about the axis
 *   (orientation kept), the seams between neighbouring sectors stitched like a segmentation's
 *   (the sectors play the children), the k copies thinned towards the node's region face count
 *   (matchDiscardedDensity).
 * - finally (weldBoundaries) the open boundaries of different copies are stitched once more
 *   (UnfoldedMesh::weld), and (closeHoles) the mesh is repaired: non-manifold faces dropped,
 *   components oriented, holes that are not the input's border filled (UnfoldedMesh::repair).
 * With the builder's error budgets (FoldingTreeOptions::errorBudget) and respectErrorBudget,
 * no point ends farther from the affine image of its leaf point than that point's budget, so
 * the result stays within the root epsilon of the input the tree was built from.
 * Returns false with `error` set when the tree is invalid (FoldingTree::Validate).
 * Deterministic.
 */
bool UnfoldFoldingTree(const FoldingTree& tree,
  const UnfoldOptions& options,
  UnfoldedMesh& result,
  std::string& error);
}

#endif
