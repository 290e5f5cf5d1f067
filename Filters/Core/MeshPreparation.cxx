#include "MeshPreparation.h"

#include "EdgeTable.h"
#include "ParallelTasks.h"
#include "PointKdTree.h"
#include "UnionFind.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace foldingmeshes
{
namespace
{
struct EdgeUse
{
  int a, b;   // sorted vertex ids
  int face;   // face using the edge
  bool along; // the face traverses a -> b
  bool operator<(const EdgeUse& o) const
  {
    return a != o.a ? a < o.a : (b != o.b ? b < o.b : face < o.face);
  }
};

void WeldPoints(const TriangleMesh& input, PreparedMesh& mesh)
{
  const int n = static_cast<int>(input.points.size());
  const auto& p = input.points;
  // Welded ids follow the first input id of each group, so the result is order-stable.
  const std::vector<int> groupFirst = CoincidentPointRepresentatives(p);
  mesh.inputToWelded.assign(n, -1);
  mesh.points.clear();
  mesh.weldedToInput.clear();
  for (int i = 0; i < n; ++i)
  {
    if (groupFirst[i] == i)
    {
      mesh.inputToWelded[i] = static_cast<int>(mesh.points.size());
      mesh.points.push_back(p[i]);
      mesh.weldedToInput.push_back(i);
    }
  }
  for (int i = 0; i < n; ++i)
    mesh.inputToWelded[i] = mesh.inputToWelded[groupFirst[i]];
}

void BuildCsr(int count,
  const std::vector<std::pair<int, int>>& pairs,
  std::vector<int>& offsets,
  std::vector<int>& values)
{
  offsets.assign(count + 1, 0);
  for (const auto& pr : pairs)
    ++offsets[pr.first + 1];
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  values.assign(pairs.size(), 0);
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (const auto& pr : pairs)
    values[fill[pr.first]++] = pr.second;
}

/// Sorts `items` into the order std::sort gives them, for an operator< that orders by
/// key(item) in [0, keyCount) first: buckets by key (a counting pass), then sorts each
/// (small) bucket. Linear in practice instead of n log n.
template <typename T, typename Key>
void BucketSort(std::vector<T>& items, int keyCount, Key key)
{
  std::vector<int> offsets(keyCount + 1, 0);
  for (const T& x : items)
    ++offsets[key(x) + 1];
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<T> sorted(items.size());
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (const T& x : items)
    sorted[fill[key(x)]++] = x;
  for (int k = 0; k < keyCount; ++k)
    std::sort(sorted.begin() + offsets[k], sorted.begin() + offsets[k + 1]);
  items.swap(sorted);
}

/// Breadth-first orientation of each part; returns per-face flip flags.
std::vector<char> OrientFaces(PreparedMesh& mesh, const std::vector<EdgeUse>& uses)
{
  const int nf = mesh.NumberOfFaces();
  // For manifold edges: the two faces and whether they traverse it in the same direction,
  // per face in the order of `uses` (compressed rows: offsets[f]..offsets[f + 1]).
  std::vector<size_t> manifold; // index in `uses` of each manifold edge's first use
  for (size_t k = 0; k < uses.size();)
  {
    size_t e = k;
    while (e < uses.size() && uses[e].a == uses[k].a && uses[e].b == uses[k].b)
      ++e;
    if (e - k == 2)
      manifold.push_back(k);
    k = e;
  }
  std::vector<int> offsets(nf + 1, 0);
  for (size_t k : manifold)
  {
    ++offsets[uses[k].face + 1];
    ++offsets[uses[k + 1].face + 1];
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::pair<int, bool>> linkValues(offsets[nf]);
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (size_t k : manifold)
  {
    const bool same = uses[k].along == uses[k + 1].along;
    linkValues[fill[uses[k].face]++] = { uses[k + 1].face, same };
    linkValues[fill[uses[k + 1].face]++] = { uses[k].face, same };
  }
  std::vector<char> flip(nf, 0), seen(nf, 0);
  for (int seed = 0; seed < nf; ++seed)
  {
    if (seen[seed])
      continue;
    seen[seed] = 1;
    std::queue<int> todo;
    todo.push(seed);
    while (!todo.empty())
    {
      const int f = todo.front();
      todo.pop();
      for (int l = offsets[f]; l < offsets[f + 1]; ++l)
      {
        const auto& [g, same] = linkValues[l];
        if (!seen[g])
        {
          seen[g] = 1;
          flip[g] = same ? !flip[f] : flip[f];
          todo.push(g);
        }
      }
    }
  }
  return flip;
}
}

std::vector<int> CoincidentPointRepresentatives(const std::vector<Vec3>& p)
{
  const int n = static_cast<int>(p.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(),
    order.end(),
    [&](int i, int j)
    {
      if (p[i].x() != p[j].x())
        return p[i].x() < p[j].x();
      if (p[i].y() != p[j].y())
        return p[i].y() < p[j].y();
      if (p[i].z() != p[j].z())
        return p[i].z() < p[j].z();
      return i < j;
    });
  std::vector<int> first(n, -1);
  for (int k = 0; k < n;)
  {
    int e = k;
    while (e < n && p[order[e]] == p[order[k]])
      ++e;
    for (int m = k; m < e; ++m)
      first[order[m]] = order[k];
    k = e;
  }
  return first;
}

void ComputeBoundsAndAreas(PreparedMesh& mesh)
{
  // Bounds (and so epsilon) over the points that triangles use: stray points of vertex or
  // line cells, or unused ones, must not change the tolerance.
  bool anyUsed = false;
  for (const Triangle& t : mesh.triangles)
    for (int v : t)
    {
      if (!anyUsed)
        mesh.boundsMin = mesh.boundsMax = mesh.points[v];
      anyUsed = true;
      mesh.boundsMin = mesh.boundsMin.cwiseMin(mesh.points[v]);
      mesh.boundsMax = mesh.boundsMax.cwiseMax(mesh.points[v]);
    }
  mesh.diagonal = (mesh.boundsMax - mesh.boundsMin).norm();

  // Areas and degeneracy (before orientation: independent of it).
  const int nf = mesh.NumberOfFaces();
  mesh.faceAreas.assign(nf, 0.0);
  mesh.faceDegenerate.assign(nf, 0);
  mesh.totalArea = 0.0;
  // Round-off of float coordinates leaves collinear faces areas near 1e-14 diag^2.
  const double areaFloor = 1e-12 * mesh.diagonal * mesh.diagonal;
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = mesh.triangles[f];
    const double area = 0.5 *
      (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]).norm();
    const bool repeated = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    mesh.faceDegenerate[f] = repeated || !(area > areaFloor);
    mesh.faceAreas[f] = mesh.faceDegenerate[f] ? 0.0 : area;
    mesh.totalArea += mesh.faceAreas[f];
  }
}

