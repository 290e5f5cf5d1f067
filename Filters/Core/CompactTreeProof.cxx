// The proof of a compact tree file against its mesh (CompactTreeProof.h).
#include "CompactTreeProof.h"

#include "CompactTreeFormat.h"
#include "FoldingTreeUnfolder.h"
#include "SurfaceDistance.h"

#include <limits>

namespace foldingmeshes
{
double ProvedCompactFileBound(const std::string& bytes,
  const TriangleMesh& input,
  double tolerance,
  double floor)
{
  FoldingTree tree;
  std::string error;
  UnfoldedMesh unfolded;
  if (!DecodeCompactTree(bytes, tree, error) ||
    !UnfoldFoldingTree(tree, UnfoldOptions(), unfolded, error) || unfolded.triangles.empty())
    return std::numeric_limits<double>::infinity();
  const TriangleMesh surface{ unfolded.points, unfolded.triangles };
  return SymmetricHausdorffBounds(input, surface, tolerance, DefaultMaximumEvaluations, floor)
    .upper;
}
}
