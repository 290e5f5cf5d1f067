#include "FaceTree.h"

#include "FaceTreeFrame.h"

#include "PointTriangleDistance.h"

#include "ParallelTasks.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace foldingmeshes
{
namespace
{
/// Subtrees whose two halves hold at least half this many faces each build them in parallel.
constexpr int ParallelBuildFaces = 4096;
/// The constructor's areaSplitDepth at most: from that depth on the splits are at the median
/// face (at most log2(faces) levels more), so that the traversal's stack of 128 entries always
/// holds a path - the area rule may peel off few faces per level.
constexpr int MaximumAreaSplitDepth = 64;
/// A node is skipped only when its box is farther than sqrt(best2) + E, with
/// E = PruneAbsoluteMargin * (|p| + the mesh's coordinate scale): the query's and the box
/// corners' coordinates, rotated into the box frame (if it is not the identity) and taken
/// relative to the tree's Origin, are within ~1e-15 of that scale of the exact ones (the float
/// boxes are rounded outward from those), and the frame is orthonormal within ~1e-15, so the
/// box's computed distance exceeds every true distance to its faces by far less than E. With
/// (a + E)^2 <= a^2 (1 + eta) + E^2 (1 + 1/eta), eta = PruneRelativeMargin, the test
/// needs no square root.
constexpr double PruneRelativeMargin = 1e-6;
constexpr double PruneAbsoluteMargin = 1e-12;

/// cosLimit clamped to [-1, 1] and the sine of its angle, for NormalCone::Excludes (the sine
/// from (1 - c)(1 + c): accurate for c near 1).
std::pair<double, double> ConeLimits(double cosLimit)
{
  const double c = std::clamp(cosLimit, -1.0, 1.0);
  return { c, std::sqrt((1.0 - c) * (1.0 + c)) };
}
}

double FaceTree::PruneAdd(const Vec3& p) const
{
  const double e =
    PruneAbsoluteMargin * std::sqrt(3.0) * (p.cwiseAbs().maxCoeff() + this->CoordinateScale);
  return e * e * (1.0 + 1.0 / PruneRelativeMargin);
}

namespace
{
/// x rounded to a float not above (Down) or not below (Up) it.
float Down(double x)
{
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}
float Up(double x)
{
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}
}

FaceTree::FloatBox FaceTree::FloatBox::Around(const Vec3& lo, const Vec3& hi)
{
  FloatBox box;
  for (int a = 0; a < 3; ++a)
  {
    box.lo[a] = Down(lo[a]);
    box.hi[a] = Up(hi[a]);
  }
  return box;
}

FaceTree::FloatCone FaceTree::FloatCone::Of(const NormalCone& cone)
{
  FloatCone c;
  c.axis = cone.axis.cast<float>();
  c.cos = cone.cos <= -1.0 ? -1.0f : Down(cone.cos);
  c.sin = cone.cos <= -1.0 ? 0.0f : Up(cone.sin);
  return c;
}

FaceTree::FaceTree(const PreparedMesh& mesh, int areaSplitDepth)
  : Mesh(mesh)
  , AreaSplitDepth(std::clamp(areaSplitDepth, 0, MaximumAreaSplitDepth))
{
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (!mesh.faceDegenerate[f])
      this->Order.push_back(f);
  if (!this->Order.empty())
  {
    this->Frame = BoxFrame(mesh, this->Order);
    this->Rotated = !this->Frame.isIdentity(0.0);
    const int count = static_cast<int>(this->Order.size());
    const int large = this->Large = this->PutLargeFacesFirst();
    const std::vector<Vec3>* points = &mesh.points;
    const std::vector<Vec3>* centroids = &mesh.faceCentroids;
    std::vector<Vec3> framePoints, frameCentroids;
    // The margins of PruneAdd.
    this->PruneScale = 1.0 + PruneRelativeMargin;
    for (const Vec3& x : mesh.points)
      this->CoordinateScale = std::max(this->CoordinateScale, x.cwiseAbs().maxCoeff());
    if (this->Rotated)
    {
      framePoints.resize(mesh.points.size());
      frameCentroids.resize(mesh.faceCentroids.size());
      ForRanges(static_cast<vtkIdType>(framePoints.size()),
        0,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType v = begin; v < end; ++v)
            framePoints[v] = this->Frame * mesh.points[v];
        });
      for (int f : this->Order)
        frameCentroids[f] = this->Frame * mesh.faceCentroids[f];
      points = &framePoints;
      centroids = &frameCentroids;
    }
    // Each face's box in the frame, for the nodes' boxes and the choice of split axis.
    std::vector<FaceBox> boxes(mesh.NumberOfFaces());
    ForRanges(count,
      0,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          const int f = this->Order[k];
          const Triangle& t = mesh.triangles[f];
          const std::vector<Vec3>& x = *points;
          boxes[f].lo = x[t[0]].cwiseMin(x[t[1]]).cwiseMin(x[t[2]]);
          boxes[f].hi = x[t[0]].cwiseMax(x[t[1]]).cwiseMax(x[t[2]]);
        }
      });
    // The nodes' boxes are stored relative to the centre of the faces' box (float keeps
    // 24 bits of a coordinate: of the mesh's own size, not of its distance from the origin).
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
    for (int f : this->Order)
    {
      lo = lo.cwiseMin(boxes[f].lo);
      hi = hi.cwiseMax(boxes[f].hi);
    }
    this->Origin = 0.5 * lo + 0.5 * hi;
    if (!this->Origin.allFinite())
      this->Origin = Vec3::Zero();
    this->Build(0, count, 0, boxes, *centroids, this->Nodes, large);
    // The centroids' boxes, children (later in preorder) before their parents.
    this->CentroidBoxes.resize(this->Nodes.size());
    for (size_t i = this->Nodes.size(); i-- > 0;)
    {
      const Node& node = this->Nodes[i];
      FloatBox& box = this->CentroidBoxes[i];
      if (node.count == 0)
      {
        const FloatBox &l = this->CentroidBoxes[node.left], &r = this->CentroidBoxes[node.right];
        box.lo = l.lo.cwiseMin(r.lo);
        box.hi = l.hi.cwiseMax(r.hi);
        continue;
      }
      Vec3 clo = Vec3::Constant(std::numeric_limits<double>::max()), chi = -clo;
      for (int k = node.first; k < node.first + node.count; ++k)
      {
        clo = clo.cwiseMin((*centroids)[this->Order[k]]);
        chi = chi.cwiseMax((*centroids)[this->Order[k]]);
      }
      box = FloatBox::Around(clo - this->Origin, chi - this->Origin);
    }
    std::vector<std::pair<int, int>> stack{ { 0, 0 } }; // node, depth
    while (!stack.empty())
    {
      const auto [index, depth] = stack.back();
      stack.pop_back();
      this->MaximumDepth = std::max(this->MaximumDepth, depth);
      if (this->Nodes[index].count == 0)
        stack.insert(stack.end(),
          { { this->Nodes[index].left, depth + 1 }, { this->Nodes[index].right, depth + 1 } });
    }
  }
  this->OrderIndex.assign(mesh.NumberOfFaces(), -1);
  // Appended (reserve, not resize: value-initialising PackedFace zeroes every byte first).
  this->Packed.reserve(this->Order.size());
  for (size_t k = 0; k < this->Order.size(); ++k)
  {
    const int f = this->Order[k];
    const Triangle& t = mesh.triangles[f];
    PackedFace face;
    face.a = mesh.points[t[0]];
    face.b = mesh.points[t[1]];
    face.c = mesh.points[t[2]];
    face.center = (face.a + face.b + face.c) / 3.0;
    face.radius = std::sqrt(std::max({ (face.a - face.center).squaredNorm(),
      (face.b - face.center).squaredNorm(),
      (face.c - face.center).squaredNorm() }));
    face.regular = IsRegularTriangle(face.a, face.b, face.c);
    // The unit normal's direction is off by about 1e-16 L^2 / |cross| radians (L: the longest
    // edge): below 1e-9 unless the face is a sliver, which keeps the sphere bound.
    const Vec3 cross = (face.b - face.a).cross(face.c - face.a);
    const double longest2 = std::max({ (face.b - face.a).squaredNorm(),
      (face.c - face.a).squaredNorm(),
      (face.c - face.b).squaredNorm() });
    face.planeBound = face.regular && cross.squaredNorm() > 1e-12 * longest2 * longest2;
    face.normal = face.planeBound ? Vec3(cross.normalized()) : Vec3::Zero();
    face.cone = NormalCone::Around(
      [&](const auto& visit)
      {
        for (int v : t)
          visit(mesh.vertexNormals[v]);
      });
    this->Packed.push_back(face);
    this->OrderIndex[f] = static_cast<int>(k);
  }
}

