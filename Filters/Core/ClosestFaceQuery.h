// The closest-face query of SurfaceDistanceQuery as an interface, so that the VTK layer can
// answer it with a cell locator (vtkStaticCellLocator by default, see vtkCellLocatorFaceQuery)
// while the core keeps no VTK data-model types. The core's own answer is FaceTree.
#ifndef foldingmeshes_ClosestFaceQuery_h
#define foldingmeshes_ClosestFaceQuery_h

#include "TriangleMesh.h"

#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace foldingmeshes
{
struct ClosestFaceHit
{
  int face = -1; ///< -1: no triangle
  double distance = std::numeric_limits<double>::infinity();
  Vec3 point = Vec3::Zero(); ///< the closest point of that triangle
};

/**
 * Closest triangle of a fixed surface to a point. A triangle whose corners are collinear or
 * coincide is measured as its edges (as SurfaceDistance.h defines the distance). Must be safe
 * to call from several threads at once.
 */
class ClosestFaceQuery
{
public:
  virtual ~ClosestFaceQuery() = default;
  virtual ClosestFaceHit Closest(const Vec3& p) const = 0;
  /// The closest triangle nearer than `radius` (none: face -1). By default Closest, cut off.
  virtual ClosestFaceHit ClosestWithin(const Vec3& p, double radius) const
  {
    const ClosestFaceHit hit = this->Closest(p);
    return hit.distance < radius ? hit : ClosestFaceHit();
  }
};

/// Makes a query over the triangles of `surface` (called once per surface).
using ClosestFaceQueryFactory =
  std::function<std::unique_ptr<ClosestFaceQuery>(const TriangleMesh& surface)>;
}

#endif
