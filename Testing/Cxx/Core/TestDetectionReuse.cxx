// BuildFoldingTree's later builds reuse the plane detections of its earlier ones
// (FoldingTreeOptions::reuseDetections, FoldingTreeDetectionCache.h): on a real mesh whose
// first tree misses the verification (the spider: a round of pins), the tree is node for node
// the one built with every detection run anew, and the later build took at least the root's
// detection from the earlier one (the trace says so); without reuse it took none.
#include "CoreTestUtilities.h"
#include "MeshIO.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdio>
#include <string>

using namespace foldingmeshes;

namespace
{
struct Build
{
  FoldingTree tree;
  int reused = 0;
};

Build BuildWithTrace(const TriangleMesh& mesh,
  const std::vector<Vec3>& normals,
  FoldingTreeOptions options)
{
  Build b;
  options.trace = [&b](const std::string& line)
  {
    b.reused +=
      line.rfind("[detect]", 0) == 0 && line.find("its result reused") != std::string::npos;
  };
  std::string error;
  REQUIRE(BuildFoldingTree(mesh, normals, options, b.tree, error), error);
  return b;
}
}

int main(int argc, char* argv[])
{
  REQUIRE(argc > 1, "usage: TestDetectionReuse spider_vtk.ply");
  std::string error;
  const vtkSmartPointer<vtkPolyData> data = ReadMesh(argv[1], error);
  REQUIRE(data, argv[1] << ": " << error);
  const TriangleMesh mesh = coretest::ToTriangleMesh(data);
  std::vector<Vec3> normals;
  if (vtkDataArray* n = data->GetPointData()->GetNormals())
    for (vtkIdType i = 0; i < n->GetNumberOfTuples(); ++i)
      normals.emplace_back(n->GetComponent(i, 0), n->GetComponent(i, 1), n->GetComponent(i, 2));
  double bounds[6];
  data->GetBounds(bounds);
  FoldingTreeOptions options;
  options.epsilon =
    0.02 * Vec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
  const Build reused = BuildWithTrace(mesh, normals, options);
  options.reuseDetections = false;
  const Build anew = BuildWithTrace(mesh, normals, options);
  std::printf("spider: %d verification rounds, %d stored faces; %d detections reused (without "
              "reuse: %d)\n",
    reused.tree.verificationRounds,
    reused.tree.StoredFaces(),
    reused.reused,
    anew.reused);
  EXPECT(coretest::SameTree(reused.tree, anew.tree), "reusing detections changed the tree");
  REQUIRE(anew.tree.verificationRounds >= 1, "the spider's first tree passed: nothing to reuse");
  EXPECT(reused.reused >= 1, "the root's detection was not reused");
  EXPECT(anew.reused == 0, "reused while off");
  return coretest::Finish("TestDetectionReuse");
}
