// The builder's proof that unfold(tree) stays within the root epsilon of the input, and where
// it does not (BuildFoldingTree, FoldingTreeOptions::verifyBound).
#ifndef foldingmeshes_FoldingTreeVerification_h
#define foldingmeshes_FoldingTreeVerification_h

#include "ClosestFaceQuery.h"
#include "FoldingTree.h"
#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
class SurfaceDistanceQuery;

/// What VerifyUnfoldedBound found.
struct UnfoldedBoundCheck
{
  bool within = false; ///< every point of both surfaces proved within epsilon (+ tolerance)
  double upper = 0.0;  ///< the proved Hausdorff bound between unfold(tree) and the input
  /// Input faces to pin (sorted ids) where the bound is not proved: the input faces nearest
  /// to the unfolded faces with a point beyond epsilon and the input faces with one, each
  /// with the faces around it (two rings of shared vertices). Empty when `within`.
  std::vector<int> pin;
  /// Edges of unfold(tree) used by one face although the input is closed (the tree lists no
  /// input border edge; points at identical positions counted as one): holes the unfolder
  /// could not close within its tolerance. 0 for an input with a border of its own.
  int openEdges = 0;
  /// Input faces to pin where those edges are (nearest to their end points and midpoints,
  /// two rings around them), sorted; empty when openEdges is 0.
  std::vector<int> pinOpen;
  /// unfold(tree)'s area over the input's (above 1: surface laid twice within epsilon, which
  /// the bound cannot see; docs/limitations.md); 0 for an input of no area.
  double areaRatio = 0.0;
};

/**
 * Unfolds `tree` with the default UnfoldOptions and bounds the symmetric Hausdorff distance
 * between the result and `input` over every point of both surfaces (DirectedHausdorffBounds
 * both ways, deciding epsilon to 1e-7 of the diagonal, as `foldingmeshes roundtrip` does).
 * Where a point is not proved within epsilon, lists the input faces to pin there; where a
 * closed input comes back with open edges, the input faces to pin there too.
 * `queries` (optional): the closest-face queries of the distances (e.g. a VTK cell locator,
 * FoldingTreeOptions::verificationQueries); without it the core's FaceTree. `toInput`
 * (optional, used only without `queries`): distances to `input` through the core's FaceTree
 * already built (the builder's), instead of a new one.
 */
/// The proofs decide epsilon to this share of the diagonal (VerifyUnfoldedBound, and the
/// compact writer's proof of its file).
constexpr double ProofToleranceOfDiagonal = 1e-7;

/// Edges of `mesh` used by one face, points at identical positions counted as one (the
/// unfolder's copies meet at shared positions).
int WeldedOpenEdges(const TriangleMesh& mesh);

UnfoldedBoundCheck VerifyUnfoldedBound(const TriangleMesh& input,
  const FoldingTree& tree,
  const ClosestFaceQueryFactory& queries = nullptr,
  const SurfaceDistanceQuery* toInput = nullptr);
}

#endif
