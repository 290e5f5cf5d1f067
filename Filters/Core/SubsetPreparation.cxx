#include "SubsetPreparation.h"

#include "MeshPreparation.h"
#include "UnionFind.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

namespace foldingmeshes
{
namespace
{
/// PrepareMesh on the soup of the selected faces (the definition PrepareFaceSubset follows).
bool PrepareSelectedSoup(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  PreparedMesh& subset)
{
  TriangleMesh soup;
  std::vector<Vec3> normals;
  std::vector<int> newId(mesh.NumberOfPoints(), -1);
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (faceMask[f])
      for (int v : mesh.triangles[f])
        newId[v] = 0;
  for (int v = 0; v < mesh.NumberOfPoints(); ++v)
    if (newId[v] == 0)
    {
      newId[v] = static_cast<int>(soup.points.size());
      soup.points.push_back(mesh.points[v]);
      normals.push_back(mesh.vertexNormals[v]);
    }
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (faceMask[f])
    {
      const Triangle& t = mesh.triangles[f];
      soup.triangles.push_back({ newId[t[0]], newId[t[1]], newId[t[2]] });
    }
  std::string error;
  return PrepareMesh(soup, normals, subset, error);
}

/// +1 if triangle t traverses u -> v, -1 if v -> u, 0 if it does not hold both.
int Traversal(const Triangle& t, int u, int v)
{
  for (int k = 0; k < 3; ++k)
    if (t[k] == u)
      return t[(k + 1) % 3] == v ? 1 : (t[(k + 2) % 3] == v ? -1 : 0);
  return 0;
}
}

namespace
{
/// Calls use(g, direction) for every other face g of `mesh` using edge k of face f (corner k
/// to corner k + 1) that `faceMask` selects (all faces without one), in the order of the
/// faces around the edge's first point.
template <typename Use>
void ForEachEdgeUse(const PreparedMesh& mesh,
  const std::vector<char>* faceMask,
  int f,
  int k,
  const Use& use)
{
  const Triangle& t = mesh.triangles[f];
  const int u = t[k], v = t[(k + 1) % 3];
  for (int m = mesh.vertexFaceOffsets[u]; m < mesh.vertexFaceOffsets[u + 1]; ++m)
  {
    const int g = mesh.vertexFaces[m];
    if (g == f || (faceMask && !(*faceMask)[g]))
      continue;
    const int direction = Traversal(mesh.triangles[g], u, v);
    if (direction != 0)
      use(g, direction);
  }
}

/**
 * Adjacency (from `table`, else mesh.vertexFaces), parts and the open / non-manifold edge
 * counts of the subset's faces (`faces`: their ids in `mesh`, `localFace`: the inverse);
 * onOpenEdge per subset face. False when two faces across a manifold edge are not
 * consistently oriented (the caller then prepares the faces as a soup).
 */
bool ConnectSubsetFaces(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  const FaceEdgeUses* table,
  const std::vector<int>& faces,
  const std::vector<int>& localFace,
  PreparedMesh& subset,
  std::vector<char>& onOpenEdge)
{
  const int nf = static_cast<int>(faces.size());
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  onOpenEdge.assign(nf, 0);
  subset.faceNeighborOffsets.assign(nf + 1, 0);
  std::vector<int> others;
  for (int i = 0; i < nf; ++i)
  {
    const int f = faces[i];
    const size_t firstNeighbor = subset.faceNeighbors.size();
    for (int k = 0; k < 3; ++k)
    {
      others.clear();
      bool lowest = true, sameDirection = false;
      const auto use = [&](int g, int direction)
      {
        others.push_back(localFace[g]);
        lowest = lowest && g > f;
        sameDirection = sameDirection || direction > 0;
      };
      if (table)
      {
        for (int m = table->offsets[3 * f + k]; m < table->offsets[3 * f + k + 1]; ++m)
          if (faceMask[table->faces[m]])
            use(table->faces[m], table->directions[m]);
      }
      else
        ForEachEdgeUse(mesh, &faceMask, f, k, use);
      const size_t uses = others.size() + 1;
      if (uses == 2 && sameDirection)
        return false;
      if (uses != 2)
        onOpenEdge[i] = 1;
      if (lowest && uses == 1)
        ++subset.numberOfBoundaryEdges;
      if (lowest && uses > 2)
        ++subset.numberOfNonManifoldEdges;
      for (int j : others)
      {
        subset.faceNeighbors.push_back(j);
        Unite(parent, i, j);
      }
    }
    std::sort(subset.faceNeighbors.begin() + firstNeighbor, subset.faceNeighbors.end());
    subset.faceNeighbors.erase(
      std::unique(subset.faceNeighbors.begin() + firstNeighbor, subset.faceNeighbors.end()),
      subset.faceNeighbors.end());
    subset.faceNeighborOffsets[i + 1] = static_cast<int>(subset.faceNeighbors.size());
  }
  subset.facePart.assign(nf, -1);
  std::vector<int> partOfRoot(nf, -1);
  for (int f = 0; f < nf; ++f)
  {
    const int r = FindRoot(parent, f);
    if (partOfRoot[r] < 0)
      partOfRoot[r] = subset.numberOfParts++;
    subset.facePart[f] = partOfRoot[r];
  }
  return true;
}

/// Orientation: consistent already (no face flipped by a walk), so an open part keeps it
/// and a closed part is turned outward.
void OrientClosedParts(PreparedMesh& subset, const std::vector<char>& onOpenEdge)
{
  const int nf = subset.NumberOfFaces();
  std::vector<char> partClosed(subset.numberOfParts, 1);
  for (int f = 0; f < nf; ++f)
    if (onOpenEdge[f])
      partClosed[subset.facePart[f]] = 0;
  std::vector<double> volume(subset.numberOfParts, 0.0);
  const Vec3 center = 0.5 * (subset.boundsMin + subset.boundsMax);
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = subset.triangles[f];
    volume[subset.facePart[f]] +=
      (subset.points[t[0]] - center)
        .dot((subset.points[t[1]] - center).cross(subset.points[t[2]] - center));
  }
  for (int f = 0; f < nf; ++f)
    if (partClosed[subset.facePart[f]] && volume[subset.facePart[f]] < 0.0)
    {
      std::swap(subset.triangles[f][1], subset.triangles[f][2]);
      ++subset.numberOfFlippedFaces;
    }
}

/// Normals, centroids, vertex areas, vertex-face incidence (in face order); then mesh's
/// vertex normals as the input normals, on the side of the subset's surface.
void SubsetNormalsAndIncidence(const PreparedMesh& mesh,
  const std::vector<int>& localPoint,
  PreparedMesh& subset)
{
  const int nf = subset.NumberOfFaces(), nv = subset.NumberOfPoints();
  subset.faceNormals.assign(nf, Vec3::Zero());
  subset.faceCentroids.assign(nf, Vec3::Zero());
  subset.vertexNormals.assign(nv, Vec3::Zero());
  subset.vertexAreas.assign(nv, 0.0);
  subset.vertexFaceOffsets.assign(nv + 1, 0);
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = subset.triangles[f];
    const Vec3 &a = subset.points[t[0]], &b = subset.points[t[1]], &c = subset.points[t[2]];
    subset.faceCentroids[f] = (a + b + c) / 3.0;
    const Vec3 cross = (b - a).cross(c - a);
    if (!subset.faceDegenerate[f])
      subset.faceNormals[f] = cross.normalized();
    for (int v : t)
    {
      subset.vertexNormals[v] += 0.5 * cross; // area-weighted
      subset.vertexAreas[v] += subset.faceAreas[f] / 3.0;
      ++subset.vertexFaceOffsets[v + 1];
    }
  }
  std::partial_sum(subset.vertexFaceOffsets.begin(),
    subset.vertexFaceOffsets.end(),
    subset.vertexFaceOffsets.begin());
  subset.vertexFaces.assign(subset.vertexFaceOffsets[nv], 0);
  std::vector<int> fill(subset.vertexFaceOffsets.begin(), subset.vertexFaceOffsets.end() - 1);
  for (int f = 0; f < nf; ++f)
    for (int v : subset.triangles[f])
      subset.vertexFaces[fill[v]++] = f;
  for (Vec3& n : subset.vertexNormals)
  {
    const double len = n.norm();
    n = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
  }
  for (int v = 0; v < mesh.NumberOfPoints(); ++v)
    if (localPoint[v] >= 0)
    {
      const Vec3& n = mesh.vertexNormals[v];
      if (n.allFinite() && n.norm() > 0.0)
      {
        Vec3& own = subset.vertexNormals[localPoint[v]];
        const Vec3 u = n.normalized();
        own = u.dot(own) < 0.0 ? Vec3(-u) : u;
      }
    }
}
}