namespace
{
/// NaN-free points and triangles that refer to existing points; false with the reason.
bool CheckTriangleMesh(const TriangleMesh& input, std::string& error)
{
  for (const Vec3& p : input.points)
  {
    if (!p.allFinite())
    {
      error = "the mesh has NaN or infinite point coordinates";
      return false;
    }
  }
  const int np = static_cast<int>(input.points.size());
  for (const Triangle& t : input.triangles)
  {
    for (int v : t)
    {
      if (v < 0 || v >= np)
      {
        error = "a triangle refers to a point that does not exist";
        return false;
      }
    }
  }
  return true;
}

/// Parts (faces connected through edges), face adjacency (CSR) and the boundary and
/// non-manifold edge counts, from the edge uses sorted by edge.
void ConnectFaces(PreparedMesh& mesh, const std::vector<EdgeUse>& uses)
{
  const int nf = mesh.NumberOfFaces();
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::pair<int, int>> adjacent;
  for (size_t k = 0; k < uses.size();)
  {
    size_t e = k;
    while (e < uses.size() && uses[e].a == uses[k].a && uses[e].b == uses[k].b)
      ++e;
    const size_t count = e - k;
    if (count == 1)
      ++mesh.numberOfBoundaryEdges;
    else if (count > 2)
      ++mesh.numberOfNonManifoldEdges;
    for (size_t i = k; i < e; ++i)
      for (size_t j = k; j < e; ++j)
        if (i != j && uses[i].face != uses[j].face)
        {
          adjacent.push_back({ uses[i].face, uses[j].face });
          Unite(parent, uses[i].face, uses[j].face);
        }
    k = e;
  }
  BucketSort(adjacent, nf, [](const std::pair<int, int>& fg) { return fg.first; });
  adjacent.erase(std::unique(adjacent.begin(), adjacent.end()), adjacent.end());
  BuildCsr(nf, adjacent, mesh.faceNeighborOffsets, mesh.faceNeighbors);

  mesh.facePart.assign(nf, -1);
  std::vector<int> partOfRoot(nf, -1);
  for (int f = 0; f < nf; ++f)
  {
    const int r = FindRoot(parent, f);
    if (partOfRoot[r] < 0)
      partOfRoot[r] = mesh.numberOfParts++;
    mesh.facePart[f] = partOfRoot[r];
  }
}

/// Orientation: consistent per part, then outward (closed parts) or the majority's (open).
void OrientParts(PreparedMesh& mesh, const std::vector<EdgeUse>& uses)
{
  const int nf = mesh.NumberOfFaces();
  std::vector<char> flip = OrientFaces(mesh, uses);
  std::vector<char> partClosed(mesh.numberOfParts, 1);
  for (size_t k = 0; k < uses.size();)
  {
    size_t e = k;
    while (e < uses.size() && uses[e].a == uses[k].a && uses[e].b == uses[k].b)
      ++e;
    if (e - k != 2)
      partClosed[mesh.facePart[uses[k].face]] = 0;
    k = e;
  }
  std::vector<double> volume(mesh.numberOfParts, 0.0);
  std::vector<int> flippedCount(mesh.numberOfParts, 0), faceCount(mesh.numberOfParts, 0);
  const Vec3 center = 0.5 * (mesh.boundsMin + mesh.boundsMax);
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = mesh.triangles[f];
    const double v = (mesh.points[t[0]] - center)
                       .dot((mesh.points[t[1]] - center).cross(mesh.points[t[2]] - center));
    volume[mesh.facePart[f]] += flip[f] ? -v : v;
    flippedCount[mesh.facePart[f]] += flip[f];
    ++faceCount[mesh.facePart[f]];
  }
  for (int f = 0; f < nf; ++f)
  {
    const int part = mesh.facePart[f];
    const bool invert =
      partClosed[part] ? volume[part] < 0.0 : 2 * flippedCount[part] > faceCount[part];
    if (invert)
      flip[f] = !flip[f];
    if (flip[f])
    {
      std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
      ++mesh.numberOfFlippedFaces;
    }
  }
}

