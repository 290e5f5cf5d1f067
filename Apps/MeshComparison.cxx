#include "MeshComparison.h"

#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSMPThreadLocalObject.h>
#include <vtkSMPTools.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace foldingmeshes
{
/// Edges used by exactly one triangle, vertices at identical positions counted as one.
long long CountOpenEdges(vtkPolyData* mesh)
{
  std::map<std::array<double, 3>, vtkIdType> unique;
  std::vector<vtkIdType> id(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    std::array<double, 3> x;
    mesh->GetPoint(p, x.data());
    id[p] = unique.emplace(x, static_cast<vtkIdType>(unique.size())).first->second;
  }
  std::map<std::pair<vtkIdType, vtkIdType>, int> edges;
  vtkCellArray* polys = mesh->GetPolys();
  if (!polys)
    return 0;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = id[pts[k]], b = id[pts[(k + 1) % n]];
      if (a != b)
        ++edges[{ std::min(a, b), std::max(a, b) }];
    }
  long long open = 0;
  for (const auto& e : edges)
    open += e.second == 1;
  return open;
}

namespace
{
struct Distances
{
  double max = 0.0, sum = 0.0;
  vtkIdType count = 0;
};

/// Distances from every point of `from` to the surface `to` (vtkStaticCellLocator).
Distances PointsToSurface(vtkPolyData* from, vtkPolyData* to)
{
  Distances result;
  if (from->GetNumberOfPoints() == 0 || to->GetNumberOfCells() == 0)
    return result;
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  std::vector<double> d(from->GetNumberOfPoints(), 0.0);
  vtkSMPThreadLocalObject<vtkGenericCell> cells;
  vtkSMPTools::For(0,
    from->GetNumberOfPoints(),
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkGenericCell* cell = cells.Local();
      double x[3], closest[3], dist2 = 0.0;
      vtkIdType cellId = -1;
      int subId = 0;
      for (vtkIdType p = begin; p < end; ++p)
      {
        from->GetPoint(p, x);
        locator->FindClosestPoint(x, closest, cell, cellId, subId, dist2);
        d[p] = std::sqrt(dist2);
      }
    });
  for (double v : d)
  {
    result.max = std::max(result.max, v);
    result.sum += v;
  }
  result.count = static_cast<vtkIdType>(d.size());
  return result;
}

}

/// Symmetric Hausdorff distance (max) and mean point-to-surface distance over both meshes.
void SymmetricSurfaceDistance(vtkPolyData* a, vtkPolyData* b, double& hausdorff, double& mean)
{
  const Distances ab = PointsToSurface(a, b), ba = PointsToSurface(b, a);
  hausdorff = std::max(ab.max, ba.max);
  mean = ab.count + ba.count > 0 ? (ab.sum + ba.sum) / static_cast<double>(ab.count + ba.count) : 0;
}
}