namespace
{
bool PrepareSubset(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  const FaceEdgeUses* uses,
  PreparedMesh& subset)
{
  subset = PreparedMesh();
  const int nfAll = mesh.NumberOfFaces();
  std::vector<int> faces; // selected face ids of `mesh`, increasing
  std::vector<int> localFace(nfAll, -1), localPoint(mesh.NumberOfPoints(), -1);
  for (int f = 0; f < nfAll; ++f)
    if (faceMask[f])
    {
      const Triangle& t = mesh.triangles[f];
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
        return PrepareSelectedSoup(mesh, faceMask, subset);
      localFace[f] = static_cast<int>(faces.size());
      faces.push_back(f);
      for (int v : t)
        localPoint[v] = 0;
    }
  if (faces.empty())
    return false;
  for (int v = 0; v < mesh.NumberOfPoints(); ++v)
    if (localPoint[v] == 0)
    {
      localPoint[v] = subset.NumberOfPoints();
      subset.points.push_back(mesh.points[v]);
    }
  const int nf = static_cast<int>(faces.size());
  const int nv = subset.NumberOfPoints();
  subset.inputToWelded.resize(nv);
  std::iota(subset.inputToWelded.begin(), subset.inputToWelded.end(), 0);
  subset.weldedToInput = subset.inputToWelded;
  subset.triangles.resize(nf);
  for (int i = 0; i < nf; ++i)
    for (int k = 0; k < 3; ++k)
      subset.triangles[i][k] = localPoint[mesh.triangles[faces[i]][k]];

  // Bounds, areas and degeneracy exactly as PrepareMesh computes them (input orientation).
  ComputeBoundsAndAreas(subset);
  if (!(subset.totalArea > 0.0) || !(subset.diagonal > 0.0))
    return false;
  std::vector<char> onOpenEdge;
  if (!ConnectSubsetFaces(mesh, faceMask, uses, faces, localFace, subset, onOpenEdge))
    return PrepareSelectedSoup(mesh, faceMask, subset);
  OrientClosedParts(subset, onOpenEdge);
  SubsetNormalsAndIncidence(mesh, localPoint, subset);
  return true;
}
}

bool PrepareFaceSubset(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  PreparedMesh& subset)
{
  return PrepareSubset(mesh, faceMask, nullptr, subset);
}

bool PrepareFaceSubset(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  PreparedMesh& subset,
  const FaceEdgeUses& uses)
{
  if (uses.offsets.size() != 3 * static_cast<size_t>(mesh.NumberOfFaces()) + 1)
    return PrepareSubset(mesh, faceMask, nullptr, subset); // not this mesh's table
  return PrepareSubset(mesh, faceMask, &uses, subset);
}

FaceEdgeUses ComputeFaceEdgeUses(const PreparedMesh& mesh)
{
  FaceEdgeUses uses;
  const int nf = mesh.NumberOfFaces();
  uses.offsets.reserve(3 * static_cast<size_t>(nf) + 1);
  uses.offsets.push_back(0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
    {
      ForEachEdgeUse(mesh,
        nullptr,
        f,
        k,
        [&](int g, int direction)
        {
          uses.faces.push_back(g);
          uses.directions.push_back(static_cast<signed char>(direction));
        });
      uses.offsets.push_back(static_cast<int>(uses.faces.size()));
    }
  return uses;
}
}
