// The folding tree of the paper's section 4.1: leaves hold mesh data, folding nodes a mirror
// plane and one child, segmentation nodes children whose regions partition the parent's faces;
// rotation nodes (issue 22) an axis, an order k and one child, one sector of 360/k degrees.
#ifndef foldingmeshes_FoldingTree_h
#define foldingmeshes_FoldingTree_h

#include "Plane.h"
#include "RotationAxis.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace foldingmeshes
{
/// Tree levels are numbered by node depth (root = 0). Per-vertex level flags are bits of a
/// uint64_t, so a tree has at most this many levels (the builder's maximumDepth is capped).
constexpr int MaximumFoldingTreeLevels = 64;

enum class FoldingNodeKind
{
  Leaf,
  Folding,      ///< one child (the kept half) and a plane
  Segmentation, ///< children 0..n: fold(S) first, then one subtree per remaining component Ri
  Rotation      ///< one child (one sector of 360/k degrees), an axis and an order k
};

/// The largest order a rotation node may have (FoldingNode::rotationOrder).
constexpr int MaximumRotationNodeOrder = 360;

/// Why the builder made a leaf (None for inner nodes).
enum class LeafReason
{
  None,
  MinimumFaces,    ///< fewer faces than FoldingTreeOptions::minimumFaces
  MinimumArea,     ///< area below minimumAreaFraction of the original mesh
  MaximumFolds,    ///< maximumFolds folds already on the path from the root
  NoSymmetry,      ///< no meaningful symmetric region (see FoldingTreeBuilder.h)
  MaximumDepth,    ///< maximumDepth reached (hard bound on the recursion)
  DetectionFailed, ///< the region could not be prepared for detection (e.g. zero area)
  Aborted          ///< the progress callback asked to stop; the subtree was not refined
};

const char* ToString(FoldingNodeKind kind);
const char* ToString(LeafReason reason);

/// The two per-level vertex flags of the tree (see FoldingLeafMesh).
enum class LevelFlag
{
  Tear, ///< on the segmentation boundary of the segmentation node at that depth
  Plane ///< on the plane of the folding node at that depth
};

/**
 * A flagged vertex that a fold removed, recorded on the kept vertex it mirrors onto: the
 * copy of `point` produced by reflecting it through exactly the folding nodes whose depths
 * are the bits of `mirrorMask` (among the folds below depth `level`; folds whose plane the
 * point lies on do not count, they do not duplicate it) carries `flag` for `level`. A
 * flagged vertex t removed by the fold at depth f is represented by the kept vertex v
 * nearest to reflect(t) (mask bit f); if t itself carried such records, they move to v with
 * bit f added. This keeps the flags exact through nested folds: the mirror copies of an
 * ordinary tear vertex are NOT tear vertices (the fold may map the seam onto an ancestor's
 * fold line), while the copies that recreate removed tear vertices (or removed vertices of an
 * ancestor's fold line) are.
 */
struct MirroredFlag
{
  int point = -1;
  int level = 0;
  uint64_t mirrorMask = 0;
  LevelFlag flag = LevelFlag::Tear;
};

/**
 * Mesh data of a leaf. Triangles index `points` (local ids) and are oriented consistently
 * with the input (as PrepareMesh oriented it). Everything per point / per triangle has the
 * size of `points` / `triangles`.
 *
 * Level flags (bit d = the node at depth d on the path from the root to this leaf):
 * - tearMask: the paper's tear stack. Bit d is set when the vertex lay on a segmentation
 *   boundary of the segmentation node at depth d (it was used by faces of two different
 *   children of that node), or on a seam of the sector kept by the rotation node at depth d
 *   (the unfolder stitches the turned copies there). It keeps the bit through folds (paper §4.3: it
 * inherits). Tear vertices removed by folds are recorded in mirroredFlags (see MirroredFlag).
 * - planeMask: bit d is set when the vertex lies on the plane of the folding node at depth d
 *   (it was projected or snapped onto it, see FoldingTreeBuilder.h). The unfolder merges
 *   these vertices with their mirror images, which closes the fold line. Fold-line vertices
 *   removed by a later fold are recorded in mirroredFlags.
 */
struct FoldingLeafMesh
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::vector<int> originalPointIds; ///< input point id of each point (see FoldingTreeBuilder.h)
  std::vector<int> originalFaceIds;  ///< input triangle id of each triangle
  std::vector<uint64_t> tearMask;
  std::vector<uint64_t> planeMask;
  std::vector<char> projected;             ///< 1: moved from the discarded side onto a fold plane
  std::vector<MirroredFlag> mirroredFlags; ///< sorted by point, level, flag, mask
  /// Per point (or empty: unknown): how far the unfolder may still move the point and its
  /// copies without breaking the root epsilon bound - the root epsilon minus the errors the
  /// folds on the way charged here (FoldingTreeOptions::errorBudget).
  std::vector<double> errorBudget;
  /// Per point (or empty: unknown, e.g. files written before it existed): 1 when the input
  /// point copied here lay on the input's own border (an edge used by one input face). The
  /// unfolder never fills a boundary loop along such points (FoldingTreeBuilder sets it).
  std::vector<char> inputBoundary;

  int NumberOfPoints() const { return static_cast<int>(points.size()); }
  int NumberOfFaces() const { return static_cast<int>(triangles.size()); }
};

