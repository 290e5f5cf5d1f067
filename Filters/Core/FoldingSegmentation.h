// Per-face labels of the input mesh from a folding tree: the segmentation view of the
// paper's Figures 1 and 4 (which leaf stands for each face, at what depth, in what role).
#ifndef foldingmeshes_FoldingSegmentation_h
#define foldingmeshes_FoldingSegmentation_h

#include "FoldingTree.h"
#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
enum class FoldingFaceRole
{
  Kept = 0,         ///< stored in a leaf
  MirroredAway = 1, ///< removed by a fold; a mirror copy of a stored face stands for it
  Boundary = 2,     ///< stored in a leaf, with a vertex on a segmentation boundary (tear)
  TurnedAway = 3    ///< removed by a rotation node; a turned copy of a stored face stands for it
};

struct FoldingSegmentation
{
  /// Per input face: the node index of the leaf that reproduces it (for mirrored-away faces:
  /// the leaf holding the face whose mirror image it is, followed through nested folds), or
  /// -1 for faces the tree does not represent (dropped degenerate faces, collapsed faces
  /// without a mirror partner).
  std::vector<int> leaf;
  /// Per input face: depth of that leaf for stored faces, depth of the folding node that
  /// removed it for mirrored-away faces; -1 when leaf is -1.
  std::vector<int> depth;
  /// Per input face: a FoldingFaceRole value; -1 when the face is not represented at all.
  std::vector<int> role;
};

/**
 * Labels every face of the input mesh (points/triangles as given to BuildFoldingTree).
 * A face removed by the fold of node n is matched to the face of n's kept half whose
 * centroid is nearest to the mirror image of its centroid; folds are resolved from the
 * deepest up, so a partner removed by a deeper fold already has its leaf. Deterministic.
 */
FoldingSegmentation LabelFacesByLeaf(const FoldingTree& tree,
  const std::vector<Vec3>& points,
  const std::vector<Triangle>& triangles);
}

#endif
