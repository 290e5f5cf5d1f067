// Fine mirror distances over a face subset that shrinks (Builder::Trim's loop).
#ifndef foldingmeshes_ShrinkingSubsetDistances_h
#define foldingmeshes_ShrinkingSubsetDistances_h

#include "MirrorDistance.h"
#include "Plane.h"
#include "SubsetPreparation.h"
#include "TriangleMesh.h"

#include <memory>
#include <vector>

namespace foldingmeshes
{
/// A face subset prepared on its own and the mirror-distance queries over it (its face tree),
/// made by one step of the builder and handed to the next one over the same subset
/// (Builder::Polish to Builder::Trim).
struct PreparedSubsetQueries
{
  std::unique_ptr<PreparedMesh> subset;
  std::unique_ptr<MirrorDistance> queries; ///< over *subset
};

/**
 * For a sequence of face subsets S of `mesh`, each within the previous one, and one plane:
 * S prepared on its own (PrepareFaceSubset) and the fine mirror distances of its vertices
 * (MirrorDistance::Compute on it) - bit for bit, but without a new FaceTree and a query per
 * vertex each time.
 *
 * A distance is the lowest (squared distance, face) over the compatible faces of S within
 * maxDistance; faces keep their order in every subset, so a face's rank among the others does
 * not change, and the queries read only the points, triangles (in corner order), degenerate
 * faces and vertex normals of the subset. The first S is the base: prepared, its FaceTree
 * built, every vertex queried. A later S whose preparation is the base's restricted to it in
 * all of those (PrepareFaceSubset may differ: the area floor of degenerate faces and the
 * normals' signs come from the subset's own faces) keeps the distance of every vertex whose
 * closest face is still in S (the minimum over fewer faces that still hold it) and of every
 * vertex with none (infinite); the vertices whose closest face left are queried again on the
 * base's FaceTree without the faces that left. An S that does not match becomes the base.
 */
class ShrinkingSubsetDistances
{
public:
  /// `edgeUses`: the mesh's (ComputeFaceEdgeUses), the caller's and outliving this object;
  /// null: made by the first Update.
  ShrinkingSubsetDistances(const PreparedMesh& mesh,
    const Plane& plane,
    double compatibilityAngleDegrees,
    double maxDistance,
    const FaceEdgeUses* edgeUses = nullptr);
  ~ShrinkingSubsetDistances();

  /// Prepares S (faces of the mesh; within the previous S, else it starts over) and the
  /// distances of its vertices. False where PrepareFaceSubset fails.
  bool Update(const std::vector<char>& S);

  /// A preparation of the next S made elsewhere, with its queries: the next update that
  /// starts over uses them instead of a new face tree where they are what it prepares (the
  /// same points, triangles, degenerate faces, face and vertex normals and face centroids:
  /// all that the queries and their face tree read), so the distances are the same bit for
  /// bit; otherwise they are dropped.
  void Adopt(PreparedSubsetQueries prepared) { this->Adopted = std::move(prepared); }

  /// S as PrepareFaceSubset prepares it.
  const PreparedMesh& Subset() const { return this->Current; }
  /// The fine mirror distance of each point of Subset() (infinite beyond maxDistance).
  const std::vector<double>& Distances() const { return this->CurrentDistance; }
  /// Updates that queried every vertex (the first one and those whose S did not match).
  int FullUpdates() const { return this->NumberOfFullUpdates; }
  /// Full updates that used an adopted preparation (Adopt) instead of a new face tree.
  int AdoptedUpdates() const { return this->NumberOfAdoptedUpdates; }

private:
  /// True when Current's points are the mesh's CurrentPoints (same positions) and its faces
  /// CurrentFaces: its ids translate to the mesh's.
  bool NumberedAsMesh() const;
  /// True when Current, in mesh ids, is the base restricted to it (see the class comment) and
  /// within the previous S.
  bool MatchesBase() const;
  /// Current becomes the base: a FaceTree over it and every vertex queried.
  void ComputeAll();
  /// The base's distances for the current S from the previous S's, querying only the
  /// vertices whose closest face left.
  void ComputeChanged();

  const PreparedMesh& Mesh;
  const Plane Mirror;
  const double CompatibilityAngle;
  const double MaxDistance;

  /// The mesh's edge uses (every S is prepared from them): the caller's, or OwnEdgeUses made
  /// by the first Update.
  const FaceEdgeUses* EdgeUses;
  std::unique_ptr<FaceEdgeUses> OwnEdgeUses;
  PreparedMesh Current;
  std::vector<int> CurrentPoints; ///< mesh point id of each point of Current
  std::vector<int> CurrentFaces;  ///< mesh face id of each face of Current
  std::vector<double> CurrentDistance;

  PreparedSubsetQueries Adopted; ///< see Adopt
  std::unique_ptr<PreparedMesh> Base;
  std::unique_ptr<MirrorDistance> BaseQueries; ///< over *Base
  std::vector<int> BasePointOf;                ///< mesh point id -> base point (-1: none)
  std::vector<int> BaseFaceOf;                 ///< mesh face id -> base face (-1: none)
  std::vector<char> BaseFaceInS;               ///< per base face: in the last S
  /// Per base point of the last S: its distance and closest face (base id; -1: none).
  std::vector<double> BaseDistance;
  std::vector<int> BaseClosest;
  int NumberOfFullUpdates = 0;
  int NumberOfAdoptedUpdates = 0;
};
}

#endif