/// Face normals and centroids, area-weighted vertex normals (the input's where it has valid
/// ones, turned to the oriented surface's side), vertex areas and the vertex -> faces CSR.
void ComputeNormalsAndIncidence(PreparedMesh& mesh,
  const TriangleMesh& input,
  const std::vector<Vec3>& inputNormals)
{
  const int nf = mesh.NumberOfFaces();
  const int nv = mesh.NumberOfPoints();
  mesh.faceNormals.assign(nf, Vec3::Zero());
  mesh.faceCentroids.assign(nf, Vec3::Zero());
  mesh.vertexNormals.assign(nv, Vec3::Zero());
  mesh.vertexAreas.assign(nv, 0.0);
  std::vector<std::pair<int, int>> incidence;
  incidence.reserve(3 * static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = mesh.triangles[f];
    const Vec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    mesh.faceCentroids[f] = (a + b + c) / 3.0;
    const Vec3 cross = (b - a).cross(c - a);
    if (!mesh.faceDegenerate[f])
      mesh.faceNormals[f] = cross.normalized();
    for (int k = 0; k < 3; ++k)
    {
      if (k > 0 && t[k] == t[k - 1])
        continue;
      mesh.vertexNormals[t[k]] += 0.5 * cross; // area-weighted
      mesh.vertexAreas[t[k]] += mesh.faceAreas[f] / 3.0;
      incidence.push_back({ t[k], f });
    }
  }
  for (Vec3& n : mesh.vertexNormals)
  {
    const double len = n.norm();
    n = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
  }
  if (!inputNormals.empty() && inputNormals.size() == input.points.size())
  {
    for (int v = 0; v < nv; ++v)
    {
      const Vec3& n = inputNormals[mesh.weldedToInput[v]];
      if (n.allFinite() && n.norm() > 0.0)
      {
        // Trust the direction, but keep it on the side of the oriented surface.
        const Vec3 u = n.normalized();
        mesh.vertexNormals[v] = u.dot(mesh.vertexNormals[v]) < 0.0 ? Vec3(-u) : u;
      }
    }
  }
  // The pairs come in increasing face order: BuildCsr's stable bucketing lists each
  // vertex's faces in increasing order, as sorting the pairs first would.
  BuildCsr(nv, incidence, mesh.vertexFaceOffsets, mesh.vertexFaces);
}

}

