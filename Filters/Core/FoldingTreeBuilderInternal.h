// Builder, the class behind BuildFoldingTree (members in FoldingTree*.cxx); not installed.
#ifndef foldingmeshes_FoldingTreeBuilderInternal_h
#define foldingmeshes_FoldingTreeBuilderInternal_h

#include "FaceTree.h"
#include "FoldingTreeBuilder.h"
#include "FoldingTreeDetectionCache.h"
#include "FoldingWorkMesh.h"
#include "MeshPreparation.h"
#include "ShrinkingSubsetDistances.h"
#include "SurfaceDistance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace foldingmeshes
{
namespace treebuilder
{
/// The side a fold through `plane` keeps: true for the side `plane.normal` points to. Faces
/// are counted by their centroids on each side; keepSide picks the side with more (ties: the
/// positive one) or fewer faces.
bool KeepsPositiveSide(const std::vector<Vec3>& points,
  const std::vector<Triangle>& triangles,
  const Plane& plane,
  KeepSide keepSide);

/// Input-degenerate faces (never in S: detection ignores them) follow S when all their
/// vertices are vertices of S.
void AddDegenerateFaces(const WorkMesh& w, const PreparedMesh& pm, std::vector<char>& S);

/// A rotation node's sector, planned (Builder::PlanRotation) before the node is made.
struct RotationPlan
{
  RotationAxis axis;
  int order = 0;
  /// Per face of w: the rotational region (a segmentation's child 0); empty: the whole region.
  std::vector<char> region;
  int regionFaces = 0;
  /// Per face / point of the planned region: the sector, its points with the seams made to
  /// meet, the seam vertices, and what the turned copies charge each kept point's budget.
  std::vector<char> keep;
  std::vector<Vec3> points;
  std::vector<char> seam;
  std::vector<double> charge;
  /// The sector's faces were cut along its bounding half-planes (FoldingTreeRotation.cxx,
  /// step 3b): Rotate cuts the region it gets the same way; start: the sector's first angle.
  bool cutFaces = false;
  double start = 0.0;
  /// Planned by the second pass (PlanSector's cutUncovered): counts as a second order
  /// (Builder::KeptSecondOrder) once a tree keeps it.
  bool secondPass = false;
};

/// `options` with rotationNodesWhenAxial decided for `input`: rotationNodes on where its
/// surface's second moments are axially symmetric (FoldingTreeOptions::rotationNodesWhenAxial).
FoldingTreeOptions RotationNodesDecided(const TriangleMesh& input,
  const FoldingTreeOptions& options);

class Builder
{
public:
  /// pinned: per input face (or empty), 1 where the face may not be part of any symmetric
  /// region S (BuildFoldingTree's verification keeps it stored as it is).
  /// toInput: distances to the input surface (shared by BuildFoldingTree's builds and its
  /// verification).
  Builder(const FoldingTreeOptions& options,
    const std::vector<Vec3>& inputNormals,
    FoldingTree& tree,
    const std::vector<char>& pinned,
    const SurfaceDistanceQuery& toInput)
    : Options(options)
    , InputNormals(inputNormals)
    , Tree(tree)
    , Pinned(pinned)
    , ToInput(toInput)
  {
    this->MaximumDepth = std::max(1, std::min(options.maximumDepth, MaximumFoldingTreeLevels - 1));
  }

  void Run(WorkMesh root);
  /// The input's own border (edges of one face) and non-manifold edges (more than two faces,
  /// duplicates included), by input point id, from the root's region after its weld:
  /// FoldingTree::inputBorderEdges, inputNonManifoldEdges and InputBoundary. They change no
  /// folding decision (the leaves and the unfolder's repair use them).
  void RecordInputEdges(const WorkMesh& w);

  bool Aborted = false;
  /// Whether a node may also plan and build the next smaller order that passes and the first
  /// cut one (PlanRotation's `second` and `cutSecond`); whether a tree kept such a sector
  /// (BuildFoldingTree retries without them before the planes alone when that tree misses the
  /// verification).
  bool SecondOrders = true;
  bool KeptSecondOrder = false;
  /// The detections of the earlier builds of this BuildFoldingTree call (null: none kept).
  DetectionCache* Detections = nullptr;

private:
  /// Reports monotonic progress; false once the callback asked to stop.
  bool Report(double value);

  double Fraction(double faces) const;

  int NewNode(int parent, int depth, double eps, int folds, const WorkMesh& w);

  void MakeLeaf(int index, WorkMesh& w, LeafReason reason);

  bool Prepare(const WorkMesh& w, double eps, PreparedMesh& pm) const;

  /// The faces of S as a prepared mesh (face order kept) with the region's vertex normals.
  static bool PrepareSubset(const WorkMesh& w,
    const PreparedMesh& pm,
    const std::vector<char>& S,
    const FaceEdgeUses& edgeUses,
    PreparedMesh& spm);

  /**
   * Polishes the plane on S alone: Gauss-Newton steps of the point-to-tangent-plane fit
   * (RefinePlaneFromCorrespondences) with every vertex of S weighted by its area, partners =
   * closest compatible points of S itself. Detection weighs vertices near the remaining
   * faces down and can stop a fraction of a degree off; on the trimmed S there are no
   * outliers. The plane with the lowest area-weighted residual is returned (the input plane
   * unless a step improves it). `edgeUses`: pm's (ComputeFaceEdgeUses). With `prepared`, S
   * as prepared here and its mirror-distance queries are handed on (for Trim on the same S).
   */
  Plane Polish(const WorkMesh& w,
    const PreparedMesh& pm,
    const std::vector<char>& S,
    const Plane& plane,
    double eps,
    const FaceEdgeUses& edgeUses,
    PreparedSubsetQueries* prepared = nullptr) const;

  /**
   * S minus its faces with a vertex whose mirror image is not within eps (and, with
   * errorBudget, its budget limit, ShrinkingMirrorBudget) of S, repeated until stable, keeping
   * the largest connected part. With errorBudget, the mirror image of every face must also be
   * within the least limit of its vertices at every point, of S itself (`region`: pm's faces,
   * those outside S excluded; MirroredFacesWithin, anew in each iteration), not only at its
   * corners: an image on faces outside S would be unfolded on top of them. The plane is fixed
   * and S only shrinks: the iterations after the first update their predecessor's distances
   * and partners (ShrinkingSubsetDistances, ShrinkingMirrorBudget).
   * provenSide: the side of `plane` (+1 along its normal, -1 against it) whose faces the
   * face proof covered - the side the fold will keep, judged on S as it was then (a later
   * change of S could tip a near tie; the fold keeps this side) - or 0 without errorBudget.
   * wholeParts: what is left of S is its largest connected region and its whole parts
   * (LargestRegionAndWholeParts), else its largest connected region.
   * `edgeUses`: pm's (ComputeFaceEdgeUses). `prepared`: S prepared elsewhere with its
   * queries (Polish's), used where it is what the first iteration prepares
   * (ShrinkingSubsetDistances::Adopt).
   * winAbove: S matters to the caller only if its area ends above this (-infinity: always);
   * once it cannot, Trim stops and returns S empty (S only shrinks: the full trim would have
   * ended at or below winAbove too).
   */
  std::vector<char> Trim(const WorkMesh& w,
    const PreparedMesh& pm,
    const FaceTree& region,
    std::vector<char> S,
    const Plane& plane,
    double eps,
    bool wholeParts,
    double winAbove,
    int& provenSide,
    const FaceEdgeUses& edgeUses,
    PreparedSubsetQueries prepared = {}) const;

  /// Detection's plane and its runners-up tried by ChooseSymmetricRegion.
  static constexpr size_t RegionCandidatePlanes = 3;
  /// ... and on regions of several parts, with whole parts, the detector's extra finalists
  /// (SymmetryOptions::scoreEveryFinalist) too.
  static constexpr size_t MultiPartCandidatePlanes = 3;

  /**
   * S and its plane for a node: the detected region, trimmed, the plane polished on it and
   * S trimmed again (trimToMirrorConsistent, polishPlane). Trimming can shrink a region
   * a lot when its mirror image is partly outside it; so the runner-up planes of detection
   * (SymmetryResult::finalists) get the same treatment - their largest connected region of
   * faces within eps, trimmed, polished - and the largest S wins (ties: detection's order).
   * Planes of ancestor folds are skipped (IsAncestorPlane), except detection's own, which
   * the caller judges. Empty S: none.
   */
  std::vector<char> ChooseSymmetricRegion(const WorkMesh& w,
    const PreparedMesh& pm,
    const FaceTree& region,
    const SymmetryResult& result,
    double eps,
    uint64_t pathFolds,
    Plane& plane,
    int& provenSide) const;

  /// S as trimmed and polished for `plane` (see ChooseSymmetricRegion); empty where it
  /// would end no larger than winAbove (see Trim), possibly before polishing.
  std::vector<char> TrimAndPolish(const WorkMesh& w,
    const PreparedMesh& pm,
    const FaceTree& region,
    std::vector<char> S,
    double eps,
    bool wholeParts,
    double winAbove,
    Plane& plane,
    int& provenSide) const;

  bool IsAncestorPlane(const Plane& p, uint64_t pathFolds, const Vec3& at, double eps) const;

  /// Builds the symmetric region of node `at` (its region, at depth atDepth): a fold or a
  /// rotation (Builder::Segment's child 0, or the node itself when S is the whole region).
  using SymmetricChild = std::function<void(int at, WorkMesh region, int atDepth)>;
  /**
   * Node `index` with symmetric region S: `symmetric` on the node itself when S is the whole
   * region, else a segmentation node with child 0 = `symmetric` on S and one subtree per
   * remaining component (paper 4.2; the tear bits of the node's depth on their boundaries).
   */
  void Segment(int index,
    WorkMesh w,
    const PreparedMesh& pm,
    const std::vector<char>& S,
    int depth,
    double eps,
    int folds,
    uint64_t pathFolds,
    const SymmetricChild& symmetric);
  /// Faces the leaves of the subtree of `index` store (its nodes: index .. the last, preorder).
  int SubtreeStoredFaces(int index) const;

  /// Builds the subtree of region w; returns its node index.
  int Build(WorkMesh w, int parent, int depth, double eps, int folds, uint64_t pathFolds);

  /**
   * Tear vertices that the fold at `depth` removes (not used by a kept face) are recorded on
   * kept vertices of the region's boundary (see MirroredFlag): each removed tear vertex t on
   * the nearest one to reflect(t), and each kept boundary vertex v whose mirror image lies
   * within eps of a removed tear vertex gets that vertex's flags. Both directions, because
   * with approximately symmetric tessellations the two sides of the seam need not have the
   * same number of vertices; the zipper of the unfolder then closes the seam.
   */
  void TransferDiscardedTears(WorkMesh& w,
    const std::vector<char>& used,
    const Plane& plane,
    int depth,
    double eps) const;

  /**
   * Fold lines of ancestor folds in the mirror copies: a boundary vertex v of the kept half
   * whose copy R_M(R_f(v)) (reflected by this fold f, then by the ancestor folds M between
   * an ancestor fold a and f, deepest first) lies within a's snap distance of a's plane gets
   * the plane flag (a, M + f). Only boundary vertices can lie on a fold line; M ranges over
   * all subsets (at most 2^(maximumFolds - 1)). Copies without this fold were flagged by
   * earlier folds. Plane flags of removed vertices are not transferred: this computes the
   * flags from the geometry the unfolder will produce. Flags of earlier folds whose copy this
   * fold's projection moved more than a's epsilon off a's plane are dropped (the unfolder
   * would drag the copy onto it).
   */
  void FlagMirroredFoldLines(WorkMesh& w,
    const std::vector<char>& keep,
    const Plane& plane,
    int depth,
    uint64_t pathFolds) const;

  /**
   * Rotation nodes (FoldingTreeOptions::rotationNodes; the rule is in FoldingTreeRotation.cxx):
   * whether node `index` (region w, prepared as pm, with its face tree and the plane
   * detection's result) may keep one sector of a rotation - of the whole region, or (plan.region)
   * of its rotational region, child 0 of a segmentation. wholeMirror: the mirror plane's S is
   * the whole region (then order 2 is left to the fold). `second` (optional): a sector of the
   * whole region of the next smaller order that passes too (order 0: none), for the caller to
   * build beside the first (the largest order is not always the smallest subtree: a sector of
   * even order may fold again below).
   */
  bool PlanRotation(int index,
    const WorkMesh& w,
    const PreparedMesh& pm,
    const FaceTree& regionFaces,
    const SymmetryResult& planes,
    bool wholeMirror,
    int depth,
    double eps,
    RotationPlan& plan,
    RotationPlan* second = nullptr,
    RotationPlan* cutSecond = nullptr) const;
  /// `cutUncovered`: only the orders whose whole faces do not cover the region once, their
  /// faces cut along the half-planes (the second pass).
  bool PlanSector(const RotationResult& r,
    const WorkMesh& region,
    const std::vector<int>& orders,
    double eps,
    RotationPlan& plan,
    std::vector<int>* covered,
    bool cutUncovered = false) const;
  /// Turns node `index` (region w: the region PlanSector planned on) into a rotation node
  /// and builds the sector below it.
  void Rotate(int index, WorkMesh w, const RotationPlan& plan, int depth, double eps, int folds);
  bool HasRotationAbove(int index) const;

  /// Turns node `index` (region w) into a folding node and builds the kept half below it.
  /// provenSide: +1 / -1, the side of `plane` whose faces the trim proved (their mirror
  /// images within the error budget: Trim), which the fold keeps; 0: none proved, the side
  /// is chosen by Options.keepSide.
  double ChargeMirrorError(const WorkMesh& w,
    const std::vector<char>& used,
    const Plane& plane,
    double eps,
    const SurfaceDistanceQuery& toRegion,
    std::vector<double>& charge,
    std::vector<double>& limit) const;
  template <typename BeyondBudget>
  int ProjectOntoFoldPlane(WorkMesh& w,
    const std::vector<char>& used,
    const std::vector<int>& side,
    const Plane& plane,
    int depth,
    double eps,
    uint64_t pathFolds,
    const std::vector<Vec3>& slide,
    const std::vector<char>& slides,
    BeyondBudget beyondBudget);
  void Fold(int index,
    WorkMesh w,
    Plane plane,
    int depth,
    double eps,
    int folds,
    uint64_t pathFolds,
    int provenSide);

  const FoldingTreeOptions& Options;
  const std::vector<Vec3>& InputNormals;
  FoldingTree& Tree;
  const std::vector<char>& Pinned;
  /// Whether face f of region w is pinned (see the constructor).
  bool IsPinned(const WorkMesh& w, int f) const
  {
    return !this->Pinned.empty() && this->Pinned[w.faceOrig[f]];
  }
  const SurfaceDistanceQuery& ToInput; ///< distances to the input surface
  std::vector<Plane> PlaneAtDepth;
  std::vector<double> EpsilonAtDepth;
  /// Per input point id: 1 on the input's border (after the root's weld); see MakeLeaf.
  std::vector<char> InputBoundary;
  int MaximumDepth = 48;
  double DoneFaces = 0.0;
  /// > 0 while Build builds the alternatives of a node (rotation and fold) to compare them.
  int BuildingAlternatives = 0;
  double LastProgress = 0.0;
};
}
}

#endif
