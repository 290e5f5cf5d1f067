// The error a fold may add at each point of a region that shrinks (Builder::Trim's budgets).
#ifndef foldingmeshes_ShrinkingMirrorBudget_h
#define foldingmeshes_ShrinkingMirrorBudget_h

#include "Plane.h"
#include "PointKdTree.h"

#include <memory>
#include <vector>

namespace foldingmeshes
{
/**
 * For the points `ids` of a region (indices into `points`, each with what is left of its error
 * budget): the error a fold through `plane` may add at each - the least of eps, its own budget
 * and the budget of its partner, the point of `ids` nearest to its mirror image within eps (a
 * copy made by the fold lands there), or without a partner the least budget of `ids`.
 *
 * Builder::Trim asks again and again with one plane while the region shrinks. A partner is the
 * lowest (distance, id) among the points within eps (PointKdTree::NearestWithin), so it stays
 * the partner while it stays in the region, and a point without one never gets one; only the
 * points whose partner left are looked up again, in the first region's tree restricted to the
 * current points. The limits are bit for bit those of a fresh search over each region. A region
 * that is not a subset of the previous one starts over.
 */
class ShrinkingMirrorBudget
{
public:
  /// Keeps references to points and budget.
  ShrinkingMirrorBudget(const std::vector<Vec3>& points,
    const std::vector<double>& budget,
    const Plane& plane,
    double eps);

  /// The limit of each point of `ids` (increasing indices into points).
  std::vector<double> Limits(const std::vector<int>& ids);

private:
  /// A tree over `ids` and every partner looked up.
  void Start(const std::vector<int>& ids);
  /// True when every point of `ids` was in the previous region.
  bool Shrinks(const std::vector<int>& ids) const;
  /// Region := ids; new partners for the points whose partner left it.
  void Shrink(const std::vector<int>& ids);
  /// The point of the current region nearest to the mirror image of v within eps (-1: none).
  int PartnerInRegion(int v) const;

  const std::vector<Vec3>& Points;
  const std::vector<double>& Budget;
  const Plane Mirror;
  const double Eps;
  std::unique_ptr<PointKdTree> Search; ///< over the region of the last Start
  std::vector<int> Region;             ///< the current points
  std::vector<char> InRegion;
  std::vector<int> Partner; ///< per point of Region (-1: none)
};
}

#endif
