// Distances of mirrored vertices to the mesh: the paper's coarse and fine metrics.
#ifndef foldingmeshes_MirrorDistance_h
#define foldingmeshes_MirrorDistance_h

#include "ClosestFaceQuery.h"
#include "FaceTree.h"
#include "Plane.h"

#include <memory>

namespace foldingmeshes
{
enum class DistanceMetric
{
  /// Distance to the plane of the face whose centroid is nearest; infinite when
  /// the normals differ by 90 degrees or more.
  Coarse,
  /// Exact point-to-triangle distance to the closest compatible face.
  Fine
};

/**
 * For every vertex v_i with normal n_i, reflects both through a plane and measures
 * d_i = dist(r_i, M) with the chosen metric. Runs in parallel (vtkSMPTools); every
 * vertex is independent, so results do not depend on the thread count.
 */
class MirrorDistance
{
public:
  /// Distances of the reflected vertices of `mesh` to `mesh` itself.
  MirrorDistance(const PreparedMesh& mesh, double compatibilityAngleDegrees);

  /// Distances of the reflected vertices of `query` (points and vertex normals) to the
  /// surface `target`: a sampled copy made of some of target's vertices (ClusterVertices)
  /// is measured against the full surface. Both meshes must outlive this object.
  MirrorDistance(const PreparedMesh& query,
    const PreparedMesh& target,
    double compatibilityAngleDegrees);

  /// The same with a face tree of the target that the caller already has (shared, not
  /// copied; it must outlive this object).
  MirrorDistance(const PreparedMesh& query,
    const FaceTree& targetFaces,
    double compatibilityAngleDegrees);

  /// d[i] for all vertices; distances beyond maxDistance (fine metric) are infinite.
  /// With `closest`, also the closest compatible point of the mesh (fine metric) or the
  /// foot of the perpendicular on the face plane (coarse metric), with `closestNormals` the
  /// unit normal of the face holding it, and with `closestFaces` that face's id (-1 where
  /// d[i] is infinite). One entry per query vertex; faces are the target's.
  /// `hints`: the closest faces of an earlier call, updated (resized to one per vertex if
  /// needed); they only speed the search up. Without it, this object's own hints are used
  /// (then concurrent calls on one object are not safe; with separate hints they are).
  void Compute(const Plane& plane,
    DistanceMetric metric,
    double maxDistance,
    std::vector<double>& d,
    std::vector<Vec3>* closest = nullptr,
    std::vector<Vec3>* closestNormals = nullptr,
    std::vector<int>* closestFaces = nullptr,
    std::vector<int>* hints = nullptr) const;

  /**
   * The fine metric again for the vertices `vertices` only, on the mesh without the faces
   * where excludedFaces[f] is nonzero: d[i] and closestFaces[i] (sized by the caller) as
   * Compute would give them for that mesh - provided its vertex normals and degenerate faces
   * are this mesh's (the caller checks), and the vertices are used by a non-excluded face
   * (the others' distance is infinite, no query needed). When a mesh loses faces, only the
   * vertices whose closest face was lost need this: the others keep their minimum.
   */
  void Recompute(const Plane& plane,
    double maxDistance,
    const std::vector<int>& vertices,
    const std::vector<char>& excludedFaces,
    std::vector<double>& d,
    std::vector<int>& closestFaces) const;

  const FaceTree& Tree() const { return this->Faces; }

  /**
   * A fast path for the fine metric (issue 19): a plain closest-face query over the target's
   * triangles (e.g. a vtkStaticCellLocator, see vtkCellLocatorFaceQuery.h), asked first. When
   * its face is compatible (FaceTree::CompatibleFaceHit), its distance bounds the face tree's
   * search, which then decides among the faces that close: the answers are bit for bit those
   * without the fast path. Null: no fast path. Not owned; it must outlive this object.
   * Compute only (Recompute uses the tree alone).
   */
  void SetFastPath(const ClosestFaceQuery* plain) { this->FastPath = plain; }

  /// Forgets this object's own search hints (LastFace), as a new object starts: an object
  /// handed on (ShrinkingSubsetDistances::Adopt) is then in a new one's state, not only in
  /// its results (hints never change an answer, FaceTree::ClosestCompatibleFace).
  void ResetHints() const { this->LastFace.assign(this->LastFace.size(), -1); }

private:
  /// VertexUsed and LastFace for the query mesh.
  void MarkUsedVertices();

  const PreparedMesh& Mesh;             ///< the query vertices
  std::unique_ptr<FaceTree> OwnedFaces; ///< the target's face tree, unless shared
  const FaceTree& Faces;
  const PreparedMesh& Target; ///< the surface measured against (Faces.Surface())
  double CosLimit;
  std::vector<char> VertexUsed;
  /// Last closest compatible face (of Target) per vertex: a search hint only (each vertex is
  /// written by the one thread that handles it; results never depend on it), unless the
  /// caller passes its own.
  mutable std::vector<int> LastFace;
  const ClosestFaceQuery* FastPath = nullptr;
};
}

#endif
