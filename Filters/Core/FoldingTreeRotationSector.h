// The geometry of a rotation node's sector (internal to the builder; the rule that uses it is
// in FoldingTreeRotation.cxx): cylindrical coordinates about the axis, the sector of whole
// faces with its seams made to meet (or its faces cut along the half-planes), and the errors
// its turned copies add.
#ifndef foldingmeshes_FoldingTreeRotationSector_h
#define foldingmeshes_FoldingTreeRotationSector_h

#include "EdgeTable.h"
#include "FoldingWorkMesh.h"
#include "RotationAxis.h"
#include "SurfaceDistance.h"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <vector>

namespace foldingmeshes
{
namespace treebuilder
{
namespace sector
{
constexpr double TwoPi = 2.0 * EIGEN_PI;

/// One order's sector with its seams made to meet (FoldingTreeRotation.cxx, step 3).
struct SectorCut
{
  int order = 0;
  double start = 0.0;
  std::vector<char> keep;     ///< per face
  std::vector<Vec3> points;   ///< the region's points with the seam vertices moved
  std::vector<double> move;   ///< per point: how far it moved
  std::vector<char> seam;     ///< per point: on a seam (or the axis, on a seam)
  double halfPlaneMove = 0.0; ///< the farthest a seam vertex lies from its half-plane
};

/// CutSector's reasons that the planning compares (the others are only reported).
extern const char* const NotCoveredOnce;
extern const char* const NoSector;
extern const char* const TooManyPieces;

/// a in [0, m).
double Modulo(double a, double m);

/// The faces of w that the axis passes through cut at the point where it does (see the
/// definition: a face's inside, or an edge and its two faces; not next to a pole).
WorkMesh SplitAtAxis(const AxisFrame& frame, const WorkMesh& w, double tiny);

/// The faces of w cut along both half-planes of the sector [start, start + width), after
/// the faces the axis passes through are cut at the axis (SplitAtAxis); the pieces keep their
/// input face. `tiny`: crossings this close to an end or an edge use it.
WorkMesh SplitAtHalfPlanes(const AxisFrame& frame,
  const WorkMesh& w,
  double start,
  double width,
  double tiny);

/// Why order k has no sector here (nullptr: it has, in `cut`).
const char* CutSector(const AxisFrame& frame,
  const WorkMesh& w,
  const EdgeTable& edges,
  int k,
  double snap,
  double offAxis,
  SectorCut& cut,
  double start = std::numeric_limits<double>::quiet_NaN(),
  int regionFaces = -1);

/// The error check (FoldingTreeRotation.cxx, step 4); fills the per-point charge (kept points) and
/// returns whether every distance is within `limit` and every charge within its point's budget
/// (`worst`: the largest distance measured). `failedStage` (optional): 0 passed; else what
/// failed: 1 the kept points turned, 2 the moved faces' samples, 3 the removed points and
/// faces turned back, 4 a budget.
bool ChargeTurns(const AxisFrame& frame,
  const WorkMesh& w,
  const SurfaceDistanceQuery& toRegion,
  const SectorCut& cut,
  double limit,
  std::vector<double>& charge,
  double& worst,
  int* failedStage = nullptr);

/**
 * The faces of `region` (per face of w) whose vertices and centroid, turned by every j 360/k
 * (j = 1 .. k - 1; above order 16 by 360/k and floor(k/2) 360/k, the detector's test turns:
 * ChargeTurns then checks every turn), lie within eps of a face of the region: the part of a
 * rotational region that the turns map onto itself (the detector's region is ragged where it
 * meets asymmetric parts). `strict`: and no nearer to a face of w outside the region than to
 * the region (a tie, e.g. a turned vertex on the region's border, counts as on it): a region
 * that stays clear of its asymmetric surroundings, smaller, whose sector keeps the bound more
 * often. Three passes of removal at most (the region shrinks with each; it is closed under
 * the turns checked when a pass drops nothing, e.g. after one pass when the turns land clear
 * of the region's border).
 */
std::vector<char> InvariantRegion(const WorkMesh& w,
  std::vector<char> region,
  const RotationAxis& axis,
  int k,
  double eps,
  bool strict);
}
}
}

#endif