bool FaceTree::CompatibleAt(int face,
  const ClosestPointOnTriangle& cp,
  const Vec3& normal,
  double cosLimit) const
{
  const Triangle& t = Mesh.triangles[face];
  const Vec3 n = cp.barycentric[0] * Mesh.vertexNormals[t[0]] +
    cp.barycentric[1] * Mesh.vertexNormals[t[1]] + cp.barycentric[2] * Mesh.vertexNormals[t[2]];
  const double len = n.norm();
  return len > 0.0 && n.dot(normal) >= cosLimit * len;
}

ClosestPointOnTriangle FaceTree::ClosestPoint(const Vec3& p, int k) const
{
  const PackedFace& face = this->Packed[k];
  return face.regular ? ClosestPointRegularTriangle(p, face.a, face.b, face.c)
                      : ClosestPointTriangle(p, face.a, face.b, face.c);
}

[[gnu::always_inline]] inline bool FaceTree::Beyond(const Vec3& p, int k, double best2) const
{
  const PackedFace& face = this->Packed[k];
  const Vec3 pc = p - face.center;
  const double d2 = pc.squaredNorm();
  const double r = face.radius;
  const double limit = best2 * (1.0 + 1e-9);
  if (!face.planeBound)
  {
    if (d2 <= r * r)
      return false;
    // <= the distance to the triangle; less the rounding of the subtraction (about 1e-16
    // (|pc| + r)), without which a best distance within rounding of zero could prune a
    // sliver the search must still reach (the answer would depend on the hint face).
    const double d = std::sqrt(d2);
    const double gap = d - r - 1e-12 * (d + r);
    return gap > 0.0 && gap * gap > limit;
  }
  // |p - x|^2 = h^2 + |q - x|^2 for x on the plane (q: the foot of p), |q - x| >= rho - r.
  // With the normal within 1e-9 radians (constructor) the computed bound, and the computed
  // distance of any point of the face, are within 1e-8 (|pc| + r)^2 of the exact ones.
  const double h = face.normal.dot(pc);
  const double h2 = h * h;
  const double slack = 1e-8 * (d2 + r * r) * 2.0; // >= 1e-8 (|pc| + r)^2
  if (h2 > limit + slack)
    return true;
  const double rho2 = d2 - h2;
  if (rho2 <= r * r)
    return false;
  const double lateral = std::sqrt(rho2) - r;
  return h2 + lateral * lateral > limit + slack;
}

