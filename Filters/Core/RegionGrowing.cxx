#include "RegionGrowing.h"
#include "UnionFind.h"

#include <numeric>

namespace foldingmeshes
{
namespace
{
int FirstSelectedFace(const PreparedMesh& mesh, const std::vector<char>& mask, int v)
{
  for (int k = mesh.vertexFaceOffsets[v]; k < mesh.vertexFaceOffsets[v + 1]; ++k)
    if (mask[mesh.vertexFaces[k]])
      return mesh.vertexFaces[k];
  return -1;
}
}

std::vector<char> FacesWithVerticesWithin(const PreparedMesh& mesh,
  const std::vector<double>& d,
  double threshold,
  bool strict)
{
  const int nf = mesh.NumberOfFaces();
  std::vector<char> mask(nf, 0);
  for (int f = 0; f < nf; ++f)
  {
    bool inside = true;
    for (int v : mesh.triangles[f])
      inside = inside && (strict ? d[v] < threshold : d[v] <= threshold);
    mask[f] = inside;
  }
  return mask;
}

int LabelConnectedRegions(const PreparedMesh& mesh,
  const std::vector<char>& mask,
  std::vector<int>& labels)
{
  const int nf = mesh.NumberOfFaces();
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < nf; ++f)
  {
    if (!mask[f])
      continue;
    // Each adjacency is listed from both faces: joining from the lower one is enough.
    for (int k = mesh.faceNeighborOffsets[f]; k < mesh.faceNeighborOffsets[f + 1]; ++k)
    {
      const int g = mesh.faceNeighbors[k];
      if (g > f && mask[g])
        Unite(parent, f, g);
    }
  }
  for (const auto& link : mesh.proximityLinks)
  {
    const int a = FirstSelectedFace(mesh, mask, link.first);
    const int b = FirstSelectedFace(mesh, mask, link.second);
    if (a >= 0 && b >= 0)
      Unite(parent, a, b);
  }
  labels.assign(nf, -1);
  std::vector<int> regionOfRoot(nf, -1);
  int count = 0;
  for (int f = 0; f < nf; ++f)
  {
    if (!mask[f])
      continue;
    const int r = FindRoot(parent, f);
    if (regionOfRoot[r] < 0)
      regionOfRoot[r] = count++;
    labels[f] = regionOfRoot[r];
  }
  return count;
}

std::vector<char> LargestConnectedRegion(const PreparedMesh& mesh, const std::vector<char>& mask)
{
  std::vector<int> labels;
  const int count = LabelConnectedRegions(mesh, mask, labels);
  std::vector<double> area(count, 0.0);
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (labels[f] >= 0)
      area[labels[f]] += mesh.faceAreas[f];
  int best = -1;
  for (int r = 0; r < count; ++r)
    if (best < 0 || area[r] > area[best])
      best = r;
  std::vector<char> region(mesh.NumberOfFaces(), 0);
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    region[f] = best >= 0 && labels[f] == best;
  return region;
}

std::vector<char> LargestRegionAndWholeParts(const PreparedMesh& mesh,
  const std::vector<char>& mask)
{
  const int nf = mesh.NumberOfFaces();
  std::vector<int> labels, parts;
  const int count = LabelConnectedRegions(mesh, mask, labels);
  if (count < 2 || LabelConnectedRegions(mesh, std::vector<char>(nf, 1), parts) < 2)
    return LargestConnectedRegion(mesh, mask);
  // A part is whole in the mask when every face of it is in the mask, its degenerate faces
  // apart (they have no distance of their own: they go with their part).
  std::vector<char> whole(nf, 1), touched(nf, 0);
  for (int f = 0; f < nf; ++f)
  {
    if (mask[f])
      touched[parts[f]] = 1;
    else if (!mesh.faceDegenerate[f])
      whole[parts[f]] = 0;
  }
  // The largest region that is not made of whole parts only (a whole part larger than it must
  // not take its place), then every whole part.
  std::vector<double> area(count, 0.0);
  std::vector<char> onlyWhole(count, 1);
  for (int f = 0; f < nf; ++f)
    if (labels[f] >= 0)
    {
      area[labels[f]] += mesh.faceAreas[f];
      if (!whole[parts[f]])
        onlyWhole[labels[f]] = 0;
    }
  int best = -1;
  for (int r = 0; r < count; ++r)
    if (!onlyWhole[r] && (best < 0 || area[r] > area[best]))
      best = r;
  std::vector<char> region(nf, 0);
  for (int f = 0; f < nf; ++f)
    region[f] = (best >= 0 && labels[f] == best) || (whole[parts[f]] && touched[parts[f]]);
  return region;
}

bool HasSeveralParts(const PreparedMesh& mesh)
{
  std::vector<int> parts;
  return LabelConnectedRegions(mesh, std::vector<char>(mesh.NumberOfFaces(), 1), parts) > 1;
}

double RegionArea(const PreparedMesh& mesh, const std::vector<char>& mask)
{
  double area = 0.0;
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (mask[f])
      area += mesh.faceAreas[f];
  return area;
}

Vec3 RegionCentroid(const PreparedMesh& mesh, const std::vector<char>& mask)
{
  Vec3 centroid = Vec3::Zero();
  double total = 0.0;
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (mask[f])
    {
      centroid += mesh.faceAreas[f] * mesh.faceCentroids[f];
      total += mesh.faceAreas[f];
    }
  return total > 0.0 ? Vec3(centroid / total) : centroid;
}
}