struct FoldingNode
{
  FoldingNodeKind kind = FoldingNodeKind::Leaf;
  int parent = -1;           ///< node index, -1 for the root
  std::vector<int> children; ///< node indices (Folding, Rotation: one; Segmentation: >= 2)
  int depth = 0;             ///< root 0
  double epsilon = 0.0;      ///< absolute tolerance this node was built with
  int foldsAbove = 0;        ///< folding nodes strictly above this node
  int numberOfFaces = 0;     ///< faces of this node's region (input faces, see below)
  double area = 0.0;         ///< area of the region as it entered this node
  /// Input face ids of the region (sorted). For a node below a fold these are the faces of
  /// the kept half only; the mirrored-away faces are listed by their folding node.
  std::vector<int> originalFaces;

  // Folding nodes.
  Plane plane;             ///< normal points into the kept half
  int discardedFaces = 0;  ///< faces removed by the fold (mirrored away, or collapsed)
  int projectedPoints = 0; ///< points moved from the discarded side onto the plane
  std::vector<int> discardedOriginalFaces; ///< sorted input ids of the removed faces
                                           ///< (rotation nodes: the other k - 1 sectors)

  // Rotation nodes: the child is one sector; the unfolder turns it k - 1 times by 360/k
  // degrees about the axis (right-handed about its direction) and welds the seams.
  RotationAxis axis;
  int rotationOrder = 0; ///< k, 2 .. MaximumRotationNodeOrder

  // Detection statistics (Folding and Segmentation nodes, and NoSymmetry leaves).
  double symmetricAreaFraction = 0.0; ///< area(S) / area(region) after trimming
  bool detectionRun = false;
  int detectionStarts = 0; ///< starts the detection tried (SymmetryResult::startsTried)
  /// Wall time of the detection at this node (a measurement: differs between runs, like
  /// FoldingTree::buildSeconds; about 0 where the build reused an earlier detection of the same
  /// region, FoldingTreeOptions::reuseDetections).
  double detectionSeconds = 0.0;

  // Leaves.
  LeafReason leafReason = LeafReason::None;
  FoldingLeafMesh mesh;
};

/// An edge of the input used by more than two faces (FoldingTree::inputNonManifoldEdges).
struct InputNonManifoldEdge
{
  int a = -1; ///< input point ids, a < b
  int b = -1;
  int faces = 0; ///< faces using the edge (> 2)
  bool operator<(const InputNonManifoldEdge& o) const
  {
    return a != o.a ? a < o.a : b != o.b ? b < o.b : faces < o.faces;
  }
};

