// Where does unfold(fold(M)) depart from M? Per mesh: the distance of the stored leaf points to
// M (by kind: projected onto a fold plane, on a fold plane, other), then the symmetric
// Hausdorff distance / diagonal of the unfolded mesh after each reconstruction step (raw
// union, fold-line slab merge, stitching, zipper, gap filling, smoothing), with open edges.
// Not a test: numbers to find which step breaks the error bound.
//
//   BenchmarkUnfoldingError [--tolerance F] MESH...   (F: root epsilon / diagonal, default 0.02)
#include "Core/FoldingTreeUnfolder.h"
#include "Core/SurfaceDistance.h"
#include "MeshIO.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeIO.h"
#include "vtkTriangleMeshAdapter.h"

#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using namespace foldingmeshes;

namespace
{
void Report(const char* label,
  const FoldingTree& tree,
  const TriangleMesh& original,
  const UnfoldOptions& options)
{
  UnfoldedMesh m;
  std::string error;
  if (!UnfoldFoldingTree(tree, options, m, error))
  {
    std::printf("  %-10s error %s\n", label, error.c_str());
    return;
  }
  TriangleMesh u;
  u.points = m.points;
  u.triangles = m.triangles;
  const SurfaceComparison c = CompareSurfaces(u, original);
  int worst = 0;
  for (int v = 0; v < m.NumberOfPoints(); ++v)
    if (c.aPointDistances[v] > c.aPointDistances[worst])
      worst = v;
  const UnfoldCopy& copy = m.copies[m.pointCopy[worst]];
  const FoldingLeafMesh& leaf = tree.nodes[copy.leaf].mesh;
  int local = -1;
  for (int v = 0; v < leaf.NumberOfPoints(); ++v)
    if (leaf.originalPointIds[v] == m.pointOriginalIds[worst])
      local = v;
  double leafDistance = -1;
  if (local >= 0)
  {
    const SurfaceDistanceQuery q(original);
    leafDistance = q.Distance(leaf.points[local]) / tree.diagonal;
  }
  // Open edges: on a fold plane (fold line not closed), or elsewhere (seams, input border).
  int onPlane = 0, elsewhere = 0;
  std::vector<std::pair<Vec3, std::pair<int, int>>> openMid;
  {
    std::map<std::pair<int, int>, int> edges;
    for (const Triangle& t : m.triangles)
      for (int k = 0; k < 3; ++k)
        ++edges[{ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) }];
    std::vector<Plane> planes;
    for (const FoldingNode& n : tree.nodes)
      if (n.kind == FoldingNodeKind::Folding)
        for (const UnfoldCopy& c : m.copies)
        {
          // The plane as placed in this copy: all images of fold planes.
          Plane q;
          q.normal = (c.linear * n.plane.normal).normalized();
          q.origin = c.linear * n.plane.origin + c.translation;
          planes.push_back(q);
        }
    for (const auto& e : edges)
      if (e.second == 1)
      {
        const Vec3 a = m.points[e.first.first], b = m.points[e.first.second];
        bool on = false;
        for (const Plane& q : planes)
          on = on ||
            (std::abs(q.SignedDistance(a)) < 1e-6 * tree.diagonal &&
              std::abs(q.SignedDistance(b)) < 1e-6 * tree.diagonal);
        on ? ++onPlane : ++elsewhere;
        if (!on)
          openMid.push_back({ 0.5 * (a + b), { e.first.first, e.first.second } });
      }
    // Crack widths: distance from an open edge's midpoint to the nearest open edge not
    // sharing a vertex with it.
    int bins[4] = { 0, 0, 0, 0 };
    const double eps = tree.rootEpsilon;
    for (size_t i = 0; i < openMid.size(); ++i)
    {
      double best = 1e300;
      for (size_t j = 0; j < openMid.size(); ++j)
      {
        const auto& p = openMid[i].second;
        const auto& q = openMid[j].second;
        if (p.first == q.first || p.first == q.second || p.second == q.first ||
          p.second == q.second)
          continue;
        best = std::min(best, (openMid[i].first - openMid[j].first).norm());
      }
      bins[best < 0.05 * eps ? 0 : best < 0.25 * eps ? 1 : best < eps ? 2 : 3]++;
    }
    std::printf("  %-10s elsewhere by crack width: <0.05eps %d, <0.25eps %d, <eps %d, more %d\n",
      label,
      bins[0],
      bins[1],
      bins[2],
      bins[3]);
  }
  {
    std::map<std::pair<int, int>, std::vector<int>> directed;
    for (int f = 0; f < m.NumberOfFaces(); ++f)
      for (int k = 0; k < 3; ++k)
        directed[{ m.triangles[f][k], m.triangles[f][(k + 1) % 3] }].push_back(f);
    for (const auto& e : directed)
      if (e.second.size() == 2 && !directed.count({ e.first.second, e.first.first }))
      {
        std::printf("  %-10s misoriented edge %d-%d: faces", label, e.first.first, e.first.second);
        for (int f : e.second)
          std::printf(" %d(filled %d mirrored %d leaf %d)",
            f,
            int(m.faceFilled[f]),
            int(m.faceMirrored[f]),
            m.faceLeaf[f]);
        std::printf("\n");
      }
  }
  std::printf("  %-10s open on fold planes %d elsewhere %d; unmatched tears %d gap edges %d\n",
    label,
    onPlane,
    elsewhere,
    m.unmatchedTearVertices,
    m.gapEdges);
  std::printf("  %-10s H %.4f (u->M %.4f M->u %.4f) mean %.5f open %5d nm %4d pts %6d | worst "
              "pt %.4f leaf %d mask %llx proj %d leafd %.4f\n",
    label,
    c.hausdorff / tree.diagonal,
    c.aToB / tree.diagonal,
    c.bToA / tree.diagonal,
    c.mean / tree.diagonal,
    m.openEdges,
    m.nonManifoldEdges,
    m.NumberOfPoints(),
    c.aPointDistances[worst] / tree.diagonal,
    copy.leaf,
    static_cast<unsigned long long>(copy.mirrorMask),
    local >= 0 ? int(leaf.projected[local]) : -1,
    leafDistance);
}
}

