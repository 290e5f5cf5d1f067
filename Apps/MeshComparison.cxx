#include "MeshComparison.h"

#include "SurfaceDistance.h"
#include "vtkCellLocatorFaceQuery.h"

#include <vtkCellArray.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace foldingmeshes
{
/// Edges used by exactly one triangle, vertices at identical positions counted as one.
long long CountOpenEdges(vtkPolyData* mesh)
{
  return CountEdges(mesh).open;
}

EdgeCounts CountEdges(vtkPolyData* mesh)
{
  EdgeCounts counts;
  std::map<std::array<double, 3>, vtkIdType> unique;
  std::vector<vtkIdType> id(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    std::array<double, 3> x;
    mesh->GetPoint(p, x.data());
    id[p] = unique.emplace(x, static_cast<vtkIdType>(unique.size())).first->second;
  }
  // Per undirected edge: uses in increasing and in decreasing vertex order.
  std::map<std::pair<vtkIdType, vtkIdType>, std::array<int, 2>> edges;
  vtkCellArray* polys = mesh->GetPolys();
  if (!polys)
    return counts;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  std::vector<char> used(unique.size(), 0);
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = id[pts[k]], b = id[pts[(k + 1) % n]];
      counts.vertices += !used[a];
      used[a] = 1;
      if (a != b)
      {
        auto it =
          edges.emplace(std::make_pair(std::min(a, b), std::max(a, b)), std::array<int, 2>{ 0, 0 })
            .first;
        ++it->second[a < b ? 0 : 1];
      }
    }
  for (const auto& e : edges)
  {
    const int uses = e.second[0] + e.second[1];
    counts.open += uses == 1;
    counts.nonManifold += uses > 2;
    counts.misoriented += uses == 2 && e.second[0] != 1;
  }
  return counts;
}

namespace
{
/// The polygons of `mesh` as triangles (fans), for the core's distance queries.
TriangleMesh ToTriangles(vtkPolyData* mesh)
{
  TriangleMesh out;
  out.points.resize(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    mesh->GetPoint(p, out.points[p].data());
  vtkCellArray* polys = mesh->GetPolys();
  if (!polys)
    return out;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    for (vtkIdType k = 1; k + 1 < n; ++k)
      out.triangles.push_back(
        { static_cast<int>(pts[0]), static_cast<int>(pts[k]), static_cast<int>(pts[k + 1]) });
  return out;
}
}

ClosestFaceQueryFactory DistanceQueries(DistanceLocator locator)
{
  return locator == DistanceLocator::StaticCellLocator ? CellLocatorFaceQueryFactory(nullptr)
                                                       : ClosestFaceQueryFactory();
}

const char* ToString(DistanceLocator locator)
{
  return locator == DistanceLocator::StaticCellLocator ? "static" : "facetree";
}

/// Symmetric Hausdorff distance (max) and mean distance over the samples of both meshes.
void SymmetricSurfaceDistance(vtkPolyData* a,
  vtkPolyData* b,
  double& hausdorff,
  double& mean,
  DistanceLocator locator)
{
  const SurfaceComparison c =
    CompareSurfaces(ToTriangles(a), ToTriangles(b), DistanceQueries(locator));
  hausdorff = c.hausdorff;
  mean = c.mean;
}

void CertifiedSurfaceDistance(vtkPolyData* a,
  vtkPolyData* b,
  double tolerance,
  double& lower,
  double& upper,
  double floor,
  DistanceLocator locator)
{
  const HausdorffBounds bounds = SymmetricHausdorffBounds(
    ToTriangles(a), ToTriangles(b), tolerance, 50000000, floor, DistanceQueries(locator));
  lower = bounds.lower;
  upper = bounds.upper;
}

ProvedDistance ProvedSurfaceDistance(vtkPolyData* a,
  vtkPolyData* b,
  double tolerance,
  double threshold,
  double decideTolerance,
  DistanceLocator locator)
{
  ProvedDistance d;
  CertifiedSurfaceDistance(a, b, tolerance, d.lower, d.upper, 0.0, locator);
  d.within = d.upper <= threshold ? 1 : d.lower > threshold ? -1 : 0;
  if (d.within == 0)
  {
    double lower = 0.0, upper = 0.0;
    CertifiedSurfaceDistance(a, b, decideTolerance, lower, upper, threshold, locator);
    d.within = upper <= threshold + decideTolerance ? 1 : lower > threshold ? -1 : 0;
  }
  return d;
}
}
