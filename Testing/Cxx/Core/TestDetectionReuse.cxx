// BuildFoldingTree keeps the plane detection of every region for its later builds
// (FoldingTreeOptions::reuseDetections, FoldingTreeDetectionCache.h). On two real meshes whose
// first tree is built again at the same epsilon - the spider (a round of pins: 2 open edges
// where the input is closed) and the fandisk (a round of pins) - the tree is node for node the
// one built with every detection run anew, and the later build took the root's detection from
// the earlier one (the trace says so for node 0); without reuse nothing was reused. (Until
// 2026-12-06 the second mesh was the queen with rotation nodes and the file's normals, whose
// first rotation tree missed the bound; since the rotation check measures the removed faces
// too, no shared mesh's rotation tree misses at 2%: the input ids in the key are checked below.)
// DetectionCache itself: a region's slot is found again only for the same points, triangles,
// epsilon and (with input normals) input ids, bit for bit (-0.0 is not 0.0), and a slot stays
// where it is while a thousand other regions are added.
#include "CoreTestUtilities.h"
#include "FoldingTreeDetectionCache.h"
#include "MeshIO.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <cstdio>
#include <string>

using namespace foldingmeshes;

namespace
{
struct Build
{
  FoldingTree tree;
  int reused = 0; ///< trace lines of reused detections
  bool rootReused = false;
};

Build BuildWithTrace(const TriangleMesh& mesh,
  const std::vector<Vec3>& normals,
  FoldingTreeOptions options)
{
  Build b;
  options.trace = [&b](const std::string& line)
  {
    if (line.rfind("[detect]", 0) != 0 || line.find("its result reused") == std::string::npos)
      return;
    ++b.reused;
    b.rootReused = b.rootReused || line.rfind("[detect] node 0:", 0) == 0;
  };
  std::string error;
  REQUIRE(BuildFoldingTree(mesh, normals, options, b.tree, error), error);
  return b;
}

/// The file's polygons as triangles (vtkTriangleFilter, as the filters triangulate) and its
/// point normals (empty if it has none).
TriangleMesh Read(const std::string& path, std::vector<Vec3>& normals)
{
  std::string error;
  const vtkSmartPointer<vtkPolyData> data = ReadMesh(path, error);
  REQUIRE(data, path << ": " << error);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(data);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* triangles = triangulate->GetOutput();
  const TriangleMesh mesh = coretest::ToTriangleMesh(triangles);
  normals.clear();
  if (vtkDataArray* n = triangles->GetPointData()->GetNormals())
    for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
      normals.emplace_back(n->GetComponent(i, 0), n->GetComponent(i, 1), n->GetComponent(i, 2));
  return mesh;
}

void Check(const std::string& path, bool rotationNodes, bool withNormals)
{
  std::vector<Vec3> normals;
  const TriangleMesh mesh = Read(path, normals);
  REQUIRE(normals.empty() != withNormals, path << ": " << normals.size() << " normals");
  Vec3 lo = mesh.points[0], hi = mesh.points[0];
  for (const Vec3& p : mesh.points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  FoldingTreeOptions options;
  options.epsilon = 0.02 * (hi - lo).norm();
  options.rotationNodes = rotationNodes;
  const Build reused = BuildWithTrace(mesh, normals, options);
  options.reuseDetections = false;
  const Build anew = BuildWithTrace(mesh, normals, options);
  std::printf("%s: %d verification rounds, %d pinned, %d stored faces; %d detections reused "
              "(without reuse: %d)\n",
    path.c_str(),
    reused.tree.verificationRounds,
    reused.tree.pinnedFaces,
    reused.tree.StoredFaces(),
    reused.reused,
    anew.reused);
  EXPECT(
    coretest::SameTree(reused.tree, anew.tree), path << ": reusing detections changed the tree");
  REQUIRE(anew.tree.verificationRounds >= 1 && anew.tree.rootEpsilon == options.epsilon,
    path << ": not built again at the same epsilon, nothing to reuse");
  EXPECT(reused.rootReused, path << ": the root's detection was not reused");
  EXPECT(anew.reused == 0, path << ": reused while off");
}
}

void TestCacheKeys()
{
  using treebuilder::DetectionCache;
  using treebuilder::WorkMesh;
  WorkMesh w;
  w.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) };
  w.triangles = { Triangle{ 0, 1, 2 } };
  w.pointOrig = { 0, 1, 2 };
  WorkMesh otherIds = w, negativeZero = w, otherTriangle = w;
  otherIds.pointOrig = { 2, 1, 0 };
  negativeZero.points[0].x() = -0.0;
  otherTriangle.triangles = { Triangle{ 0, 2, 1 } };
  DetectionCache cache;
  DetectionCache::Slot& slot = cache.For(w, true, 0.5);
  EXPECT(!slot, "a new region's slot is not empty");
  slot = std::make_shared<const SymmetryResult>();
  EXPECT(&cache.For(w, true, 0.5) == &slot, "the same region: another slot");
  EXPECT(&cache.For(otherIds, true, 0.5) != &slot, "other input ids: the same slot");
  EXPECT(&cache.For(w, true, 0.25) != &slot, "another epsilon: the same slot");
  EXPECT(&cache.For(negativeZero, true, 0.5) != &slot, "-0.0 matched 0.0");
  EXPECT(&cache.For(otherTriangle, true, 0.5) != &slot, "another triangle: the same slot");
  EXPECT(&cache.For(w, false, 0.5) != &slot, "without ids: the slot with ids");
  EXPECT(&cache.For(w, false, 0.5) == &cache.For(otherIds, false, 0.5),
    "without input normals the ids matter");
  for (int i = 0; i < 1000; ++i)
  {
    WorkMesh more = w;
    more.points[1].y() = i + 1.0;
    cache.For(more, true, 0.5);
  }
  EXPECT(&cache.For(w, true, 0.5) == &slot && slot, "the slot moved or lost its result");
}

int main(int argc, char* argv[])
{
  TestCacheKeys();
  REQUIRE(argc > 2, "usage: TestDetectionReuse spider_vtk.ply fandisk_alec.obj");
  Check(argv[1], false, false);
  Check(argv[2], false, false);
  return coretest::Finish("TestDetectionReuse");
}
