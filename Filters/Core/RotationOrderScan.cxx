#include "RotationOrderScan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace foldingmeshes
{
namespace rotation_detail
{
namespace
{
/// The scan counts a turned vertex when it lands within this many epsilon of a compatible
/// face (looser than the final epsilon: the candidate axes are not refined yet).
constexpr double ScanToleranceRatio = 2.0;
/// An order is kept when its passing area is at least this fraction of the best order's on
/// the same axis: a k-fold part passes every divisor of k with the same area, while a flat
/// face across the axis lets any turn pass on part of it (a box turned by 5 degrees keeps its
/// top and bottom, not its sides).
constexpr double OrderAreaRatio = 0.9;
/// Turns of an order tried by the scan (the spread ones first; all of them up to order 13).
constexpr int SpreadTurnsTried = 12;
/// Turns of a prime order tried for the scan's largest area (an estimate from above).
constexpr int PrimeTurnsTried = 6;

/**
 * The passing areas of turns about one axis on the scan's sample, memoised per turn. A
 * turn's area is computed only as far as a caller's threshold needs: once the vertices left
 * cannot lift it to the threshold, it is known to be below (a lower bound on the failures).
 */
class TurnAreas
{
public:
  TurnAreas(const PreparedMesh& mesh,
    const FaceTree& faces,
    const RotationOptions& options,
    const std::vector<int>& sample,
    const RotationAxis& axis)
    : Mesh(mesh)
    , Faces(faces)
    , Sample(sample)
    , Axis(axis)
    , CosLimit(std::cos(options.compatibilityAngle * Pi / 180.0))
    , Tolerance(ScanToleranceRatio * options.epsilon)
  {
    for (int v : sample)
      this->SampleArea += mesh.vertexAreas[v];
  }

  /// The passing area of turn t as a fraction of the sample's area when it is at least
  /// `threshold`; else some value below the threshold.
  double Area(const Turn& t, double threshold)
  {
    Known& k = this->Memo[t];
    if (k.exact || (k.below && k.threshold <= threshold))
      return k.value;
    const AxisTurn turn(this->Axis, t.Angle());
    const double needed = threshold * this->SampleArea;
    double passed = 0.0, left = this->SampleArea;
    for (int v : this->Sample)
    {
      const double a = this->Mesh.vertexAreas[v];
      left -= a;
      if (TurnedHasPartner(this->Mesh, this->Faces, turn, v, this->CosLimit, this->Tolerance))
        passed += a;
      if (passed + left < needed)
      {
        k = { false, true, threshold, (passed + left) / this->SampleArea };
        return k.value;
      }
    }
    k = { true, false, threshold, this->SampleArea > 0.0 ? passed / this->SampleArea : 0.0 };
    return k.value;
  }

  /**
   * The area of order k (the smallest over its turns j/k, j = 1..k-1) when every turn keeps
   * at least `threshold`; else a value below it. The turns are tried in an order that spreads
   * them around the circle, and at most `maximumTurns` of them: an order m k0 that is not a
   * symmetry (the true order k0) fails on (m - 1) / m >= 1/2 of its turns, so it fails within
   * a few.
   */
  double OrderArea(int k, double threshold, int maximumTurns = SpreadTurnsTried)
  {
    double area = 1.0;
    const std::vector<int> spread = SpreadTurns(k);
    for (size_t i = 0; i < spread.size() && i < static_cast<size_t>(maximumTurns); ++i)
    {
      const int j = spread[i];
      area = std::min(area, this->Area(Reduced(j, k), threshold));
      if (area < threshold)
        break;
    }
    return area;
  }

private:
  /// 1..k-1 in the order of the golden-ratio sequence (half turn first), each once.
  static std::vector<int> SpreadTurns(int k)
  {
    std::vector<int> order;
    std::vector<char> taken(k, 0);
    const double golden = 0.6180339887498949;
    double x = 0.5;
    for (int i = 0; i < 4 * k && static_cast<int>(order.size()) < k - 1; ++i)
    {
      const int j = std::clamp(static_cast<int>(std::lround(x * k)), 1, k - 1);
      if (!taken[j])
      {
        taken[j] = 1;
        order.push_back(j);
      }
      x = std::fmod(x + golden, 1.0);
    }
    for (int j = 1; j < k; ++j)
      if (!taken[j])
        order.push_back(j);
    return order;
  }

  struct Known
  {
    bool exact = false; ///< value is the area
    bool below = false; ///< the area is below `threshold` (value: an upper bound)
    double threshold = 0.0;
    double value = 0.0;
  };
  const PreparedMesh& Mesh;
  const FaceTree& Faces;
  const std::vector<int>& Sample;
  const RotationAxis Axis;
  const double CosLimit, Tolerance;
  double SampleArea = 0.0;
  std::map<Turn, Known> Memo;
};

/// Whether n is prime (n >= 2).
bool IsPrime(int n)
{
  for (int d = 2; d * d <= n; ++d)
    if (n % d == 0)
      return false;
  return n >= 2;
}

}

Turn Reduced(int num, int den)
{
  const int g = std::gcd(num, den);
  return { num / g, den / g };
}

std::vector<Turn> TurnsOfOrder(int k)
{
  std::vector<Turn> turns{ Reduced(1, k) };
  const Turn far = Reduced(k / 2, k);
  if (far.num != turns[0].num || far.den != turns[0].den)
    turns.push_back(far);
  return turns;
}

std::vector<int> SampleVertices(const PreparedMesh& mesh, int count)
{
  std::vector<int> used;
  for (int v = 0; v < mesh.NumberOfPoints(); ++v)
    if (mesh.vertexAreas[v] > 0.0)
      used.push_back(v);
  if (static_cast<int>(used.size()) <= count)
    return used;
  std::vector<int> sample;
  sample.reserve(count);
  const double stride = static_cast<double>(used.size()) / count;
  for (int s = 0; s < count; ++s)
    sample.push_back(used[static_cast<size_t>(s * stride)]);
  return sample;
}

FaceTree::Hit TurnedHit(const PreparedMesh& mesh,
  const FaceTree& faces,
  const AxisTurn& turn,
  int v,
  double cosLimit,
  double maxDistance,
  int hint)
{
  return faces.ClosestCompatibleFace(
    turn.Point(mesh.points[v]), turn.Direction(mesh.vertexNormals[v]), cosLimit, maxDistance, hint);
}

bool TurnedHasPartner(const PreparedMesh& mesh,
  const FaceTree& faces,
  const AxisTurn& turn,
  int v,
  double cosLimit,
  double maxDistance)
{
  return faces.HasCompatibleFaceWithin(
    turn.Point(mesh.points[v]), turn.Direction(mesh.vertexNormals[v]), cosLimit, maxDistance);
}

ScanEntry ScanAxis(const PreparedMesh& mesh,
  const FaceTree& faces,
  const RotationOptions& options,
  const std::vector<int>& sample,
  int axisIndex,
  const RotationAxis& axis)
{
  TurnAreas areas(mesh, faces, options, sample, axis);
  double best = 0.0;
  for (int p = 2; p <= options.maximumOrder; ++p)
    if (IsPrime(p))
    {
      const double a =
        areas.OrderArea(p, std::max(best, options.minimumSymmetricAreaFraction), PrimeTurnsTried);
      best = std::max(best, a);
    }
  ScanEntry entry;
  entry.axis = axisIndex;
  const double threshold = std::max(options.minimumSymmetricAreaFraction, OrderAreaRatio * best);
  if (best < options.minimumSymmetricAreaFraction)
    return entry;
  for (int k = options.maximumOrder; k >= std::max(2, options.minimumOrder) &&
       entry.orders.size() < static_cast<size_t>(RefinedOrders);
       --k)
  {
    if (!entry.orders.empty() && entry.order % k != 0)
      continue;
    const double a = areas.OrderArea(k, threshold);
    if (a < threshold)
      continue;
    if (entry.orders.empty())
    {
      entry.order = k;
      entry.area = a;
    }
    entry.orders.push_back(k);
  }
  entry.continuous = entry.order == options.maximumOrder && entry.order > 2 &&
    areas.OrderArea(entry.order - 1, threshold) >= threshold;
  return entry;
}
}
}
