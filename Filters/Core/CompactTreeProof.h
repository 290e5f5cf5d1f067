// The proof of a compact tree file against the mesh it was folded from: its unfold's distance
// to the mesh, over every point of both surfaces. The builder proves its tree in memory, and
// a compact file takes its quantisation error out of the points' budgets, but some unfolder
// steps do not answer to the budgets when positions move (fewer seam vertices pair, larger
// loops are filled or faces dropped by the final repair): the bearing moved rigidly came back
// 1.02 epsilon from its input at 8 bits (docs/limitations.md). vtkFoldingTreeCompactWriter
// proves its file with it where it is given the mesh, and writes it again with more bits.
#ifndef foldingmeshes_CompactTreeProof_h
#define foldingmeshes_CompactTreeProof_h

#include "TriangleMesh.h"

#include <string>

namespace foldingmeshes
{
/// What ProveCompactFile found.
struct CompactFileProof
{
  /// The proved symmetric Hausdorff bound between the file's unfold and the input, decided
  /// against the floor; infinite when the file does not decode or unfold.
  double bound = 0.0;
  /// Edges of the file's unfold used by one face (WeldedOpenEdges); -1 when it did not unfold.
  int openEdges = -1;
};

/**
 * The file `bytes` decoded (DecodeCompactTree), unfolded with the default UnfoldOptions and
 * bounded against `input` (SymmetricHausdorffBounds, to `tolerance`, decided against `floor`:
 * the upper bound is at most floor + tolerance when the distance is proved within floor), and
 * its open edges counted (a closed input should come back closed, as the builder's proof asks).
 */
CompactFileProof ProveCompactFile(const std::string& bytes,
  const TriangleMesh& input,
  double tolerance,
  double floor);
}

#endif
