// Small helpers shared by the core unit tests: a non-fatal EXPECT that counts failures,
// conversion of procedural vtkPolyData meshes into the core's TriangleMesh / PreparedMesh,
// folding and unfolding, edge counts, volume, brute-force Hausdorff distance.
#ifndef foldingmeshes_CoreTestUtilities_h
#define foldingmeshes_CoreTestUtilities_h

#include "../TestExpect.h"
#include "FoldingTreeBuilder.h"
#include "FoldingTreeUnfolder.h"
#include "MeshPreparation.h"
#include "PointTriangleDistance.h"
#include "TriangleMesh.h"

#include <Eigen/Geometry>

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace coretest
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

#define EXPECT(cond, msg) FOLDINGMESHES_EXPECT(coretest::Failures(), cond, msg)

/// Two trees node by node: structure, planes, axes, epsilons, areas, discarded faces, every
/// leaf's data and the tree's input edges and verification, bit for bit (not the measured
/// times).
inline bool SameTree(const foldingmeshes::FoldingTree& a, const foldingmeshes::FoldingTree& b)
{
  auto sameEdges = [](const foldingmeshes::FoldingTree& x, const foldingmeshes::FoldingTree& y)
  {
    if (x.inputNonManifoldEdges.size() != y.inputNonManifoldEdges.size())
      return false;
    for (size_t k = 0; k < x.inputNonManifoldEdges.size(); ++k)
      if (x.inputNonManifoldEdges[k].a != y.inputNonManifoldEdges[k].a ||
        x.inputNonManifoldEdges[k].b != y.inputNonManifoldEdges[k].b ||
        x.inputNonManifoldEdges[k].faces != y.inputNonManifoldEdges[k].faces)
        return false;
    return x.inputBorderEdges == y.inputBorderEdges;
  };
  if (a.NumberOfNodes() != b.NumberOfNodes() || a.verifiedBound != b.verifiedBound ||
    a.pinnedFaces != b.pinnedFaces || a.verificationRounds != b.verificationRounds ||
    a.aborted != b.aborted || a.rootEpsilon != b.rootEpsilon ||
    a.numberOfDroppedFaces != b.numberOfDroppedFaces || !sameEdges(a, b))
    return false;
  for (int i = 0; i < a.NumberOfNodes(); ++i)
  {
    const foldingmeshes::FoldingNode &x = a.nodes[i], &y = b.nodes[i];
    if (x.kind != y.kind || x.parent != y.parent || x.children != y.children ||
      x.depth != y.depth || x.epsilon != y.epsilon || x.foldsAbove != y.foldsAbove ||
      x.numberOfFaces != y.numberOfFaces || x.area != y.area ||
      x.originalFaces != y.originalFaces || x.plane.normal != y.plane.normal ||
      x.plane.origin != y.plane.origin || x.leafReason != y.leafReason ||
      x.axis.origin != y.axis.origin || x.axis.direction != y.axis.direction ||
      x.rotationOrder != y.rotationOrder || x.discardedFaces != y.discardedFaces ||
      x.discardedOriginalFaces != y.discardedOriginalFaces ||
      x.projectedPoints != y.projectedPoints ||
      x.symmetricAreaFraction != y.symmetricAreaFraction || x.detectionRun != y.detectionRun ||
      x.detectionStarts != y.detectionStarts)
      return false;
    const foldingmeshes::FoldingLeafMesh &m = x.mesh, &n = y.mesh;
    if (m.points != n.points || m.triangles != n.triangles ||
      m.originalPointIds != n.originalPointIds || m.originalFaceIds != n.originalFaceIds ||
      m.tearMask != n.tearMask || m.planeMask != n.planeMask || m.projected != n.projected ||
      m.errorBudget != n.errorBudget || m.inputBoundary != n.inputBoundary ||
      m.mirroredFlags.size() != n.mirroredFlags.size())
      return false;
    for (size_t k = 0; k < m.mirroredFlags.size(); ++k)
      if (m.mirroredFlags[k].point != n.mirroredFlags[k].point ||
        m.mirroredFlags[k].level != n.mirroredFlags[k].level ||
        m.mirroredFlags[k].mirrorMask != n.mirroredFlags[k].mirrorMask ||
        m.mirroredFlags[k].flag != n.mirroredFlags[k].flag)
        return false;
  }
  return true;
}

