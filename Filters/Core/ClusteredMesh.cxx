#include "ClusteredMesh.h"

#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace foldingmeshes
{
namespace
{
/// A copy whose triangles use more points than this per face asked for comes from a mesh of
/// many small parts (a connected surface's copy uses 0.4-0.9 of them: 29 shared meshes): the
/// cells grow until it uses at most this many ...
constexpr double MaximumPointsPerTargetFace = 1.0;
/// ... and the coarser copy is taken only where it still uses at least this many (parts of
/// one size and orientation collapse all at once: no cell size in between).
constexpr double MinimumPointsPerTargetFace = 0.4;
/// ... on meshes above this many faces only: below, the search is fast anyway (under 0.4 s on
/// the artist-like corpus) and a coarser copy would only change its trees (the slatted bench
/// of 3,648 faces: a tree of 235 instead of 242 faces that unfolds with more surface laid twice
/// under some rigid motions, scripts/fuzz).
constexpr int CoarserCellsAboveFaces = 5000;
/// Growth of the cell size per step, steps at most, and bisections between the last two.
constexpr double CoarserCellFactor = 1.25;
constexpr int MaximumCoarserCells = 32;
constexpr int CellSizeBisections = 8;

/// Cluster of every vertex (numbered by its lowest vertex) for grid cells of size h.
std::vector<int> ClustersForCellSize(const PreparedMesh& mesh, double h)
{
  const int nf = mesh.NumberOfFaces();
  const int nv = mesh.NumberOfPoints();
  std::vector<std::array<long long, 3>> cell(nv);
  for (int v = 0; v < nv; ++v)
  {
    const Vec3 q = ((mesh.points[v] - mesh.boundsMin) / h).array().floor();
    cell[v] = {
      static_cast<long long>(q.x()), static_cast<long long>(q.y()), static_cast<long long>(q.z())
    };
  }
  std::vector<int> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < nf; ++f)
  {
    if (mesh.faceDegenerate[f])
      continue;
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      if (cell[a] == cell[b] && mesh.vertexNormals[a].dot(mesh.vertexNormals[b]) > 0.0)
        Unite(parent, a, b);
    }
  }
  std::vector<int> cluster(nv);
  for (int v = 0; v < nv; ++v)
    cluster[v] = FindRoot(parent, v); // the lowest vertex index of the cluster
  return cluster;
}

/// The copy for the clusters: representatives and triangles (see ClusterVertices).
ClusteredMesh CopyOfClusters(const PreparedMesh& mesh,
  const std::vector<char>& used,
  const std::vector<int>& cluster)
{
  ClusteredMesh out;
  const int nf = mesh.NumberOfFaces();
  const int nv = mesh.NumberOfPoints();
  // Representatives: per cluster (numbered by its lowest vertex), the member nearest to
  // the area-weighted mean.
  std::vector<Vec3> mean(nv, Vec3::Zero());
  std::vector<double> weight(nv, 0.0);
  for (int v = 0; v < nv; ++v)
    if (used[v])
    {
      const double w = mesh.vertexAreas[v] > 0.0 ? mesh.vertexAreas[v] : 1e-300;
      mean[cluster[v]] += w * mesh.points[v];
      weight[cluster[v]] += w;
    }
  std::vector<int> best(nv, -1);
  std::vector<double> bestDistance(nv, std::numeric_limits<double>::infinity());
  for (int v = 0; v < nv; ++v)
    if (used[v])
    {
      const int c = cluster[v];
      const double d = (mesh.points[v] - mean[c] / weight[c]).squaredNorm();
      if (d < bestDistance[c])
      {
        bestDistance[c] = d;
        best[c] = v;
      }
    }
  std::vector<int> point(nv, -1); // cluster (its lowest vertex) -> point of out.mesh
  for (int c = 0; c < nv; ++c)
    if (best[c] >= 0)
    {
      point[c] = static_cast<int>(out.vertex.size());
      out.vertex.push_back(best[c]);
      out.mesh.points.push_back(mesh.points[best[c]]);
      out.normals.push_back(mesh.vertexNormals[best[c]]);
    }

  std::vector<std::array<int, 3>> keys;
  for (int f = 0; f < nf; ++f)
  {
    if (mesh.faceDegenerate[f])
      continue;
    const Triangle t{ point[cluster[mesh.triangles[f][0]]],
      point[cluster[mesh.triangles[f][1]]],
      point[cluster[mesh.triangles[f][2]]] };
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      continue;
    std::array<int, 3> key = t;
    std::sort(key.begin(), key.end());
    keys.push_back(key);
    out.mesh.triangles.push_back(t);
  }
  // Two faces collapsing onto the same cluster triangle: the first one stays.
  std::vector<int> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(),
    order.end(),
    [&](int a, int b) { return keys[a] != keys[b] ? keys[a] < keys[b] : a < b; });
  std::vector<char> keep(keys.size(), 1);
  for (size_t m = 1; m < order.size(); ++m)
    if (keys[order[m]] == keys[order[m - 1]])
      keep[order[m]] = 0;
  std::vector<Triangle> kept;
  for (size_t m = 0; m < keys.size(); ++m)
    if (keep[m])
      kept.push_back(out.mesh.triangles[m]);
  out.mesh.triangles.swap(kept);
  return out;
}

