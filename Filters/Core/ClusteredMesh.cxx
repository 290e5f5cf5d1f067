#include "ClusteredMesh.h"

#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace foldingmeshes
{
ClusteredMesh ClusterVertices(const PreparedMesh& mesh, int targetFaces)
{
  ClusteredMesh out;
  const int nf = mesh.NumberOfFaces();
  const int nv = mesh.NumberOfPoints();
  std::vector<char> used(nv, 0);
  for (int f = 0; f < nf; ++f)
    if (!mesh.faceDegenerate[f])
      for (int v : mesh.triangles[f])
        used[v] = 1;
  std::vector<int> cluster(nv, -1);
  if (nf <= targetFaces || targetFaces <= 0)
  {
    for (int v = 0; v < nv; ++v)
      cluster[v] = v;
  }
  else
  {
    // Cell size from the mean face area: a surface of area A holds about A / h^2 cells, and
    // a cluster mesh has about twice as many faces as vertices.
    const double h = std::sqrt(2.0 * mesh.totalArea / targetFaces);
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
    for (int v = 0; v < nv; ++v)
      cluster[v] = FindRoot(parent, v); // the lowest vertex index of the cluster
  }

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
}
