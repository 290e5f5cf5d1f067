// The builder's proof that unfold(tree) stays within the root epsilon of the input (see
// FoldingTreeVerification.h).
#include "FoldingTreeVerification.h"

#include "EdgeTable.h"
#include "FoldingTreeUnfolder.h"
#include "SurfaceDistance.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <memory>
#include <string>

namespace foldingmeshes
{
namespace
{
/// Rings of faces sharing a vertex with `faces`, `rings` times (input vertex ids).
std::vector<int> GrowByRings(const TriangleMesh& mesh, std::vector<char> mark, int rings)
{
  std::vector<std::vector<int>> facesOf(mesh.points.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int v : mesh.triangles[f])
      facesOf[v].push_back(static_cast<int>(f));
  for (int r = 0; r < rings; ++r)
  {
    std::vector<char> next = mark;
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
      if (mark[f])
        for (int v : mesh.triangles[f])
          for (int g : facesOf[v])
            next[g] = 1;
    mark = std::move(next);
  }
  std::vector<int> out;
  for (size_t f = 0; f < mark.size(); ++f)
    if (mark[f])
      out.push_back(static_cast<int>(f));
  return out;
}

/// End points and midpoints of the edges of `mesh` used by one face, points at identical
/// positions counted as one (the unfolder's copies meet at shared positions); `count`: the
/// number of such edges.
std::vector<Vec3> OpenEdgeProbes(const TriangleMesh& mesh, int& count)
{
  std::map<std::array<double, 3>, int> idOf;
  std::vector<int> id(mesh.points.size());
  std::vector<Vec3> at;
  for (size_t v = 0; v < mesh.points.size(); ++v)
  {
    const Vec3& x = mesh.points[v];
    const auto it = idOf.emplace(std::array<double, 3>{ x.x(), x.y(), x.z() }, at.size());
    if (it.second)
      at.push_back(x);
    id[v] = it.first->second;
  }
  std::vector<Triangle> welded;
  for (const Triangle& t : mesh.triangles)
    if (id[t[0]] != id[t[1]] && id[t[1]] != id[t[2]] && id[t[2]] != id[t[0]])
      welded.push_back({ id[t[0]], id[t[1]], id[t[2]] });
  const std::vector<Edge> open = OpenEdges(welded);
  count = static_cast<int>(open.size());
  std::vector<Vec3> probes;
  for (const Edge& e : open)
    probes.insert(probes.end(), { at[e.first], at[e.second], 0.5 * (at[e.first] + at[e.second]) });
  return probes;
}

/// The summed area of the mesh's triangles.
double MeshArea(const TriangleMesh& mesh)
{
  double area = 0.0;
  for (const Triangle& t : mesh.triangles)
    area += 0.5 *
      (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]).norm();
  return area;
}
}

int WeldedOpenEdges(const TriangleMesh& mesh)
{
  int count = 0;
  OpenEdgeProbes(mesh, count);
  return count;
}

UnfoldedBoundCheck VerifyUnfoldedBound(const TriangleMesh& input,
  const FoldingTree& tree,
  const ClosestFaceQueryFactory& queries,
  const SurfaceDistanceQuery* sharedToInput)
{
  UnfoldedBoundCheck check;
  UnfoldedMesh unfolded;
  std::string error;
  if (!UnfoldFoldingTree(tree, UnfoldOptions(), unfolded, error))
  {
    // Not expected for a tree the builder made; nothing to pin but everything.
    check.upper = std::numeric_limits<double>::infinity();
    check.pin.resize(input.triangles.size());
    for (size_t f = 0; f < check.pin.size(); ++f)
      check.pin[f] = static_cast<int>(f);
    return check;
  }
  TriangleMesh out;
  out.points = unfolded.points;
  out.triangles = unfolded.triangles;
  const double epsilon = tree.rootEpsilon;
  const double tolerance = ProofToleranceOfDiagonal * tree.diagonal;
  std::unique_ptr<SurfaceDistanceQuery> ownToInput;
  if (queries || !sharedToInput)
    ownToInput = std::make_unique<SurfaceDistanceQuery>(input, queries);
  const SurfaceDistanceQuery& toInput = ownToInput ? *ownToInput : *sharedToInput;
  const SurfaceDistanceQuery toOut(out, queries);
  std::vector<int> outBeyond, inputBeyond;
  const HausdorffBounds there = DirectedHausdorffBounds(
    out, toInput, tolerance, DefaultMaximumEvaluations, epsilon, &outBeyond);
  const HausdorffBounds back = DirectedHausdorffBounds(
    input, toOut, tolerance, DefaultMaximumEvaluations, epsilon, &inputBeyond);
  check.upper = std::max(there.upper, back.upper);
  check.within = check.upper <= epsilon + tolerance;
  const double inputArea = MeshArea(input);
  check.areaRatio = inputArea > 0.0 ? MeshArea(out) / inputArea : 0.0;
  if (tree.inputBorderEdges.empty())
  {
    const std::vector<Vec3> probes = OpenEdgeProbes(out, check.openEdges);
    if (check.openEdges > 0)
    {
      std::vector<double> d;
      std::vector<int> nearest;
      toInput.Closest(probes, d, nearest);
      std::vector<char> mark(input.triangles.size(), 0);
      for (int f : nearest)
        if (f >= 0)
          mark[f] = 1;
      check.pinOpen = GrowByRings(input, std::move(mark), 2);
    }
  }
  if (check.within)
    return check;
  std::vector<char> mark(input.triangles.size(), 0);
  for (int f : inputBeyond)
    mark[f] = 1;
  // The input faces under the unfolded faces beyond epsilon: nearest to their corners and
  // centroids.
  std::vector<Vec3> probes;
  for (int f : outBeyond)
  {
    const Triangle& t = out.triangles[f];
    for (int v : t)
      probes.push_back(out.points[v]);
    probes.push_back((out.points[t[0]] + out.points[t[1]] + out.points[t[2]]) / 3.0);
  }
  std::vector<double> d;
  std::vector<int> nearest;
  toInput.Closest(probes, d, nearest);
  for (int f : nearest)
    if (f >= 0)
      mark[f] = 1;
  check.pin = GrowByRings(input, std::move(mark), 2);
  return check;
}
}
