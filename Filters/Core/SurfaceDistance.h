// Distances between triangle surfaces: point-to-surface distances and the symmetric Hausdorff
// distance, the project's one measure of how far an unfolded mesh is from its original.
#ifndef foldingmeshes_SurfaceDistance_h
#define foldingmeshes_SurfaceDistance_h

#include "ClosestFaceQuery.h"
#include "TriangleMesh.h"

#include <memory>
#include <vector>

namespace foldingmeshes
{
class FaceTree;

/**
 * Exact closest-point queries against one triangle surface (a FaceTree over all its
 * triangles; degenerate ones count as their edges). The surface is copied. Queries are const
 * and thread-safe.
 */
class SurfaceDistanceQuery
{
public:
  /// With `factory`, the closest-face queries (Distance, Distances, Closest) go through the
  /// query it makes (e.g. a VTK cell locator), asked within a radius the core's FaceTree bounds
  /// (the tree is built either way: about 250 bytes a face); without it, through the tree.
  explicit SurfaceDistanceQuery(
    const TriangleMesh& surface, const ClosestFaceQueryFactory& factory = nullptr);
  ~SurfaceDistanceQuery();
  SurfaceDistanceQuery(const SurfaceDistanceQuery&) = delete;
  SurfaceDistanceQuery& operator=(const SurfaceDistanceQuery&) = delete;

  /// Distance from p to the surface (infinity for a surface without triangles).
  double Distance(const Vec3& p) const;
  /// Distances of all `points`, in parallel (vtkSMPTools; the result does not depend on it).
  std::vector<double> Distances(const std::vector<Vec3>& points) const;
  /// Distances and the closest triangles (ties: lowest id; -1 for no triangle), in parallel.
  void Closest(const std::vector<Vec3>& points,
    std::vector<double>& distances,
    std::vector<int>& faces) const;
  /// Distance from p to triangle `face` of the surface.
  double FaceDistance(const Vec3& p, int face) const;
  /// The surface's points and triangles (the copy the queries use).
  const std::vector<Vec3>& Points() const;
  const std::vector<Triangle>& Triangles() const;

private:
  struct Internal;
  std::unique_ptr<Internal> Impl;
};

/**
 * Sample points of a surface at which distances are measured: its vertices used by a
 * triangle, then the centroid of every triangle.
 */
std::vector<Vec3> SurfaceSamplePoints(const TriangleMesh& mesh);

/// The distances between two surfaces, both ways.
struct SurfaceComparison
{
  /// Distance of every point of a (b) to surface b (a); unused points get 0.
  std::vector<double> aPointDistances, bPointDistances;
  double aToB = 0.0;      ///< largest distance of a sample of a to b
  double bToA = 0.0;      ///< largest distance of a sample of b to a
  double hausdorff = 0.0; ///< max(aToB, bToA): the symmetric Hausdorff distance, sampled
  double mean = 0.0;      ///< mean distance over the samples of both surfaces
  int samples = 0;        ///< number of samples (both surfaces)
};

/**
 * Compares two triangle surfaces. Distances are exact point-to-surface distances, sampled at
 * the vertices and triangle centroids of both surfaces (SurfaceSamplePoints): the symmetric
 * Hausdorff distance is the largest of them (a lower bound of the true one, which it equals
 * where the farthest point is a vertex - as for meshes that differ by moved vertices), the
 * mean distance their mean. Empty surfaces give infinite distances (0 when both are empty).
 * Deterministic.
 */
SurfaceComparison CompareSurfaces(const TriangleMesh& a,
  const TriangleMesh& b,
  const ClosestFaceQueryFactory& factory = nullptr);

/// Bounds on a Hausdorff distance over whole surfaces (see DirectedHausdorffBounds).
struct HausdorffBounds
{
  double lower = 0.0;        ///< a distance measured at a point of the surface
  double upper = 0.0;        ///< proved: no point of the surface is farther
  long long evaluations = 0; ///< point-to-surface distances computed
  /// upper - lower is within the tolerance (or upper within floor + tolerance); false: the
  /// evaluation budget ran out first, `upper` is still proved but looser.
  bool converged = true;
};

/// Evaluation budget of one direction of the bounds below.
constexpr long long DefaultMaximumEvaluations = 50000000;

/**
 * The directed Hausdorff distance sup over every point x of every triangle of `from` (not
 * only sample points) of dist(x, to), bracketed: `lower` is the largest distance measured (at
 * the vertices, the triangle centroids and the points of the subdivision below), `upper` a
 * proof. On a (sub)triangle P with centroid c and corners v_i within r of c, two bounds hold:
 * dist(x, to) <= dist(c) + r (the distance is 1-Lipschitz), and dist(x, to) <= dist(x, T)
 * <= max_i dist(v_i, T) for T the triangle of `to` closest to c (the distance to one
 * triangle is convex) - the second is exact where P lies over a single flat triangle. Where
 * P reaches over an edge of T, for each triangle U across it (vertices matched by position):
 * a plane through the edge (bisecting the angle of T and U) splits P in two convex parts,
 * T bounds the one on its side and U the other, each by its largest value at the part's
 * corners - exact where P lies over two flat triangles, so a piece crossing an edge of `to`
 * at distance 0 needs no splitting down to the tolerance (only pieces at a vertex of `to`
 * do: a few per level). Branch and bound: the piece with the largest bound is split into
 * four at its edge midpoints (in batches, the distances in parallel), until upper - lower <=
 * tolerance or maxEvaluations distances were computed (then `upper` is still a bound, only
 * looser, and `converged` false). Memory: the pieces still above the stop level, fewer than
 * maxEvaluations / 2. An empty `from` gives 0; an empty `to` infinity. Deterministic, for
 * any thread count.
 * With `unproved`: filled with the triangles of `from` (sorted ids) that hold a point not
 * proved within floor + tolerance of `to` (a piece whose final bound is above it) - where the
 * distance exceeds floor, or may (the evaluation budget ran out); empty when upper <= floor +
 * tolerance.
 */
HausdorffBounds DirectedHausdorffBounds(const TriangleMesh& from,
  const SurfaceDistanceQuery& to,
  double tolerance,
  long long maxEvaluations = DefaultMaximumEvaluations,
  double floor = 0.0,
  std::vector<int>* unproved = nullptr);

/**
 * Both ways: lower = max of the two lowers, upper = max of the two uppers (the symmetric
 * Hausdorff distance between the two surfaces lies in [lower, upper]), converged if both are. `floor` (both
 * functions): pieces are split only while their bound exceeds max(lower, floor) + tolerance,
 * so with floor = a threshold t the bounds decide quickly whether the distance is within t
 * (upper <= t + tolerance) or not (lower > t); below t they are then not tight.
 */
HausdorffBounds SymmetricHausdorffBounds(const TriangleMesh& a,
  const TriangleMesh& b,
  double tolerance,
  long long maxEvaluations = DefaultMaximumEvaluations,
  double floor = 0.0,
  const ClosestFaceQueryFactory& factory = nullptr);
}

#endif