template <typename ForEachNormal>
FaceTree::NormalCone FaceTree::NormalCone::Around(ForEachNormal forEachNormal)
{
  NormalCone cone;
  Vec3 axis = Vec3::Zero();
  forEachNormal([&](const Vec3& n) { axis += n; });
  if (!(axis.norm() > 0.0))
    return cone;
  cone.axis = axis.normalized();
  double minCos = 1.0, maxSin = 0.0;
  forEachNormal(
    [&](const Vec3& n)
    {
      minCos = std::min(minCos, n.dot(cone.axis));
      maxSin = std::max(maxSin, n.cross(cone.axis).norm());
    });
  // Convex combinations of normals stay in the cone only if it is narrower than 90 degrees.
  // The sine also from the cross products: sqrt(1 - cos^2) is 0 for normals less than about
  // 1.5e-8 radians apart (cos rounds to 1), a cone far narrower than the normals' spread.
  if (minCos > 1e-6)
  {
    cone.cos = minCos;
    cone.sin = std::min(1.0, std::max(std::sqrt(std::max(0.0, 1.0 - minCos * minCos)), maxSin));
  }
  else
    cone.axis = Vec3::UnitX();
  return cone;
}

int FaceTree::Build(int first,
  int count,
  int depth,
  const std::vector<FaceBox>& boxes,
  const std::vector<Vec3>& centroids,
  std::vector<Node>& nodes,
  int split)
{
  Node node;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  Vec3 clo = lo, chi = hi;
  for (int k = first; k < first + count; ++k)
  {
    const int f = this->Order[k];
    lo = lo.cwiseMin(boxes[f].lo);
    hi = hi.cwiseMax(boxes[f].hi);
    clo = clo.cwiseMin(centroids[f]);
    chi = chi.cwiseMax(centroids[f]);
  }
  node.box = FloatBox::Around(lo - this->Origin, hi - this->Origin);
  node.cone = FloatCone::Of(NormalCone::Around(
    [&](const auto& visit)
    {
      for (int k = first; k < first + count; ++k)
        for (int v : Mesh.triangles[this->Order[k]])
          visit(Mesh.vertexNormals[v]);
    }));
  node.first = first;
  node.count = count <= LeafSize ? count : 0;
  node.left = node.right = -1;
  const int index = static_cast<int>(nodes.size());
  nodes.push_back(node);
  if (count <= LeafSize)
    return index;
  assert(split == 0 || split < count); // PutLargeFacesFirst's split
  const int half = split > 0 ? split : this->Split(first, count, depth, boxes, centroids, clo, chi);
  // Preorder: the first half's subtree follows its parent, then the second half's. Two large
  // halves (2,048 faces and more each) are built in parallel into nodes of their own, appended
  // after (their links moved by where they land): the halves touch disjoint ranges of Order, so
  // the tree is the same for any thread count. A split that peels off few faces, and the root's
  // split of the large faces, build their halves one after the other, so that the larger
  // half's own halves are built in parallel (and its nodes are not copied).
  const int firsts[2] = { first, first + half }, counts[2] = { half, count - half };
  int children[2];
  if (split > 0 || std::min(half, count - half) < ParallelBuildFaces / 2)
    for (int c = 0; c < 2; ++c)
      children[c] = this->Build(firsts[c], counts[c], depth + 1, boxes, centroids, nodes);
  else
  {
    std::vector<Node> halves[2];
    ForRanges(2,
      1,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType c = begin; c < end; ++c)
          this->Build(firsts[c], counts[c], depth + 1, boxes, centroids, halves[c]);
      });
    for (int c = 0; c < 2; ++c)
    {
      const int offset = children[c] = static_cast<int>(nodes.size());
      for (Node& n : halves[c])
      {
        if (n.count == 0)
        {
          n.left += offset;
          n.right += offset;
        }
        nodes.push_back(n);
      }
    }
  }
  nodes[index].left = children[0];
  nodes[index].right = children[1];
  return index;
}

