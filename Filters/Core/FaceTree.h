// A bounding-volume hierarchy over a mesh's faces for exact closest-compatible-face and
// nearest-centroid queries.
#ifndef foldingmeshes_FaceTree_h
#define foldingmeshes_FaceTree_h

#include "ClosestFaceQuery.h"
#include "PointTriangleDistance.h"
#include "TriangleMesh.h"

#include <limits>
#include <vector>

namespace foldingmeshes
{
/**
 * Faces are split recursively by their centroids where the two children's boxes have the least
 * surface area times faces (Split; leaves of at most 8 faces; a few faces far larger than the
 * rest are held apart under the root first, PutLargeFacesFirst), in the frame BoxFrame chooses (the
 * identity, or axes along the mesh's long edges when its faces' boxes are much smaller there:
 * slivers of a rotated mesh). Every node stores the bounding box of its triangles and a cone
 * bounding the vertex normals of its faces, so a query skips whole subtrees that are too far away
 * *or* whose normals cannot be compatible with the query normal. Results are exact (ties: lowest
 * face id). Degenerate faces are left out. Queries are const and thread-safe.
 *
 * Why not vtkStaticCellLocator: its API answers "closest cell" or "cells in a box", not
 * "closest cell whose interpolated normal is within 45 degrees of n". Emulating that with
 * growing box queries visits every cell near a mirrored vertex whose partner is missing
 * (the common case off the symmetric region); the normal cones prune those.
 */
class FaceTree
{
public:
  /// `areaSplitDepth`: the depth from which nodes split at the median instead of by surface
  /// area (see Split; tests lower it to check the median path).
  explicit FaceTree(const PreparedMesh& mesh, int areaSplitDepth = 64);

  struct Hit
  {
    int face = -1;
    double distance = std::numeric_limits<double>::infinity();
    Vec3 point = Vec3::Zero(); ///< closest point on the face
  };

  /**
   * The face closest to p among the faces compatible with the unit vector `normal`: the
   * normal interpolated (barycentrically, from the vertex normals) at the face's closest
   * point makes a cosine >= cosLimit with `normal`. Only faces not farther than maxDistance
   * count; none gives face -1 and an infinite distance. `hintFace` (e.g. the answer of a
   * previous query for a nearby point) only speeds the search up: the result is the same.
   * With `excludedFaces` (per face id, nonzero: left out) the answer is the one for the mesh
   * without those faces - e.g. a region that lost a few faces, queried without a new tree.
   */
  Hit ClosestCompatibleFace(const Vec3& p,
    const Vec3& normal,
    double cosLimit,
    double maxDistance,
    int hintFace = -1,
    const std::vector<char>* excludedFaces = nullptr) const;

  /**
   * ClosestCompatibleFace(p, normal, cosLimit, maxDistance).face >= 0, answered by stopping at
   * the first compatible face within maxDistance (the same tests, no search for the closest):
   * for callers that only count the points with a partner.
   */
  bool HasCompatibleFaceWithin(const Vec3& p,
    const Vec3& normal,
    double cosLimit,
    double maxDistance) const;

  /**
   * Face `face` as ClosestCompatibleFace tests it: true (and `hit` its closest point and
   * distance) when it is compatible with `normal` and within maxDistance; false for other
   * faces, degenerate faces and ids out of range. A true answer bounds the closest compatible
   * face's distance (MirrorDistance's fast path).
   */
  bool CompatibleFaceHit(const Vec3& p,
    const Vec3& normal,
    double cosLimit,
    double maxDistance,
    int face,
    Hit& hit) const;
  /// The face closest to p, whatever its normal (closer than maxDistance; else face -1), among
  /// the faces f with !(*excluded)[f] when `excluded` (per face of the surface) is given.
  Hit ClosestFace(const Vec3& p,
    double maxDistance,
    const std::vector<char>* excluded = nullptr) const;

  /// The (non-degenerate) face whose centroid is nearest to p; -1 if there is none.
  int NearestCentroidFace(const Vec3& p) const;

