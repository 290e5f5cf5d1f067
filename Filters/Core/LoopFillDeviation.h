// Proved distance between the fill of a boundary loop and the loop.
#ifndef foldingmeshes_LoopFillDeviation_h
#define foldingmeshes_LoopFillDeviation_h

#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
/**
 * An upper bound on sup over every point x of the triangles `from` (indices into `points`) of
 * the distance from x to the closed polyline `loop` (its last point joins the first): how far
 * the fill of a boundary loop reaches from the loop's edges. Proved by subdividing each
 * triangle into pieces: a piece with centroid c, closest to segment e of the loop, and corners
 * within r of c is within min(dist(c) + r, max over its corners of dist(corner, e)) of the
 * loop (the distance is 1-Lipschitz, and the distance to one segment is convex). Pieces are
 * split in four while their bound exceeds `limit`. Returns the largest bound of the settled
 * pieces (<= limit), or infinity when a measured point is farther than `limit` or
 * `maximumPieces` pieces did not settle it (then the fill is not proved within the limit).
 * Brute force over the loop's edges: for the small loops the unfolder fills.
 */
double ProvedLoopDeviation(const std::vector<Vec3>& points,
  const std::vector<Triangle>& from,
  const std::vector<int>& loop,
  double limit,
  int maximumPieces = 4096);
}

#endif