template <typename Prune, typename Visit>
void FaceTree::Traverse(const Vec3& p, const double& best2, Prune prune, Visit visit) const
{
  // Depth-first, nearer child first; `best2` shrinks as `visit` finds closer faces. Each
  // node's box distance is computed once, when its parent pushes it.
  const Vec3 q = this->InFrame(p);
  const double scale = this->PruneScale, add = this->PruneAdd(p);
  int stack[128];
  double stackDistance2[128];
  int top = 0;
  stack[top] = 0;
  stackDistance2[top++] = this->Nodes[0].box.Distance2(q);
  while (top > 0)
  {
    --top;
    if (stackDistance2[top] > best2 * scale + add)
      continue;
    const Node& node = this->Nodes[stack[top]];
    if (prune(node))
      continue;
    if (node.count > 0)
    {
      for (int k = node.first; k < node.first + node.count; ++k)
        visit(k);
      continue;
    }
    const double dl = this->Nodes[node.left].box.Distance2(q);
    const double dr = this->Nodes[node.right].box.Distance2(q);
    const bool leftFirst = dl <= dr;
    stack[top] = leftFirst ? node.right : node.left;
    stackDistance2[top++] = leftFirst ? dr : dl;
    stack[top] = leftFirst ? node.left : node.right;
    stackDistance2[top++] = leftFirst ? dl : dr;
  }
}

template <typename Excluded>
bool FaceTree::TryFace(const Vec3& p,
  const Vec3& normal,
  double cosLimit,
  double sinLimit,
  int k,
  double& best2,
  Hit& hit,
  Excluded excluded) const
{
  // No interpolated normal of the face is compatible (on a box or a thin plate, most faces
  // near a mirrored point face away from it): no closest point to compute.
  if (this->Packed[k].cone.Excludes(normal, std::clamp(cosLimit, -1.0, 1.0), sinLimit))
    return false;
  if (this->Beyond(p, k, best2))
    return false;
  const int f = this->Order[k];
  if (excluded(f))
    return false;
  const ClosestPointOnTriangle cp = this->ClosestPoint(p, k);
  if (cp.squaredDistance > best2 || (cp.squaredDistance == best2 && hit.face >= 0 && f > hit.face))
    return false;
  if (!this->CompatibleAt(f, cp, normal, cosLimit))
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
  int hintFace,
  const std::vector<char>* excludedFaces) const
{
  if (excludedFaces)
    return this->ClosestCompatibleFaceAmong(p,
      normal,
      cosLimit,
      maxDistance,
      hintFace,
      [excludedFaces](int f) { return (*excludedFaces)[f] != 0; });
  return this->ClosestCompatibleFaceAmong(
    p, normal, cosLimit, maxDistance, hintFace, [](int) { return false; });
}