  int NumberOfNodes() const { return static_cast<int>(this->Nodes.size()); }
  /// Faces held apart as large (the root's first child: see PutLargeFacesFirst); 0: none.
  int LargeFaces() const { return this->Large; }
  /// Levels below the root of the deepest leaf (0: a single leaf or none).
  int Depth() const { return this->MaximumDepth; }
  /// True when the boxes are built in a rotated frame (see BoxFrame).
  bool RotatedFrame() const { return this->Rotated; }
  /// The box frame (rows: its axes; the identity unless RotatedFrame()).
  const Eigen::Matrix3d& FrameAxes() const { return this->Frame; }

  /// The mesh whose faces this tree holds.
  const PreparedMesh& Surface() const { return this->Mesh; }

private:
  /// The test of NormalCone::Excludes and FloatCone::Excludes, given normal . axis and the
  /// cone's cos and sin: angle(normal, axis) > half-angle + acos(cosL), by
  /// cos(h + l) = cos h cos l - sin h sin l (valid while h + l < 180 degrees), with `margin`
  /// above the rounding of the stored cone.
  static bool ConeExcludes(double normalDotAxis,
    double cos,
    double sin,
    double cosL,
    double sinL,
    double margin)
  {
    if (cos <= -1.0 || !(cosL > margin - cos))
      return false;
    return normalDotAxis < cos * cosL - sin * sinL - margin;
  }
  /// A cone holding unit vertex normals: every normal interpolated between them points into
  /// it (it is narrower than 90 degrees, else `cos` is -1: no bound).
  struct NormalCone
  {
    Vec3 axis = Vec3::UnitX(); ///< unit mean of the vertex normals
    double cos = -1.0;         ///< cos of the half-angle (-1: no bound)
    double sin = 0.0;          ///< sin of the half-angle
    /// The cone around the mean of unit vertex normals: forEachNormal(visit) calls
    /// visit(n) for each of them (twice: for the mean, then for the half-angle).
    template <typename ForEachNormal>
    static NormalCone Around(ForEachNormal forEachNormal);
    /// True when no direction in the cone is within acos(cosL) of the unit vector `normal`
    /// (sinL = sqrt(1 - cosL^2)): angle(normal, axis) > half-angle + acos(cosL).
    bool Excludes(const Vec3& normal, double cosL, double sinL) const
    {
      return ConeExcludes(normal.dot(this->axis), this->cos, this->sin, cosL, sinL, 1e-12);
    }
  };
  /// Faces per leaf at most.
  static constexpr int LeafSize = 8;
  /// A box in single precision, rounded outward: it holds the double box it was made from,
  /// so it prunes nothing that box would not (the results stay those of the double boxes).
  struct FloatBox
  {
    Eigen::Vector3f lo, hi;
    static FloatBox Around(const Vec3& lo, const Vec3& hi);
    /// Squared distance of p (in the box frame) to the box, in double.
    double Distance2(const Vec3& p) const
    {
      return BoxDistance2(this->lo.cast<double>(), this->hi.cast<double>(), p);
    }
  };
  /// A node's NormalCone in single precision. Excludes tests with a margin (1e-6) far above
  /// the rounding of the axis, cosine and sine (about 1e-7): it excludes only normals the
  /// double cone excludes, so the results stay the same.
  struct FloatCone
  {
    Eigen::Vector3f axis;
    float cos, sin;
    static FloatCone Of(const NormalCone& cone);
    bool Excludes(const Vec3& normal, double cosL, double sinL) const
    {
      return ConeExcludes(
        normal.dot(this->axis.cast<double>()), this->cos, this->sin, cosL, sinL, 1e-6);
    }
  };
  /// What the traversal reads of a node, in one 64-byte line (the boxes of the face centroids,
  /// for NearestCentroidFace, are apart: CentroidBoxes).
  struct alignas(64) Node
  {
    FloatBox box;     ///< of the triangles
    FloatCone cone;   ///< of the vertex normals of its faces
    int first, count; ///< leaf: range in Order; inner: count == 0
    int left, right;  ///< inner node children
  };
  static_assert(sizeof(Node) == 64, "a node is one cache line");
  /// A face's bounding box (in the box frame).
  struct FaceBox
  {
    Vec3 lo, hi;
  };
  /// Builds the subtree over Order[first, first + count) (at `depth`), appended to `nodes` in
  /// preorder (child links: indices into `nodes`), from the faces' boxes and centroids in the
  /// box frame; returns its root's index. `split` > 0: the first `split` faces (in Order) are
  /// the first child, the rest the second (the root's split of PutLargeFacesFirst); else Split.
  int Build(int first,
    int count,
    int depth,
    const std::vector<FaceBox>& boxes,
    const std::vector<Vec3>& centroids,
    std::vector<Node>& nodes,
    int split = 0);
  /// Reorders Order[first, first + count) into the node's two children and returns the first
  /// one's count: the split (a boundary between 16 bins of the centroids along one axis; clo,
  /// chi: the centroids' box) of least surface area times faces summed over the two boxes, the
  /// rule of ray-tracing trees (a query descends into a child about as often as its box is
  /// large). The median along the longest axis of the centroids, the old rule, splits a grid
  /// of long thin boxes (a rack's rods, a bench's slats) along their length into halves whose
  /// boxes both span it, so a query near a rod's end visits both; by area the children hold
  /// whole rods. The median is kept where the sampled centroids fall in one bin on every
  /// axis, and from depth AreaSplitDepth on.
  int Split(int first,
    int count,
    int depth,
    const std::vector<FaceBox>& boxes,
    const std::vector<Vec3>& centroids,
    const Vec3& clo,
    const Vec3& chi);
  /// Moves the large faces (longest edge over LargeFaceRatio times the median face's, at most
  /// one face in MaximumLargeShare) to the front of Order, in id order; returns their count
  /// (0: none, Order unchanged).
  int PutLargeFacesFirst();
  /// p in the box frame, relative to Origin (as the nodes' boxes).
  Vec3 InFrame(const Vec3& p) const
  {
    return (this->Rotated ? Vec3(this->Frame * p) : p) - this->Origin;
  }
  /// A node whose (frame) box is d2 away from the query is skipped when
  /// d2 > best2 * PruneScale + PruneAdd(p): margins far above the rounding of the rotation
  /// (if any) and of the subtraction of Origin (see PruneRelativeMargin). So a hint face, which
  /// only lowers best2 sooner, never hides a face of the same computed distance.
  double PruneAdd(const Vec3& p) const;
  /// Visits the faces of the leaves not farther than sqrt(best2) from p (best2 may shrink
  /// during the visit) and not pruned by prune(node).
  template <typename Prune, typename Visit>
  void Traverse(const Vec3& p, const double& best2, Prune prune, Visit visit) const;
  /// ClosestCompatibleFace among the faces f with !excluded(f): a template, so that the
  /// query without exclusions (the hot path) inlines a constant `false`, no test per face.
  template <typename Excluded>
  Hit ClosestCompatibleFaceAmong(const Vec3& p,
    const Vec3& normal,
    double cosLimit,
    double maxDistance,
    int hintFace,
    Excluded excluded) const;
  /// Leaf test of ClosestCompatibleFace: takes face f when it is not excluded, compatible and
  /// closer (or as close with a lower id) than best2; true if taken. sinLimit is
  /// sqrt(1 - cosLimit^2) with cosLimit clamped to [-1, 1] (for the face's normal cone).
  template <typename Excluded>
  bool TryFace(const Vec3& p,
    const Vec3& normal,
    double cosLimit,
    double sinLimit,
    int k,
    double& best2,
    Hit& hit,
    Excluded excluded) const;
  static double BoxDistance2(const Vec3& lo, const Vec3& hi, const Vec3& p)
  {
    const Vec3 d = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
    return d.squaredNorm();
  }

