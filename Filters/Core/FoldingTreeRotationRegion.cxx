// The rotational part of a region (InvariantRegion, FoldingTreeRotationSector.h): the faces
// every turn of an order maps onto the part itself.
#include "FoldingTreeRotationSector.h"

#include "SurfaceDistance.h"

#include <algorithm>
#include <limits>
#include <memory>

namespace foldingmeshes
{
namespace treebuilder
{
namespace sector
{
namespace
{
/// The turns j (by j 360/k) InvariantRegion checks: all of them up to order
/// InvariantRegionAllTurns; above, the first and the half turn (the detector's test turns;
/// ChargeTurns then checks every turn).
constexpr int InvariantRegionAllTurns = 16;
std::vector<int> InvariantRegionTurns(int k)
{
  std::vector<int> turns = { 1 };
  if (k <= InvariantRegionAllTurns)
    for (int j = 2; j < k; ++j)
      turns.push_back(j);
  else if (k / 2 > 1)
    turns.push_back(k / 2);
  return turns;
}
}

/// (FoldingTreeRotationSector.h)
std::vector<char> InvariantRegion(const WorkMesh& w,
  std::vector<char> region,
  const RotationAxis& axis,
  int k,
  double eps,
  bool strict)
{
  std::unique_ptr<SurfaceDistanceQuery> toMesh; // strict: the whole of w
  if (strict)
  {
    TriangleMesh mesh;
    mesh.points = w.points;
    mesh.triangles = w.triangles;
    toMesh = std::make_unique<SurfaceDistanceQuery>(mesh);
  }
  // Rounding between the two queries' distances to the same face (or to two faces meeting at
  // the point): a few ulps of the coordinates, far below eps.
  double scale = axis.origin.cwiseAbs().maxCoeff();
  for (const Vec3& x : w.points)
    scale = std::max(scale, x.cwiseAbs().maxCoeff());
  const double tie = 1e-9 * eps + 64.0 * std::numeric_limits<double>::epsilon() * scale;
  for (int pass = 0; pass < 3; ++pass)
  {
    // A turned sample must lie within eps of the region and (strict) no nearer to a face
    // outside it than to the region (ties to the region: a turned vertex on its border).
    TriangleMesh surface;
    surface.points = w.points;
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      if (region[f])
        surface.triangles.push_back(w.triangles[f]);
    if (surface.triangles.empty())
      break;
    const SurfaceDistanceQuery toRegion(surface);
    // The samples: the region's vertices, then its faces' centroids (a face whose corners
    // all lie on the border of a dropped patch turns onto the patch's inside).
    std::vector<int> points;
    std::vector<char> inRegion(w.points.size(), 0);
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      if (region[f])
        for (int v : w.triangles[f])
          inRegion[v] = 1;
    std::vector<Vec3> samples;
    for (int v = 0; v < w.NumberOfPoints(); ++v)
      if (inRegion[v])
      {
        points.push_back(v);
        samples.push_back(w.points[v]);
      }
    std::vector<int> faces;
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      if (region[f])
      {
        const Triangle& t = w.triangles[f];
        faces.push_back(f);
        samples.push_back((w.points[t[0]] + w.points[t[1]] + w.points[t[2]]) / 3.0);
      }
    std::vector<char> bad(samples.size(), 0);
    for (int j : InvariantRegionTurns(k))
    {
      const AxisTurn turn(axis, 2.0 * EIGEN_PI * j / k);
      std::vector<Vec3> turned;
      turned.reserve(samples.size());
      for (const Vec3& x : samples)
        turned.push_back(turn.Point(x));
      const std::vector<double> distance = toRegion.Distances(turned);
      std::vector<double> anyDistance;
      if (strict)
        anyDistance = toMesh->Distances(turned);
      for (size_t i = 0; i < samples.size(); ++i)
        bad[i] = bad[i] || !(distance[i] <= eps) || (strict && distance[i] > anyDistance[i] + tie);
    }
    std::vector<char> badPoint(w.points.size(), 0);
    for (size_t i = 0; i < points.size(); ++i)
      badPoint[points[i]] = bad[i];
    bool dropped = false;
    for (size_t i = 0; i < faces.size(); ++i)
    {
      const Triangle& t = w.triangles[faces[i]];
      if (bad[points.size() + i] || badPoint[t[0]] || badPoint[t[1]] || badPoint[t[2]])
      {
        region[faces[i]] = 0;
        dropped = true;
      }
    }
    if (!dropped)
      break;
  }
  return region;
}
}
}
}
