// Unfolder: removal of the vertices the builder projected onto a fold plane (after the
// reflection at that folding node; their copies mirrored off that plane after the stitching
// at a segmentation node above), so the strip across the fold line comes back with about
// the input's tessellation. See UnfoldOptions::removeProjectedPoints.
#include "FoldingTreeUnfolderInternal.h"
#include "FoldingTreeUnfolderVertexRemoval.h"
#include "Trace.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace foldingmeshes
{
namespace unfolder_detail
{
int Unfolder::RemoveProjectedPoints(const FoldingNode* node, Piece& piece, std::vector<char>* added)
{
  const bool atFold = node && node->kind == FoldingNodeKind::Folding;
  const uint64_t bit = node ? uint64_t(1) << node->depth : 0;
  const uint64_t above = bit - 1;
  const int n = piece.NumberOfPoints();
  // Rounding slack for points whose budget is used up: a star that is planar to this
  // precision is replaced by a triangulation of the same polygon.
  VertexRemover remover(piece, this->Options.planeTolerance * this->Tree.diagonal);
  // The limit without budgets (respectErrorBudget off, older trees): the node's epsilon;
  // after the traversal, that of the folds below the root.
  const double fallback = node ? node->epsilon : 0.5 * this->Tree.rootEpsilon;
  const bool debug = static_cast<bool>(this->Options.trace);
  std::map<std::string, int> reasons;
  RingRemoval removal;
  const char* why = "";
  for (int v = 0; v < n; ++v)
  {
    if (!piece.projected[v] || (atFold && !(piece.onPlane[v] & bit)))
      continue;
    // After the stitching at a segmentation node: copies that the reflection at a fold below
    // moved off the fold line they were projected onto (on no fold plane). No fold tries
    // them, so the thinning at the folds above would count them as still to go, while the
    // final pass finds their budgets spent by then (nested folds through one axis: the
    // queen's copies on the seams between its sectors). Those a fold kept for tear flags
    // stay for the final pass, as do those it could not remove.
    if (node && !atFold &&
      (piece.projected[v] != 1 || piece.onPlane[v] != 0 || !piece.tear[v].empty()))
      continue;
    // At a fold: projected onto its plane and onto no plane of a fold above (whose fold line
    // it helps close), no pending tear or fold-line flag (the stitching above needs them).
    // Always: not on the input's border.
    const char* keep = piece.border[v] == 1 ? "border"
      : !atFold                             ? nullptr
      : (piece.onPlane[v] & above)          ? "plane above"
      : !piece.tear[v].empty()              ? "tear"
                                            : nullptr;
    if (keep)
    {
      if (debug)
        ++reasons[keep];
      continue;
    }
    // At a segmentation node a ring still open (a gap the stitching above, the weld or the
    // repair may close) leaves the point to go later, as the thinning above expects.
    if (node && !atFold && !remover.Interior(v))
    {
      if (debug)
        ++reasons["open ring, later"];
      continue;
    }
    // Failed: the thinning above no longer counts it; the final pass tries it again.
    if (!remover.Try(v, remover.Limit(v, fallback), RingRules(), removal, why))
    {
      if (node)
        piece.projected[v] = 2;
      if (debug)
        ++reasons[why];
      continue;
    }
    remover.Apply(removal);
  }
  if (debug)
  {
    std::string line = FormatTrace("[projected] %s %d: removed %d",
      atFold   ? "fold at depth"
        : node ? "seams at depth"
               : "final pass, points",
      node ? node->depth : n,
      remover.Count());
    for (const auto& r : reasons)
      line += FormatTrace(", %s %d", r.first.c_str(), r.second);
    this->Options.trace(line);
  }
  return remover.Compact(added);
}
} // namespace unfolder_detail
} // namespace foldingmeshes