  /// A face's corners, bounding sphere and plane, stored in tree order (Order) for the leaf
  /// tests.
  /// What Beyond reads comes first, in one 64-byte line; the corners and the normal cone
  /// after it.
  struct alignas(64) PackedFace
  {
    Vec3 center;     ///< centroid
    Vec3 normal;     ///< unit normal if planeBound, else zero
    double radius;   ///< largest distance of a corner to the centroid
    bool regular;    ///< IsRegularTriangle(a, b, c)
    bool planeBound; ///< `normal` is accurate enough for the plane bound of Beyond
    Vec3 a, b, c;
    NormalCone cone; ///< of the face's three vertex normals
  };
  /// The compatibility test of ClosestCompatibleFace: the normal interpolated (from the vertex
  /// normals) at `cp`, the closest point of face `face`, is within acos(cosLimit) of `normal`.
  bool CompatibleAt(int face,
    const ClosestPointOnTriangle& cp,
    const Vec3& normal,
    double cosLimit) const;
  /// Closest point on the packed face k (index into Order), without the sphere test.
  ClosestPointOnTriangle ClosestPoint(const Vec3& p, int k) const;
  /// True when packed face k is provably farther than sqrt(best2) from p. The face lies in
  /// its plane within `radius` of its centroid, so with h the height of p over the plane and
  /// rho the distance of p's foot on the plane from the centroid, every point of the face
  /// is at least sqrt(h^2 + max(0, rho - radius)^2) away (for a slanted sliver without an
  /// accurate normal: the bounding sphere's distance). The margins are well above the
  /// rounding errors, so a face whose computed distance could be at most sqrt(best2) is
  /// never skipped: the results are exactly those of testing every face.
  inline bool Beyond(const Vec3& p, int k, double best2) const;