/// Stops the test at once (for preconditions the rest depends on).
#define REQUIRE(cond, msg)                                                                         \
  do                                                                                               \
  {                                                                                                \
    EXPECT(cond, msg);                                                                             \
    if (!(cond))                                                                                   \
      std::exit(EXIT_FAILURE);                                                                     \
  } while (0)

inline int Finish(const char* name)
{
  if (coretest::Failures() > 0)
    std::printf("%s: %d check(s) FAILED\n", name, coretest::Failures());
  else
    std::printf("%s: all checks passed\n", name);
  return coretest::Failures() > 0 ? EXIT_FAILURE : EXIT_SUCCESS;
}

/// The triangles of an all-triangle vtkPolyData (exits if a cell is not a triangle).
inline foldingmeshes::TriangleMesh ToTriangleMesh(vtkPolyData* pd)
{
  foldingmeshes::TriangleMesh mesh;
  mesh.points.resize(static_cast<size_t>(pd->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    pd->GetPoint(i, mesh.points[static_cast<size_t>(i)].data());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    pd->GetCellPoints(c, ids);
    REQUIRE(ids->GetNumberOfIds() == 3, "procedural mesh cell " << c << " is not a triangle");
    mesh.triangles.push_back({ static_cast<int>(ids->GetId(0)),
      static_cast<int>(ids->GetId(1)),
      static_cast<int>(ids->GetId(2)) });
  }
  return mesh;
}

/// PrepareMesh without input normals; exits on failure.
inline foldingmeshes::PreparedMesh Prepare(const foldingmeshes::TriangleMesh& soup)
{
  foldingmeshes::PreparedMesh mesh;
  std::string error;
  const bool ok = foldingmeshes::PrepareMesh(soup, {}, mesh, error);
  REQUIRE(ok, "PrepareMesh failed: " << error);
  return mesh;
}

/// A tree made of one leaf holding `m` (no flags, no budgets), of the given root epsilon and
/// input diagonal.
inline foldingmeshes::FoldingTree LeafTree(const foldingmeshes::TriangleMesh& m,
  double rootEpsilon,
  double diagonal)
{
  using namespace foldingmeshes;
  FoldingTree t;
  FoldingNode leaf;
  leaf.kind = FoldingNodeKind::Leaf;
  leaf.leafReason = LeafReason::MinimumFaces;
  leaf.epsilon = rootEpsilon;
  leaf.numberOfFaces = static_cast<int>(m.triangles.size());
  FoldingLeafMesh& l = leaf.mesh;
  l.points = m.points;
  l.triangles = m.triangles;
  const int np = static_cast<int>(m.points.size());
  for (int v = 0; v < np; ++v)
    l.originalPointIds.push_back(v);
  for (int f = 0; f < static_cast<int>(m.triangles.size()); ++f)
    l.originalFaceIds.push_back(f);
  l.tearMask.assign(np, 0);
  l.planeMask.assign(np, 0);
  l.projected.assign(np, 0);
  l.inputBoundary.assign(np, 0);
  t.nodes.push_back(leaf);
  t.numberOfOriginalFaces = leaf.numberOfFaces;
  t.numberOfOriginalPoints = np;
  t.diagonal = diagonal;
  t.rootEpsilon = rootEpsilon;
  return t;
}

inline double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// UnfoldFoldingTree; exits on failure.
inline foldingmeshes::UnfoldedMesh Unfold(const foldingmeshes::FoldingTree& tree,
  const foldingmeshes::UnfoldOptions& options = {})
{
  foldingmeshes::UnfoldedMesh u;
  std::string error;
  const bool ok = foldingmeshes::UnfoldFoldingTree(tree, options, u, error);
  REQUIRE(ok, "UnfoldFoldingTree failed: " << error);
  return u;
}

/// Edges used by one triangle, by more than two, and by two running the same direction.
struct EdgeStats
{
  int open = 0;
  int nonManifold = 0;
  int misoriented = 0;
};

inline EdgeStats CountEdges(const std::vector<foldingmeshes::Triangle>& triangles)
{
  std::map<std::pair<int, int>, std::pair<int, int>> edges; // (min,max) -> (forward, backward)
  for (const foldingmeshes::Triangle& t : triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      auto& e = edges[{ std::min(a, b), std::max(a, b) }];
      (a < b ? e.first : e.second)++;
    }
  EdgeStats s;
  for (const auto& e : edges)
  {
    const int uses = e.second.first + e.second.second;
    s.open += uses == 1;
    s.nonManifold += uses > 2;
    s.misoriented += uses == 2 && e.second.first != 1;
  }
  return s;
}

/// The rigid motion the face-tree tests turn meshes by: x rotated by 0.7 radians about an
/// oblique axis and moved (axis-aligned slivers then need the tree's rotated box frame).
inline foldingmeshes::Vec3 Turned(const foldingmeshes::Vec3& x)
{
  static const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(0.7, foldingmeshes::Vec3(0.3, -0.8, 0.5).normalized()).toRotationMatrix();
  return rotation * x + foldingmeshes::Vec3(0.4, -1.3, 2.2);
}

/// A capped cylinder along z (radius r, length 2 h) of `segments` long side slivers and two fans.
inline foldingmeshes::TriangleMesh SliverCylinder(double r, double h, int segments)
{
  using foldingmeshes::Vec3;
  const double pi = 3.14159265358979323846;
  foldingmeshes::TriangleMesh m;
  for (int i = 0; i < segments; ++i)
  {
    const double a = 2.0 * pi * i / segments;
    m.points.push_back(Vec3(r * std::cos(a), r * std::sin(a), -h));
    m.points.push_back(Vec3(r * std::cos(a), r * std::sin(a), h));
  }
  const int bottom = static_cast<int>(m.points.size());
  m.points.push_back(Vec3(0, 0, -h));
  m.points.push_back(Vec3(0, 0, h));
  for (int i = 0; i < segments; ++i)
  {
    const int j = (i + 1) % segments;
    m.triangles.push_back({ 2 * i, 2 * j, 2 * j + 1 });
    m.triangles.push_back({ 2 * i, 2 * j + 1, 2 * i + 1 });
    m.triangles.push_back({ bottom, 2 * j, 2 * i });
    m.triangles.push_back({ bottom + 1, 2 * i + 1, 2 * j + 1 });
  }
  return m;
}

/// `m` with `count` large triangles across its bounding box (long slivers and fat ones in
/// turn, random orientation: a soup), drawn with uniform(a, b) and randomUnit().
template <typename Uniform, typename RandomUnit>
foldingmeshes::TriangleMesh WithLargeTriangles(foldingmeshes::TriangleMesh m,
  int count,
  Uniform uniform,
  RandomUnit randomUnit)
{
  using foldingmeshes::Vec3;
  Vec3 lo = m.points[0], hi = m.points[0];
  for (const Vec3& q : m.points)
  {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  for (int t = 0; t < count; ++t)
  {
    const int base = static_cast<int>(m.points.size());
    const Vec3 a(uniform(lo.x(), hi.x()), uniform(lo.y(), hi.y()), uniform(lo.z(), hi.z()));
    const Vec3 b(uniform(lo.x(), hi.x()), uniform(lo.y(), hi.y()), uniform(lo.z(), hi.z()));
    const double width = t % 2 == 0 ? 1e-3 : 0.3;
    const Vec3 c = 0.5 * (a + b) + width * (hi - lo).norm() * randomUnit();
    m.points.insert(m.points.end(), { a, b, c });
    m.triangles.push_back({ base, base + 1, base + 2 });
  }
  return m;
}

/// Total area of the triangles.
inline double SurfaceArea(const std::vector<foldingmeshes::Vec3>& p,
  const std::vector<foldingmeshes::Triangle>& t)
{
  double a = 0.0;
  for (const foldingmeshes::Triangle& f : t)
    a += 0.5 * (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]).norm();
  return a;
}

/// Signed volume enclosed by a closed triangle mesh (positive: oriented outward).
inline double SignedVolume(const std::vector<foldingmeshes::Vec3>& p,
  const std::vector<foldingmeshes::Triangle>& t)
{
  double v = 0.0;
  for (const foldingmeshes::Triangle& f : t)
    v += p[f[0]].dot(p[f[1]].cross(p[f[2]])) / 6.0;
  return v;
}

// Brute-force distances and a folding helper for the tree tests.
using foldingmeshes::FoldingTree;
using foldingmeshes::FoldingTreeOptions;
using foldingmeshes::Triangle;
using foldingmeshes::TriangleMesh;
using foldingmeshes::UnfoldedMesh;
using foldingmeshes::Vec3;

/// Brute force (samples: vertices and face centroids): largest distance from the vertices and face
/// centroids of A to the triangles of B.
inline double OneSided(const std::vector<Vec3>& pa,
  const std::vector<Triangle>& ta,
  const std::vector<Vec3>& pb,
  const std::vector<Triangle>& tb)
{
  std::vector<Vec3> samples = pa;
  for (const Triangle& t : ta)
    samples.push_back((pa[t[0]] + pa[t[1]] + pa[t[2]]) / 3.0);
  std::vector<Vec3> lo, hi;
  for (const Triangle& t : tb)
  {
    lo.push_back(pb[t[0]].cwiseMin(pb[t[1]]).cwiseMin(pb[t[2]]));
    hi.push_back(pb[t[0]].cwiseMax(pb[t[1]]).cwiseMax(pb[t[2]]));
  }
  double worst = 0.0;
  size_t hint = 0;
  for (const Vec3& q : samples)
  {
    const Triangle& h = tb[hint];
    double best2 =
      foldingmeshes::ClosestPointTriangle(q, pb[h[0]], pb[h[1]], pb[h[2]]).squaredDistance;
    for (size_t f = 0; f < tb.size(); ++f)
    {
      const Vec3 d = (lo[f] - q).cwiseMax(q - hi[f]).cwiseMax(Vec3::Zero());
      if (d.squaredNorm() >= best2)
        continue;
      const Triangle& t = tb[f];
      const double d2 =
        foldingmeshes::ClosestPointTriangle(q, pb[t[0]], pb[t[1]], pb[t[2]]).squaredDistance;
      if (d2 < best2)
      {
        best2 = d2;
        hint = f;
      }
    }
    worst = std::max(worst, std::sqrt(best2));
  }
  return worst;
}

/// Symmetric Hausdorff distance between a and b, sampled like OneSided.
inline double Hausdorff(const TriangleMesh& a, const UnfoldedMesh& b)
{
  return std::max(OneSided(a.points, a.triangles, b.points, b.triangles),
    OneSided(b.points, b.triangles, a.points, a.triangles));
}

/// Bounding-box diagonal of a mesh's points.
inline double Diagonal(const TriangleMesh& m)
{
  Vec3 lo = m.points[0], hi = m.points[0];
  for (const Vec3& p : m.points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

/// BuildFoldingTree with root epsilon `epsilon`; exits on failure.
inline FoldingTree Fold(const TriangleMesh& m, double epsilon, FoldingTreeOptions o = {})
{
  o.epsilon = epsilon;
  FoldingTree tree;
  std::string error;
  const bool ok = foldingmeshes::BuildFoldingTree(m, {}, o, tree, error);
  REQUIRE(ok, "BuildFoldingTree failed: " << error);
  return tree;
}
}

#endif
