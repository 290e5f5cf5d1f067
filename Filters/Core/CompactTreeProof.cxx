// The proof of a compact tree file against its mesh (CompactTreeProof.h).
#include "CompactTreeProof.h"

#include "CompactTreeFormat.h"
#include "FoldingTreeUnfolder.h"
#include "FoldingTreeVerification.h"
#include "SurfaceDistance.h"

#include <limits>

namespace foldingmeshes
{
CompactFileProof ProveCompactFile(const std::string& bytes,
  const TriangleMesh& input,
  double tolerance,
  double floor)
{
  CompactFileProof proof;
  proof.bound = std::numeric_limits<double>::infinity();
  FoldingTree tree;
  std::string error;
  UnfoldedMesh unfolded;
  if (!DecodeCompactTree(bytes, tree, error) ||
    !UnfoldFoldingTree(tree, UnfoldOptions(), unfolded, error) || unfolded.triangles.empty())
    return proof;
  const TriangleMesh surface{ unfolded.points, unfolded.triangles };
  proof.bound =
    SymmetricHausdorffBounds(input, surface, tolerance, DefaultMaximumEvaluations, floor).upper;
  proof.openEdges = WeldedOpenEdges(surface);
  return proof;
}
}