  const PreparedMesh& Mesh;
  Eigen::Matrix3d Frame = Eigen::Matrix3d::Identity(); ///< rows: the box axes
  bool Rotated = false;                                ///< Frame is not the identity
  int Large = 0;                                       ///< see LargeFaces
  int MaximumDepth = 0;                                ///< see Depth
  int AreaSplitDepth = 64;                             ///< see the constructor
  double PruneScale = 1.0;        ///< 1 + PruneRelativeMargin (the constructor)
  Vec3 Origin = Vec3::Zero();     ///< the centre of the faces' box (frame), see InFrame
  double CoordinateScale = 0.0;   ///< largest |coordinate| of the mesh's points
  std::vector<int> Order;         ///< face ids, leaf ranges
  std::vector<PackedFace> Packed; ///< per Order entry
  std::vector<int> OrderIndex;    ///< face id -> index into Order (-1: degenerate)
  std::vector<Node> Nodes;
  std::vector<FloatBox> CentroidBoxes; ///< per node: the box of its faces' centroids
};

/// FaceTree::ClosestFace behind the ClosestFaceQuery interface (degenerate faces left out, ties
/// to the lowest id; optionally the faces `excluded` marks too, a mask that must outlive the
/// query), for code that takes either the tree or a VTK cell locator.
class FaceTreeQuery : public ClosestFaceQuery
{
public:
  explicit FaceTreeQuery(const FaceTree& tree, const std::vector<char>* excluded = nullptr)
    : Tree(tree)
    , Excluded(excluded)
  {
  }
  ClosestFaceHit Closest(const Vec3& p) const override
  {
    return this->ClosestWithin(p, std::numeric_limits<double>::infinity());
  }
  ClosestFaceHit ClosestWithin(const Vec3& p, double radius) const override
  {
    const FaceTree::Hit hit = this->Tree.ClosestFace(p, radius, this->Excluded);
    if (!(hit.face >= 0 && hit.distance < radius))
      return ClosestFaceHit();
    return { hit.face, hit.distance, hit.point };
  }

private:
  const FaceTree& Tree;
  const std::vector<char>* Excluded;
};
}

#endif
