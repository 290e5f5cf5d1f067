/**
 * @file    MeshComparison.h
 * @brief   measures between two surface meshes (command line, benchmarks)
 */
#ifndef foldingmeshes_MeshComparison_h
#define foldingmeshes_MeshComparison_h

#include "ClosestFaceQuery.h"

class vtkPolyData;

namespace foldingmeshes
{
/// Edges used by exactly one polygon, vertices at identical positions counted as one.
long long CountOpenEdges(vtkPolyData* mesh);

/// Edge statistics (vertices at identical positions counted as one): edges of one polygon,
/// of more than two, and of two that traverse the edge in the same direction; and the
/// vertices (distinct positions) the polygons use.
struct EdgeCounts
{
  long long open = 0;
  long long nonManifold = 0;
  long long misoriented = 0;
  long long vertices = 0;
};
EdgeCounts CountEdges(vtkPolyData* mesh);

/**
 * Which structure answers the closest-triangle queries of the measures below: a
 * vtkStaticCellLocator (as vtkFoldingTreeUnfolder's distances to its "Original"; the users'
 * design) or the core's face tree (the same distances, 4-20x faster; docs/benchmarks.md).
 */
enum class DistanceLocator
{
  StaticCellLocator,
  FaceTree
};

/// The core's query factory for `locator` (null: the face tree).
ClosestFaceQueryFactory DistanceQueries(DistanceLocator locator);

/// The locator's name as the command line spells it ("static", "facetree").
const char* ToString(DistanceLocator locator);

/**
 * Symmetric Hausdorff distance and mean distance between the polygon surfaces of two meshes,
 * by the core's CompareSurfaces (Filters/Core/SurfaceDistance.h: exact point-to-surface
 * distances sampled at the vertices and face centroids of both meshes) - the same measure
 * vtkFoldingTreeUnfolder reports against its "Original" input. Lengths, not fractions of a
 * diagonal.
 */
void SymmetricSurfaceDistance(vtkPolyData* a,
  vtkPolyData* b,
  double& hausdorff,
  double& mean,
  DistanceLocator locator = DistanceLocator::FaceTree);

/**
 * The symmetric Hausdorff distance between the polygon surfaces of a and b over every point of
 * both (not only samples), bracketed to within `tolerance` (a length): lower, a distance
 * measured; upper, proved (the core's SymmetricHausdorffBounds, Filters/Core/SurfaceDistance.h,
 * which also says what `floor` does).
 */
void CertifiedSurfaceDistance(vtkPolyData* a,
  vtkPolyData* b,
  double tolerance,
  double& lower,
  double& upper,
  double floor = 0.0,
  DistanceLocator locator = DistanceLocator::FaceTree);

/// CertifiedSurfaceDistance within `tolerance`, and whether the distance is within
/// `threshold`: -1 proved above it, 1 proved within it (to `decideTolerance`: where the first
/// bounds straddle it, they are refined to that tolerance with threshold as the floor), 0
/// still undecided.
struct ProvedDistance
{
  double lower = 0.0, upper = 0.0;
  int within = 0;
};
ProvedDistance ProvedSurfaceDistance(vtkPolyData* a,
  vtkPolyData* b,
  double tolerance,
  double threshold,
  double decideTolerance,
  DistanceLocator locator = DistanceLocator::FaceTree);
}

#endif