bool PrepareMesh(const TriangleMesh& input,
  const std::vector<Vec3>& inputNormals,
  PreparedMesh& mesh,
  std::string& error)
{
  mesh = PreparedMesh();
  if (input.points.empty() || input.triangles.empty())
  {
    error = "the mesh has no triangles";
    return false;
  }
  if (!CheckTriangleMesh(input, error))
    return false;
  WeldPoints(input, mesh);
  const int nf = static_cast<int>(input.triangles.size());
  mesh.triangles.resize(nf);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      mesh.triangles[f][k] = mesh.inputToWelded[input.triangles[f][k]];

  ComputeBoundsAndAreas(mesh);
  if (!(mesh.totalArea > 0.0) || !(mesh.diagonal > 0.0))
  {
    error = "the mesh has zero area";
    return false;
  }

  // Edge uses of faces with three distinct vertices.
  std::vector<EdgeUse> uses;
  uses.reserve(3 * static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      continue;
    for (int k = 0; k < 3; ++k)
    {
      const int u = t[k], v = t[(k + 1) % 3];
      uses.push_back({ std::min(u, v), std::max(u, v), f, u < v });
    }
  }
  BucketSort(uses, mesh.NumberOfPoints(), [](const EdgeUse& u) { return u.a; });

  ConnectFaces(mesh, uses);

  OrientParts(mesh, uses);

  ComputeNormalsAndIncidence(mesh, input, inputNormals);
  return true;
}

void LinkNearbyParts(PreparedMesh& mesh, double gap)
{
  mesh.proximityLinks.clear();
  if (mesh.numberOfParts < 2 || !(gap > 0.0))
    return;
  const int nv = mesh.NumberOfPoints();
  std::vector<int> vertexPart(nv, -1);
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    for (int v : mesh.triangles[f])
      vertexPart[v] = mesh.facePart[f];
  std::vector<int> used;
  for (int v = 0; v < nv; ++v)
    if (vertexPart[v] >= 0)
      used.push_back(v);
  const PointKdTree search(mesh.points, used);
  // Closer than `gap` (strictly: the largest double below it as the radius).
  const double radius = std::nextafter(gap, 0.0);
  // Only the nearest vertex of another part: linear in the mesh size even for triangle soups,
  // where every face is its own part. Every vertex alone (a read-only tree), the links then in
  // vertex order: the same for any thread count.
  std::vector<int> nearest(nv, -1);
  ForRanges(nv,
    512,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType v = first; v < last; ++v)
        if (vertexPart[v] >= 0)
          nearest[v] = search.NearestWithinWhere(
            mesh.points[v], radius, [&](int w) { return vertexPart[w] != vertexPart[v]; });
    });
  for (int v = 0; v < nv; ++v)
    if (nearest[v] >= 0)
      mesh.proximityLinks.push_back({ v, nearest[v] });
}

std::vector<char> BorderPoints(const std::vector<Triangle>& triangles, size_t pointCount)
{
  std::vector<char> border(pointCount, 0);
  for (const Edge& e : OpenEdges(triangles))
    border[e.first] = border[e.second] = 1;
  return border;
}
}
