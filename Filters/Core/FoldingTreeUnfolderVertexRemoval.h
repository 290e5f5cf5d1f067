// Internal to FoldingTreeUnfolder*.cxx (no public API): removal of single interior vertices
// of a Piece by re-triangulating their closed 1-rings, shared by the removal of projected
// points (FoldingTreeUnfolderProjectedPoints.cxx) and the thinning of mirrored copies
// (FoldingTreeUnfolderDensity.cxx).
#ifndef foldingmeshes_FoldingTreeUnfolderVertexRemoval_h
#define foldingmeshes_FoldingTreeUnfolderVertexRemoval_h

#include "FoldingTreeUnfolderInternal.h"

#include <vector>

namespace foldingmeshes
{
namespace unfolder_detail
{
/// What a re-triangulation must respect beyond the checks every removal makes.
struct RingRules
{
  /// Smallest interior angle (radians) a new face may have, unless the old star already had
  /// a smaller one (then that one: never worse than before). 0: no such check.
  double minimumAngle = 0.0;
  /// Weight of the ear's shape in the ear order: an ear's cost (its departure from the old
  /// star) grows by shapeWeight x the mean spoke length x (1 - its smallest angle / 60
  /// degrees). 0: departure alone (and the shorter diagonal on ties).
  double shapeWeight = 0.0;
  /// Per point, or nullptr: no new edge may join two points marked here (e.g. the vertices
  /// of a fold line, whose edges must stay as they are).
  const std::vector<char>* noNewEdgeBetween = nullptr;
};

/// A removal found by VertexRemover::Try, applied by VertexRemover::Apply.
struct RingRemoval
{
  int vertex = -1;
  std::vector<int> ring;         ///< the closed 1-ring, in order
  std::vector<int> ringFace;     ///< ringFace[i]: the star face with ring edge ring[i] -> ring[i+1]
  std::vector<Triangle> created; ///< the new faces over the ring
  double moved = 0.0;            ///< largest deviation from the old star measured
  double limit = 0.0;            ///< what it was allowed to move (the error limit)
};

/**
 * True when no triangle of three points of `ring` lies within `reach` of x, measured as the
 * budget check of VertexRemover::Try measures the faces a re-triangulation creates
 * (ClosestPointTriangle) and in each vertex order one can be created in: every face ear
 * clipping or a collapse into a ring vertex makes is three ring points in the ring's cyclic
 * order, starting at any of them (the closest point's rounding depends on the order). Try
 * refuses a removal early where this holds for the limit: its budget check would fail.
 */
bool NoRingTriangleWithin(const Vec3& x,
  const std::vector<Vec3>& points,
  const std::vector<int>& ring,
  double reach);

/**
 * Removes interior vertices of a piece one by one (deterministic: in the order asked).
 * Try(v) re-triangulates the closed 1-ring of v by ear clipping (the ear that departs least
 * from the old star first) in the plane perpendicular to the star's mean normal; that needs
 * the star to project one-to-one onto that plane (every star face facing the mean normal,
 * the angles around v summing to one turn), every ear convex there and empty of other ring
 * vertices (so no new face flips against the star). Otherwise (a sharp crease through v) v
 * is collapsed into the ring vertex whose new faces depart least (no new face turning 90
 * degrees or more, moving the surface by at most a tenth of the limit). Either way no new
 * edge may exist already (no duplicate or non-manifold edge, no duplicate face), no new face
 * may be degenerate, the RingRules hold, and the surface moves by at most the limit
 * (sampled: v, the star's face centroids and spoke midpoints against the new faces, the new
 * faces' centroids and diagonal midpoints against the star). Apply replaces the star by the
 * new faces (each carries the ids, copy and flags of an old star face - the
 * one containing its centroid seen along the star's mean normal, among the star faces with
 * the copy and flags of the one whose ring edge starts at its second vertex) and charges the
 * ring's error budgets what it moved. Compact drops the removed points and replaced faces.
 */
class VertexRemover
{
public:
  /// `slack`: the smallest limit (rounding: a star planar to it is re-triangulated even
  /// with its budget used up).
  VertexRemover(Piece& piece, double slack);

  /// The error limit at v: the least budget of v and its star's vertices, `fallback` where
  /// the budgets are unknown (infinite), at least the slack.
  double Limit(int v, double fallback) const;
  bool Try(int v,
    double limit,
    const RingRules& rules,
    RingRemoval& removal,
    const char*& why) const;
  void Apply(const RingRemoval& removal);

  /// Whether v is interior: its star's ring edges form one closed loop (Try's first check
  /// after the limit on the faces around v).
  bool Interior(int v) const;

  bool Removed(int v) const { return this->IsRemoved[v] != 0; }
  /// The faces of v that are still there.
  const std::vector<int>& FacesOf(int v) const { return this->VertexFaces[v]; }
  bool Alive(int f) const { return this->FaceAlive[f] != 0; }
  int Count() const { return this->RemovedCount; }

  /// Drops the removed points and the replaced faces from the piece, keeping every array
  /// aligned; `perPoint` (optional) is compacted with the points. Returns how many points
  /// were removed; the remover then starts over on the compacted piece.
  int Compact(std::vector<char>* perPoint);

private:
  Piece& Mesh;
  double Slack;
  std::vector<std::vector<int>> VertexFaces;
  std::vector<char> FaceAlive, IsRemoved;
  int RemovedCount = 0;
};
} // namespace unfolder_detail
} // namespace foldingmeshes

#endif