/// Points of `copy` that a triangle uses: the vertices detection queries.
int PointsUsed(const ClusteredMesh& copy)
{
  std::vector<char> used(copy.mesh.points.size(), 0);
  for (const Triangle& t : copy.mesh.triangles)
    for (int v : t)
      used[v] = 1;
  return static_cast<int>(std::count(used.begin(), used.end(), 1));
}
}

ClusteredMesh ClusterVertices(const PreparedMesh& mesh, int targetFaces)
{
  const int nf = mesh.NumberOfFaces();
  const int nv = mesh.NumberOfPoints();
  std::vector<char> used(nv, 0);
  for (int f = 0; f < nf; ++f)
    if (!mesh.faceDegenerate[f])
      for (int v : mesh.triangles[f])
        used[v] = 1;
  if (nf <= targetFaces || targetFaces <= 0)
  {
    std::vector<int> cluster(nv);
    std::iota(cluster.begin(), cluster.end(), 0);
    return CopyOfClusters(mesh, used, cluster);
  }
  // Cell size from the mean face area: a surface of area A holds about A / h^2 cells, and
  // a cluster mesh has about twice as many faces as vertices.
  double h = std::sqrt(2.0 * mesh.totalArea / targetFaces);
  ClusteredMesh out = CopyOfClusters(mesh, used, ClustersForCellSize(mesh, h));
  // A mesh of many small parts keeps most of its vertices at that size (a part smaller than
  // a cell still keeps its corners wherever its edges leave the cell, and its faces have
  // little area). Then the cells grow until the copy queries at most
  // MaximumPointsPerTargetFace points per face asked for, as a connected surface's copy does,
  // and shrink back by bisection to the smallest size found that does: parts of one size
  // collapse over a narrow range of sizes.
  const double limit = MaximumPointsPerTargetFace * targetFaces;
  if (nf > CoarserCellsAboveFaces && PointsUsed(out) > limit)
  {
    double fine = h, coarse = h;
    ClusteredMesh coarseCopy;
    int coarseUsed = 0;
    int steps = 0;
    // Cells larger than the mesh's diagonal change nothing more.
    do
    {
      fine = coarse;
      coarse *= CoarserCellFactor;
      coarseCopy = CopyOfClusters(mesh, used, ClustersForCellSize(mesh, coarse));
      coarseUsed = PointsUsed(coarseCopy);
    } while (coarseUsed > limit && ++steps < MaximumCoarserCells && coarse < mesh.diagonal);
    // No size got there: the first copy stays (no bisection).
    for (int k = 0; k < CellSizeBisections && coarseUsed <= limit; ++k)
    {
      const double mid = std::sqrt(fine * coarse);
      ClusteredMesh copy = CopyOfClusters(mesh, used, ClustersForCellSize(mesh, mid));
      const int copyUsed = PointsUsed(copy);
      if (copyUsed > limit)
        fine = mid;
      else
      {
        coarse = mid;
        coarseCopy = std::move(copy);
        coarseUsed = copyUsed;
      }
    }
    if (coarseUsed <= limit && coarseUsed >= MinimumPointsPerTargetFace * targetFaces)
      out = std::move(coarseCopy);
  }
  return out;
}
}
