// Distances between triangle surfaces: point-to-surface distances and the symmetric Hausdorff
// distance, the project's one measure of how far an unfolded mesh is from its original.
#ifndef foldingmeshes_SurfaceDistance_h
#define foldingmeshes_SurfaceDistance_h

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
  explicit SurfaceDistanceQuery(const TriangleMesh& surface);
  ~SurfaceDistanceQuery();
  SurfaceDistanceQuery(const SurfaceDistanceQuery&) = delete;
  SurfaceDistanceQuery& operator=(const SurfaceDistanceQuery&) = delete;

  /// Distance from p to the surface (infinity for a surface without triangles).
  double Distance(const Vec3& p) const;
  /// Distances of all `points`, in parallel (vtkSMPTools; the result does not depend on it).
  std::vector<double> Distances(const std::vector<Vec3>& points) const;

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
SurfaceComparison CompareSurfaces(const TriangleMesh& a, const TriangleMesh& b);
}

#endif