/**
 * The tree: nodes in preorder (nodes[0] is the root, children follow their parent).
 * Also the statistics of the paper's Table 1.
 */
struct FoldingTree
{
  std::vector<FoldingNode> nodes;

  int numberOfOriginalFaces = 0;  ///< input triangles
  int numberOfOriginalPoints = 0; ///< input points
  int numberOfDroppedFaces = 0;   ///< input triangles with a repeated vertex (not stored)
  double originalArea = 0.0;
  double diagonal = 0.0; ///< bounding-box diagonal of the input
  double rootEpsilon = 0.0;
  double buildSeconds = 0.0;
  bool aborted = false;
  /// Whether the builder looked for rotation nodes (FoldingTreeOptions::rotationNodes, or
  /// rotationNodesWhenAxial and the input's moments axially symmetric).
  bool rotationNodesTried = false;
  /// The proved bound on the Hausdorff distance between unfold(tree) (default UnfoldOptions)
  /// and the input, when the builder verified it (FoldingTreeOptions::verifyBound); -1: not
  /// verified (the option off, an abort, or a tree read from a file written without it).
  double verifiedBound = -1.0;
  /// Input faces the verification pinned (kept out of every symmetric region, stored as they
  /// are) and the builds it added for that (0: the first tree was proved).
  int pinnedFaces = 0;
  int verificationRounds = 0;
  /// The input's own border: its edges used by one face (after the root's weld of coincident
  /// points), as sorted pairs of input point ids (FoldingLeafMesh::originalPointIds), sorted.
  /// With the leaves' inputBoundary flags the unfolder tells the input's border from gaps.
  /// Empty: no border, or unknown (older files) - then only the flags are used.
  std::vector<std::pair<int, int>> inputBorderEdges;
  /// The input's own non-manifold edges: its edges used by more than two faces (after the
  /// root's weld; duplicate faces count), as sorted pairs of input point ids like
  /// inputBorderEdges, sorted, with the number of faces using each. The unfolder's repair
  /// keeps the faces at such an edge (up to that many). Empty: none, or unknown (older files).
  std::vector<InputNonManifoldEdge> inputNonManifoldEdges;

  bool Empty() const { return this->nodes.empty(); }
  int NumberOfNodes() const { return static_cast<int>(this->nodes.size()); }
  int NumberOfLeaves() const;
  /// Sum of the leaves' triangles: the paper's "non-redundant faces".
  int StoredFaces() const;
  int StoredPoints() const;
  /// 1 - stored / original (0 for an empty tree).
  double Compression() const;
  /// Number of levels: 1 + the largest leaf depth (a single leaf has height 1), as in the
  /// paper's Table 1 (the queen, folded three times, has height 4).
  int Height() const;
  /// Folding nodes in the tree, and the most on one root-to-leaf path.
  int NumberOfFolds() const;
  /// Rotation nodes in the tree.
  int NumberOfRotations() const;
  int MaximumFoldsOnPath() const;
  /// Indices of the leaves, in preorder.
  std::vector<int> Leaves() const;

  /**
   * Structural check, for trees built elsewhere (e.g. read back from a file): child counts
   * per kind, parent links, preorder, depths, unit plane normals, leaf array sizes and
   * index ranges, depth < MaximumFoldingTreeLevels; also the metadata: a positive, finite
   * diagonal and root epsilon (equal to the root node's epsilon), non-negative counts, at
   * least one stored triangle, leaf PlaneMask / TearMask bits only for the folding /
   * segmentation nodes above the leaf, and a diagonal that matches the extent of the stored
   * points (at most 4 diagonals, and at least diagonal / (8 * 5^folds on a path)). Returns an
   * empty string when valid, else a description of the first problem.
   */
  std::string Validate() const;
};
}

#endif
