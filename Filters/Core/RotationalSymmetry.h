// Rotational symmetry detection: an axis and an order k such that turning the mesh by 360/k
// degrees about the axis maps a region of it onto itself within epsilon (issue 22, the
// paper's future work "axial symmetries").
#ifndef foldingmeshes_RotationalSymmetry_h
#define foldingmeshes_RotationalSymmetry_h

#include "FaceTree.h"
#include "Plane.h"
#include "RotationAxis.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace foldingmeshes
{
/// The largest order the detector tries by default (RotationOptions::maximumOrder).
constexpr int DefaultMaximumRotationOrder = 64;

struct RotationOptions
{
  double epsilon = 0.0;                           ///< tolerance as a length (required, > 0)
  int maximumOrder = DefaultMaximumRotationOrder; ///< orders 2 .. this are tried (2 .. 360)
  /// Axes whose best order is below this are left out (2: none). An axis keeps only orders
  /// whose area is at least 0.9 times its best order's, so an axis of order 2 over the whole
  /// surface yields nothing: a caller that has no use for order 2 (the builder, where a
  /// mirror fold covers the whole region) skips its fits.
  int minimumOrder = 2;
  double compatibilityAngle = 45.0;
  double minimumSymmetricAreaFraction = 0.1;
  /// Mirror planes already found (e.g. SymmetryResult::finalists): two of them at an angle
  /// meet in a line that is a candidate axis (two mirror planes at pi/k meet in a k-fold
  /// axis). The surface's principal axes through its area centroid are always candidates.
  std::vector<Plane> mirrorPlanes;
  int maximumIterations = 30; ///< Gauss-Newton steps of the axis fit
  /// Rank the scanned axes by the area their order maps onto itself (ties within 2% of the
  /// area: the higher order) instead of by the faces a fold would save (area * (1 - 1/k)): a
  /// caller that needs the whole region symmetric (the builder's rotation nodes) wants the
  /// axis of the largest region, not a high order on part of it.
  bool rankByArea = false;
  /// Called with progress in [0,1] after the scan of each pair of candidate axes and each
  /// fit; return false to abort (RotationResult::aborted, order 0).
  std::function<bool(double)> progress;
};

struct RotationResult
{
  bool found = false;   ///< the rule of DetectRotationalSymmetry holds
  bool aborted = false; ///< the progress callback asked to stop
  int order = 0;        ///< k (0: no candidate axis had any order)
  RotationAxis axis;
  /// Every order 2 .. maximumOrder passed the scan on the best axis: a surface of
  /// revolution within epsilon (order is then maximumOrder).
  bool continuous = false;
  /// Per vertex: the larger of the distances of its images under the two tested turns
  /// (360/k and the turn of floor(k/2) sectors) to the closest compatible face; infinite
  /// beyond 3 epsilon.
  std::vector<double> distance;
  std::vector<char> faceLabel; ///< 1: in the rotational region, 0: outside
  double symmetricAreaFraction = 0.0;
  double rmsResidual = 0.0; ///< area-weighted RMS of distance over the region
  int candidateAxes = 0;    ///< distinct candidate axes scanned
  int iterations = 0;       ///< Gauss-Newton steps of the winner
};

/**
 * Finds the axis and the largest order k (2 <= k <= maximumOrder) of a rotational symmetry
 * of `mesh` within epsilon:
 * 1. candidate axes: the principal axes of the surface through its area centroid, and the
 *    lines where two of options.mirrorPlanes meet (at 2 to 90 degrees);
 * 2. scan: on a fixed sample of vertices, for each axis and order, the turns by 360/k and by
 *    floor(k/2) * 360/k (so that a near-identity turn cannot pass alone) each map at least
 *    minimumSymmetricAreaFraction of the sample's vertex area within 2 epsilon of a
 *    compatible face (normal within compatibilityAngle of the turned vertex normal);
 * 3. the best candidate (largest order, then the larger passing area) is refined by
 *    Gauss-Newton on the axis (point-to-tangent-plane distances of the turned vertices,
 *    Geman-McClure weights with sigma = 3 epsilon, then epsilon), the turn angles fixed;
 * 4. on the whole mesh: the region is the faces whose vertices all map within epsilon
 *    under both turns. found: its area is at least minimumSymmetricAreaFraction of the
 *    mesh and its area-weighted RMS distance at most FoundResidualRatio epsilon.
 * If the best candidate fails the rule after refinement, the next two are tried.
 * Deterministic: no randomness; parallel queries write disjoint results.
 * `meshFaces`: a FaceTree of `mesh` the caller already has (else one is built).
 */
RotationResult DetectRotationalSymmetry(const PreparedMesh& mesh,
  const RotationOptions& options,
  const FaceTree* meshFaces = nullptr);
}

#endif
