#include "FaceTree.h"

#include "PointTriangleDistance.h"

#include <algorithm>
#include <cmath>

namespace foldingmeshes
{
namespace
{
constexpr int LeafSize = 8;
}

FaceTree::FaceTree(const PreparedMesh& mesh)
  : Mesh(mesh)
{
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (!mesh.faceDegenerate[f])
      this->Order.push_back(f);
  this->Nodes.reserve(2 * this->Order.size() / LeafSize + 2);
  if (!this->Order.empty())
    this->Build(0, static_cast<int>(this->Order.size()));
}

int FaceTree::Build(int first, int count)
{
  const int index = static_cast<int>(this->Nodes.size());
  this->Nodes.push_back(Node());
  Node node;
  node.lo = Vec3::Constant(std::numeric_limits<double>::max());
  node.hi = -node.lo;
  Vec3 clo = node.lo, chi = node.hi, axis = Vec3::Zero();
  for (int k = first; k < first + count; ++k)
  {
    const int f = this->Order[k];
    for (int v : Mesh.triangles[f])
    {
      node.lo = node.lo.cwiseMin(Mesh.points[v]);
      node.hi = node.hi.cwiseMax(Mesh.points[v]);
      axis += Mesh.vertexNormals[v];
    }
    clo = clo.cwiseMin(Mesh.faceCentroids[f]);
    chi = chi.cwiseMax(Mesh.faceCentroids[f]);
  }
  node.clo = clo;
  node.chi = chi;
  node.coneCos = -1.0;
  node.coneAxis = Vec3::UnitX();
  if (axis.norm() > 0.0)
  {
    node.coneAxis = axis.normalized();
    double minCos = 1.0;
    for (int k = first; k < first + count; ++k)
      for (int v : Mesh.triangles[this->Order[k]])
        minCos = std::min(minCos, Mesh.vertexNormals[v].dot(node.coneAxis));
    // Convex combinations of normals stay in the cone only if it is narrower than 90 degrees.
    node.coneCos = minCos > 1e-6 ? minCos : -1.0;
    node.coneSin = std::sqrt(std::max(0.0, 1.0 - node.coneCos * node.coneCos));
  }
  if (count <= LeafSize)
  {
    node.first = first;
    node.count = count;
    node.left = node.right = -1;
    this->Nodes[index] = node;
    return index;
  }
  int axisIndex = 0;
  (chi - clo).maxCoeff(&axisIndex);
  const int half = count / 2;
  std::nth_element(this->Order.begin() + first,
    this->Order.begin() + first + half,
    this->Order.begin() + first + count,
    [&](int a, int b)
    {
      const double ca = Mesh.faceCentroids[a][axisIndex], cb = Mesh.faceCentroids[b][axisIndex];
      return ca != cb ? ca < cb : a < b;
    });
  node.first = first;
  node.count = 0;
  node.left = this->Build(first, half);
  node.right = this->Build(first + half, count - half);
  this->Nodes[index] = node;
  return index;
}

double FaceTree::BoxDistance2(const Vec3& lo, const Vec3& hi, const Vec3& p)
{
  const Vec3 d = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
  return d.squaredNorm();
}

template <typename Prune, typename Visit>
void FaceTree::Traverse(const Vec3& p, const double& best2, Prune prune, Visit visit) const
{
  // Depth-first, nearer child first; `best2` shrinks as `visit` finds closer faces.
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    if (BoxDistance2(node.lo, node.hi, p) > best2 || prune(node))
      continue;
    if (node.count > 0)
    {
      for (int k = node.first; k < node.first + node.count; ++k)
        visit(this->Order[k]);
      continue;
    }
    const double dl = BoxDistance2(this->Nodes[node.left].lo, this->Nodes[node.left].hi, p);
    const double dr = BoxDistance2(this->Nodes[node.right].lo, this->Nodes[node.right].hi, p);
    if (dl <= dr)
    {
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
    else
    {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
}

bool FaceTree::TryFace(const Vec3& p,
  const Vec3& normal,
  double cosLimit,
  int f,
  double& best2,
  Hit& hit) const
{
  const Triangle& t = Mesh.triangles[f];
  const ClosestPointOnTriangle cp =
    ClosestPointTriangle(p, Mesh.points[t[0]], Mesh.points[t[1]], Mesh.points[t[2]]);
  if (cp.squaredDistance > best2 || (cp.squaredDistance == best2 && hit.face >= 0 && f > hit.face))
    return false;
  const Vec3 n = cp.barycentric[0] * Mesh.vertexNormals[t[0]] +
    cp.barycentric[1] * Mesh.vertexNormals[t[1]] + cp.barycentric[2] * Mesh.vertexNormals[t[2]];
  const double len = n.norm();
  if (!(len > 0.0 && n.dot(normal) >= cosLimit * len))
    return false;
  best2 = cp.squaredDistance;
  hit.face = f;
  hit.point = cp.point;
  return true;
}

FaceTree::Hit FaceTree::ClosestCompatibleFace(const Vec3& p,
  const Vec3& normal,
  double cosLimit,
  double maxDistance,
  int hintFace) const
{
  Hit hit;
  if (this->Nodes.empty())
    return hit;
  // Angle between the query normal and a cone: compatible only if
  // angle(normal, axis) <= halfAngle + compatibilityAngle.
  // cos(a) < cos(h + l) = cos h cos l - sin h sin l, valid while h + l < 180 degrees.
  const double cosL = std::clamp(cosLimit, -1.0, 1.0);
  const double sinL = std::sqrt(1.0 - cosL * cosL);
  double best2 = maxDistance * maxDistance;
  // A compatible hint bounds the search from the start; the minimum (lowest id on ties) is
  // the same with or without it.
  if (hintFace >= 0 && hintFace < Mesh.NumberOfFaces() && !Mesh.faceDegenerate[hintFace])
    this->TryFace(p, normal, cosLimit, hintFace, best2, hit);
  this->Traverse(
    p,
    best2,
    [&](const Node& node)
    {
      // Skip when angle(normal, axis) > h + l, i.e. cos < cos(h + l); only meaningful
      // while h + l < 180 degrees, i.e. cos l > -cos h.
      if (node.coneCos <= -1.0)
        return false;
      const double cosSum = node.coneCos * cosL - node.coneSin * sinL;
      return cosL > -node.coneCos && normal.dot(node.coneAxis) < cosSum - 1e-12;
    },
    [&](int f) { this->TryFace(p, normal, cosLimit, f, best2, hit); });
  if (hit.face >= 0)
    hit.distance = std::sqrt(best2);
  return hit;
}

FaceTree::Hit FaceTree::ClosestFace(const Vec3& p, double maxDistance) const
{
  Hit hit;
  if (this->Nodes.empty())
    return hit;
  double best2 = maxDistance * maxDistance;
  this->Traverse(
    p,
    best2,
    [](const Node&) { return false; },
    [&](int f)
    {
      const Triangle& t = Mesh.triangles[f];
      const ClosestPointOnTriangle cp =
        ClosestPointTriangle(p, Mesh.points[t[0]], Mesh.points[t[1]], Mesh.points[t[2]]);
      if (cp.squaredDistance < best2 ||
        (cp.squaredDistance == best2 && (hit.face < 0 || f < hit.face)))
      {
        best2 = cp.squaredDistance;
        hit.face = f;
        hit.point = cp.point;
      }
    });
  if (hit.face >= 0)
    hit.distance = std::sqrt(best2);
  return hit;
}

int FaceTree::NearestCentroidFace(const Vec3& p) const
{
  int bestFace = -1;
  double best2 = std::numeric_limits<double>::infinity();
  if (this->Nodes.empty())
    return bestFace;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    if (BoxDistance2(node.clo, node.chi, p) > best2)
      continue;
    if (node.count > 0)
    {
      for (int k = node.first; k < node.first + node.count; ++k)
      {
        const int f = this->Order[k];
        const double d2 = (Mesh.faceCentroids[f] - p).squaredNorm();
        if (d2 < best2 || (d2 == best2 && f < bestFace))
        {
          best2 = d2;
          bestFace = f;
        }
      }
      continue;
    }
    const double dl = BoxDistance2(this->Nodes[node.left].clo, this->Nodes[node.left].chi, p);
    const double dr = BoxDistance2(this->Nodes[node.right].clo, this->Nodes[node.right].chi, p);
    if (dl <= dr)
    {
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
    else
    {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return bestFace;
}
}
