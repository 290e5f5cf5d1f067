// Where does unfold(fold(M)) depart from M? Per mesh: the distance of the stored leaf points to
// M (by kind: projected onto a fold plane, on a fold plane, other), then the symmetric
// Hausdorff distance / diagonal of the unfolded mesh after each reconstruction step (raw
// union, fold-line slab merge, stitching, zipper, gap filling, smoothing), with open edges.
// Not a test: numbers to find which step breaks the error bound.
//
//   BenchmarkUnfoldingError [--tolerance F] [--explain] MESH...
//
// F: root epsilon / diagonal, default 0.02. --explain: only where the default unfolding
// exceeds epsilon (the worst samples each way, the fill patch around the worst, the distance
// measured on 28 samples per face instead of vertices and centroids).
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
double SegmentDistance(const Vec3& x, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}

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
/// Where the distance exceeds epsilon: per side, the samples above it (vertices and
/// centroids, filled faces apart), the worst one, the patch of filled faces around it (its
/// faces, border edges, how far its points are from M), and a denser measure (6 x 6
/// barycentric samples per face) to see what vertices + centroids miss.
void Explain(const char* label,
  const FoldingTree& tree,
  const TriangleMesh& original,
  const UnfoldOptions& options)
{
  UnfoldedMesh m;
  std::string error;
  if (!UnfoldFoldingTree(tree, options, m, error))
    return;
  TriangleMesh u;
  u.points = m.points;
  u.triangles = m.triangles;
  const double eps = tree.rootEpsilon, diag = tree.diagonal;
  const SurfaceDistanceQuery toM(original), toU(u);
  auto centroid = [](const TriangleMesh& s, int f)
  {
    const Triangle& t = s.triangles[f];
    return Vec3((s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0);
  };
  // Unfolded -> M.
  const std::vector<double> dv = toM.Distances(u.points);
  std::vector<Vec3> cu;
  for (int f = 0; f < m.NumberOfFaces(); ++f)
    cu.push_back(centroid(u, f));
  const std::vector<double> dc = toM.Distances(cu);
  int overFilled = 0, overReal = 0, overVertex = 0, overAdded = 0, worstFace = -1;
  double worst = 0.0;
  for (int f = 0; f < m.NumberOfFaces(); ++f)
  {
    if (dc[f] > eps)
      ++(m.faceFilled[f] ? overFilled : overReal);
    if (dc[f] > worst)
    {
      worst = dc[f];
      worstFace = f;
    }
    for (int k = 0; k < 3; ++k)
      if (dv[u.triangles[f][k]] > worst)
      {
        worst = dv[u.triangles[f][k]];
        worstFace = f;
      }
  }
  for (int v = 0; v < m.NumberOfPoints(); ++v)
    if (dv[v] > eps)
      ++(m.pointAdded[v] ? overAdded : overVertex);
  std::printf("  %-10s u->M %.4f: above eps: centroids of fills %d, of copied faces %d, "
              "vertices %d (added %d)\n",
    label,
    worst / diag,
    overFilled,
    overReal,
    overVertex,
    overAdded);
  if (worstFace >= 0 && m.faceFilled[worstFace])
  {
    // The patch of filled faces connected (by edges) to the worst one.
    std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
    for (int f = 0; f < m.NumberOfFaces(); ++f)
      for (int k = 0; k < 3; ++k)
      {
        const int a = u.triangles[f][k], b = u.triangles[f][(k + 1) % 3];
        edgeFaces[{ std::min(a, b), std::max(a, b) }].push_back(f);
      }
    std::vector<int> patch{ worstFace }, stack{ worstFace };
    std::vector<char> in(m.NumberOfFaces(), 0);
    in[worstFace] = 1;
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int a = u.triangles[f][k], b = u.triangles[f][(k + 1) % 3];
        for (int g : edgeFaces[{ std::min(a, b), std::max(a, b) }])
          if (!in[g] && m.faceFilled[g])
          {
            in[g] = 1;
            patch.push_back(g);
            stack.push_back(g);
          }
      }
    }
    std::map<std::pair<int, int>, int> uses;
    double loopLength = 0.0, loopWorst = 0.0, patchWorst = 0.0;
    int added = 0;
    for (int f : patch)
    {
      patchWorst = std::max(patchWorst, dc[f]);
      for (int k = 0; k < 3; ++k)
      {
        const int a = u.triangles[f][k], b = u.triangles[f][(k + 1) % 3];
        ++uses[{ std::min(a, b), std::max(a, b) }];
        added += m.pointAdded[a];
      }
    }
    int loopEdges = 0;
    for (const auto& e : uses)
      if (e.second == 1)
      {
        ++loopEdges;
        loopLength += (u.points[e.first.first] - u.points[e.first.second]).norm();
        loopWorst = std::max({ loopWorst, dv[e.first.first], dv[e.first.second] });
      }
    // Each fill face: centroid distance to M and to the patch's loop edges; each loop edge:
    // its end points' and midpoint's distances to M, its length.
    std::vector<std::pair<int, int>> loop;
    for (const auto& e : uses)
      if (e.second == 1)
        loop.push_back(e.first);
    for (int f : patch)
    {
      double toLoop = 1e300;
      for (const auto& e : loop)
        toLoop = std::min(toLoop, SegmentDistance(cu[f], u.points[e.first], u.points[e.second]));
      std::printf("  %-10s     fill face %d: centroid %.4f from M, %.4f from the loop\n",
        label, f, dc[f] / diag, toLoop / diag);
    }
    for (const auto& e : loop)
      std::printf("  %-10s     loop edge %d-%d: length %.4f, ends %.4f %.4f, middle %.4f "
                  "from M\n",
        label, e.first, e.second,
        (u.points[e.first] - u.points[e.second]).norm() / diag, dv[e.first] / diag,
        dv[e.second] / diag,
        toM.Distance(0.5 * (u.points[e.first] + u.points[e.second])) / diag);
    const Vec3 c = cu[worstFace];
    std::printf("  %-10s   worst is a fill: patch of %zu faces, %d loop edges (length %.4f "
                "diag), loop vertices up to %.4f from M, fill centroids up to %.4f, "
                "added-point corners %d, at (%.4g %.4g %.4g)\n",
      label,
      patch.size(),
      loopEdges,
      loopLength / diag,
      loopWorst / diag,
      patchWorst / diag,
      added,
      c.x(),
      c.y(),
      c.z());
  }
  // M -> unfolded.
  const std::vector<double> mv = toU.Distances(original.points);
  std::vector<Vec3> cm;
  for (int f = 0; f < static_cast<int>(original.triangles.size()); ++f)
    cm.push_back(centroid(original, f));
  const std::vector<double> mc = toU.Distances(cm);
  int overM = 0, worstM = -1;
  double worstMDistance = 0.0;
  for (int f = 0; f < static_cast<int>(original.triangles.size()); ++f)
  {
    double d = mc[f];
    for (int v : original.triangles[f])
      d = std::max(d, mv[v]);
    overM += d > eps;
    if (d > worstMDistance)
    {
      worstMDistance = d;
      worstM = f;
    }
  }
  if (worstM >= 0)
  {
    const Vec3 c = cm[worstM];
    std::printf("  %-10s M->u %.4f: %d faces of M with a sample above eps; worst face %d at "
                "(%.4g %.4g %.4g)\n",
      label,
      worstMDistance / diag,
      overM,
      worstM,
      c.x(),
      c.y(),
      c.z());
  }
  // Denser samples: 6 x 6 barycentric grid per face, both ways.
  auto dense = [](const TriangleMesh& s)
  {
    std::vector<Vec3> x;
    constexpr int k = 6;
    for (const Triangle& t : s.triangles)
      for (int i = 0; i <= k; ++i)
        for (int j = 0; i + j <= k; ++j)
          x.push_back(((k - i - j) * s.points[t[0]] + i * s.points[t[1]] + j * s.points[t[2]]) /
            double(k));
    return x;
  };
  double du = 0.0, dm = 0.0;
  {
    const std::vector<double> dd = toM.Distances(dense(u));
    size_t worstSample = 0;
    for (size_t i = 0; i < dd.size(); ++i)
      if (dd[i] > du)
      {
        du = dd[i];
        worstSample = i;
      }
    if (!dd.empty())
    {
      // Where the dense u->M maximum lies: a copied or filled face, and its corners.
      const int f = static_cast<int>(worstSample / 28);
      const Triangle& t = u.triangles[f];
      std::printf("  %-10s dense u->M worst on face %d (%s, leaf %d, copy %d, input face %d): "
                  "corners %.4f %.4f %.4f, centroid %.4f\n",
        label, f, m.faceFilled[f] ? "fill" : (m.faceMirrored[f] ? "mirrored copy" : "copy"),
        m.faceLeaf[f], m.faceCopy[f], m.faceOriginalIds[f], toM.Distance(u.points[t[0]]) / diag,
        toM.Distance(u.points[t[1]]) / diag, toM.Distance(u.points[t[2]]) / diag,
        toM.Distance(cu[f]) / diag);
    }
  }
  for (double d : toU.Distances(dense(original)))
    dm = std::max(dm, d);
  std::printf("  %-10s dense (28 samples per face): u->M %.4f M->u %.4f\n",
    label,
    du / diag,
    dm / diag);
}
}

int main(int argc, char* argv[])
{
  double tolerance = 0.02;
  bool explainOnly = false;
  for (int i = 1; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--tolerance" && i + 1 < argc)
    {
      tolerance = std::atof(argv[++i]);
      continue;
    }
    if (std::string(argv[i]) == "--explain")
    {
      explainOnly = true;
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
    if (explainOnly)
    {
      Explain("default", tree, original, UnfoldOptions());
      std::fflush(stdout);
      continue;
    }
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
    Explain("default", tree, original, UnfoldOptions());
    o = UnfoldOptions();
    o.closeHoles = false;
    Explain("noclose", tree, original, o);
    o.weldBoundaries = true;
    o.weldToleranceScale = 1.0;
    Report("weld1", tree, original, o);
    o.respectErrorBudget = false;
    Report("weld1free", tree, original, o);
    std::fflush(stdout);
  }
  return 0;
}