int main(int argc, char* argv[])
{
  double tolerance = 0.02;
  for (int i = 1; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--tolerance" && i + 1 < argc)
    {
      tolerance = std::atof(argv[++i]);
      continue;
    }
    std::string error;
    auto mesh = ReadMesh(argv[i], error);
    if (!mesh)
      continue;
    vtkNew<vtkFoldingTreeBuilder> builder;
    builder->SetInputData(mesh);
    builder->SetTolerance(tolerance);
    builder->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
    FoldingTree tree;
    TriangleMesh original;
    std::vector<Vec3> normals;
    if (!blocks || !MultiBlockToFoldingTree(blocks, tree, error) ||
      !ToTriangleMesh(builder->GetOutput(1), original, normals, error))
    {
      std::printf("%s: %s\n", argv[i], error.c_str());
      continue;
    }
    std::printf("%s  (eps %.4f of the diagonal, %d nodes, %d points)\n",
      std::filesystem::path(argv[i]).stem().string().c_str(),
      tree.rootEpsilon / tree.diagonal,
      tree.NumberOfNodes(),
      static_cast<int>(original.points.size()));
    // Leaf points.
    const SurfaceDistanceQuery toOriginal(original);
    double worst[3] = { 0, 0, 0 };
    int count[3] = { 0, 0, 0 };
    for (int leaf : tree.Leaves())
    {
      const FoldingLeafMesh& m = tree.nodes[leaf].mesh;
      const std::vector<double> d = toOriginal.Distances(m.points);
      for (int v = 0; v < m.NumberOfPoints(); ++v)
      {
        const int kind = m.projected[v] ? 0 : (m.planeMask[v] ? 1 : 2);
        worst[kind] = std::max(worst[kind], d[v]);
        ++count[kind];
      }
    }
    std::printf("  leaves: projected %d max %.4f | on plane %d max %.4f | other %d max %.4f\n",
      count[0],
      worst[0] / tree.diagonal,
      count[1],
      worst[1] / tree.diagonal,
      count[2],
      worst[2] / tree.diagonal);
    UnfoldOptions o;
    o.stitch = false;
    o.foldLineToleranceScale = 0.0;
    Report("raw", tree, original, o);
    o.foldLineToleranceScale = UnfoldOptions().foldLineToleranceScale;
    Report("+slab", tree, original, o);
    o.stitch = true;
    o.zipper = o.fillSeamGaps = false;
    o.smoothingIterations = 0;
    Report("+stitch", tree, original, o);
    o.zipper = true;
    Report("+zip", tree, original, o);
    o.fillSeamGaps = true;
    Report("+fill", tree, original, o);
    o = UnfoldOptions();
    o.weldBoundaries = false;
    Report("noweld", tree, original, o);
    Report("default", tree, original, UnfoldOptions());
    o.weldBoundaries = true;
    o.weldToleranceScale = 1.0;
    Report("weld1", tree, original, o);
    o.respectErrorBudget = false;
    Report("weld1free", tree, original, o);
    std::fflush(stdout);
  }
  return 0;
}
