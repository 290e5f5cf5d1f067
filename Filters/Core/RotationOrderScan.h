// Internals of the rotational symmetry detection (RotationalSymmetry.h): turns about an
// axis, the vertex samples, and the scan that finds an axis' largest order.
#ifndef foldingmeshes_RotationOrderScan_h
#define foldingmeshes_RotationOrderScan_h

#include "FaceTree.h"
#include "RotationalSymmetry.h"

#include <vector>

namespace foldingmeshes
{
namespace rotation_detail
{
constexpr double Pi = 3.14159265358979323846;
/// Orders the scan hands on per axis (the largest, then its divisors that passed too).
constexpr int RefinedOrders = 4;

/// A turn as a fraction num/den of a full turn, in lowest terms.
struct Turn
{
  int num = 0, den = 1;
  double Angle() const { return 2.0 * Pi * num / den; }
  bool operator<(const Turn& o) const { return num * o.den < o.num * den; }
};

Turn Reduced(int num, int den);

/// The two turns tested for order k: one sector, and floor(k/2) sectors (the half turn for
/// even k), so that a near-identity turn cannot pass alone.
std::vector<Turn> TurnsOfOrder(int k);

/// Vertices with area (used by a non-degenerate face), about `count` of them, evenly spread.
std::vector<int> SampleVertices(const PreparedMesh& mesh, int count);

/// Closest compatible face of the turned vertex v (its normal turned too), within maxDistance.
FaceTree::Hit TurnedHit(const PreparedMesh& mesh,
  const FaceTree& faces,
  const AxisTurn& turn,
  int v,
  double cosLimit,
  double maxDistance,
  int hint = -1);

/// TurnedHit(...).face >= 0, sooner: whether the turned vertex v has a compatible face within
/// maxDistance (FaceTree::HasCompatibleFaceWithin).
bool TurnedHasPartner(const PreparedMesh& mesh,
  const FaceTree& faces,
  const AxisTurn& turn,
  int v,
  double cosLimit,
  double maxDistance);

/// One scanned (axis, order): the smallest passing area of its turns, as a fraction of the
/// sample's vertex area.
struct ScanEntry
{
  int axis = -1;
  int order = 0;
  double area = 0.0;
  bool continuous = false;
  /// The orders that passed and divide the largest, largest first (order is the first; at
  /// most RefinedOrders): a multiple of the true order may pass at the scan's looser
  /// tolerance and fail at epsilon.
  std::vector<int> orders;
  /// Faces the fold would save on the sample: area * (1 - 1/order).
  double Saved() const { return this->area * (1.0 - 1.0 / this->order); }
};

/**
 * The best order of one axis (index axisIndex among the candidates) on the vertex sample,
 * or order 0. Every order k >= 2 has a prime divisor p whose turns are among k's, so the
 * largest area of any order is that of a prime (each prime's estimated from its first few
 * spread turns, so from above): the threshold is 0.9 times it (at least
 * minimumSymmetricAreaFraction). The largest order whose turns (12 of them, spread around
 * the circle) keep the threshold wins; continuous when the cap and the cap - 1 both do
 * (their turns together are 1 / (cap (cap - 1)) of a turn apart).
 */
ScanEntry ScanAxis(const PreparedMesh& mesh,
  const FaceTree& faces,
  const RotationOptions& options,
  const std::vector<int>& sample,
  int axisIndex,
  const RotationAxis& axis);
}
}

#endif