template <typename Excluded>
FaceTree::Hit FaceTree::ClosestCompatibleFaceAmong(const Vec3& p,
  const Vec3& normal,
  double cosLimit,
  double maxDistance,
  int hintFace,
  Excluded excluded) const
{
  Hit hit;
  if (this->Nodes.empty())
    return hit;
  // For the normal cones of nodes and faces (NormalCone::Excludes).
  const std::pair<double, double> cone = ConeLimits(cosLimit);
  const double cosL = cone.first, sinL = cone.second;
  double best2 = maxDistance * maxDistance;
  // A compatible hint bounds the search from the start; the minimum (lowest id on ties) is
  // the same with or without it (Beyond's bounds hold with a slack above their rounding, also
  // at best distances within rounding of zero; TestFaceTreeHints).
  if (hintFace >= 0 && hintFace < Mesh.NumberOfFaces() && this->OrderIndex[hintFace] >= 0)
    this->TryFace(p, normal, cosLimit, sinL, this->OrderIndex[hintFace], best2, hit, excluded);
  this->Traverse(
    p,
    best2,
    [&](const Node& node) { return node.cone.Excludes(normal, cosL, sinL); },
    [&](int k) { this->TryFace(p, normal, cosLimit, sinL, k, best2, hit, excluded); });
  if (hit.face >= 0)
    hit.distance = std::sqrt(best2);
  return hit;
}

bool FaceTree::HasCompatibleFaceWithin(const Vec3& p,
  const Vec3& normal,
  double cosLimit,
  double maxDistance) const
{
  if (this->Nodes.empty())
    return false;
  const std::pair<double, double> cone = ConeLimits(cosLimit);
  const double cosL = cone.first, sinL = cone.second;
  // best2 stays maxDistance^2 until a face is taken; then every node left is pruned.
  double best2 = maxDistance * maxDistance;
  Hit hit;
  bool found = false;
  this->Traverse(
    p,
    best2,
    [&](const Node& node) { return found || node.cone.Excludes(normal, cosL, sinL); },
    [&](int k)
    {
      found =
        found || this->TryFace(p, normal, cosLimit, sinL, k, best2, hit, [](int) { return false; });
    });
  return found;
}

bool FaceTree::CompatibleFaceHit(const Vec3& p,
  const Vec3& normal,
  double cosLimit,
  double maxDistance,
  int face,
  Hit& hit) const
{
  if (face < 0 || face >= Mesh.NumberOfFaces() || this->OrderIndex[face] < 0)
    return false;
  const ClosestPointOnTriangle cp = this->ClosestPoint(p, this->OrderIndex[face]);
  if (!(cp.squaredDistance <= maxDistance * maxDistance) ||
    !this->CompatibleAt(face, cp, normal, cosLimit))
    return false;
  hit.face = face;
  hit.point = cp.point;
  hit.distance = std::sqrt(cp.squaredDistance);
  return true;
}

FaceTree::Hit FaceTree::ClosestFace(const Vec3& p,
  double maxDistance,
  const std::vector<char>* excluded) const
{
  Hit hit;
  if (this->Nodes.empty())
    return hit;
  double best2 = maxDistance * maxDistance;
  this->Traverse(
    p,
    best2,
    [](const Node&) { return false; },
    [&](int k)
    {
      if (this->Beyond(p, k, best2))
        return;
      const int f = this->Order[k];
      if (excluded && (*excluded)[f])
        return;
      const ClosestPointOnTriangle cp = this->ClosestPoint(p, k);
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
  // As Traverse, on the boxes of the face centroids.
  const Vec3 q = this->InFrame(p);
  const double scale = this->PruneScale, add = this->PruneAdd(p);
  int stack[128];
  double stackDistance2[128];
  int top = 0;
  stack[top] = 0;
  stackDistance2[top++] = this->CentroidBoxes[0].Distance2(q);
  while (top > 0)
  {
    --top;
    if (stackDistance2[top] > best2 * scale + add)
      continue;
    const Node& node = this->Nodes[stack[top]];
    if (node.count > 0)
    {
      for (int k = node.first; k < node.first + node.count; ++k)
      {
        const int f = this->Order[k];
        const double d2 = (this->Packed[k].center - p).squaredNorm();
        if (d2 < best2 || (d2 == best2 && f < bestFace))
        {
          best2 = d2;
          bestFace = f;
        }
      }
      continue;
    }
    const double dl = this->CentroidBoxes[node.left].Distance2(q);
    const double dr = this->CentroidBoxes[node.right].Distance2(q);
    const bool leftFirst = dl <= dr;
    stack[top] = leftFirst ? node.right : node.left;
    stackDistance2[top++] = leftFirst ? dr : dl;
    stack[top] = leftFirst ? node.left : node.right;
    stackDistance2[top++] = leftFirst ? dl : dr;
  }
  return bestFace;
}
}
