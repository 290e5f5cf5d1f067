// scratch: print trees
#include "CoreTestUtilities.h"
#include "FoldingTreeBuilder.h"
#include "ProceduralMeshes.h"

#include <cstdio>
#include <cstring>

using namespace foldingmeshes;
namespace pm = foldingmeshes::testing;

namespace
{
void PrintTree(const FoldingTree& t)
{
  for (int i = 0; i < t.NumberOfNodes(); ++i)
  {
    const FoldingNode& n = t.nodes[i];
    std::printf("%*s#%d %s depth %d eps/diag %.4f folds %d faces %d area %.3f", 2 * n.depth, "", i,
      ToString(n.kind), n.depth, n.epsilon / t.diagonal, n.foldsAbove, n.numberOfFaces,
      n.area / t.originalArea);
    if (n.kind == FoldingNodeKind::Folding)
      std::printf(" n=(%.3f %.3f %.3f) o=(%.3f %.3f %.3f) discarded %d projected %d",
        n.plane.normal.x(), n.plane.normal.y(), n.plane.normal.z(), n.plane.origin.x(),
        n.plane.origin.y(), n.plane.origin.z(), n.discardedFaces, n.projectedPoints);
    if (n.kind == FoldingNodeKind::Leaf)
      std::printf(" reason %s stored %d symfrac %.3f", ToString(n.leafReason),
        n.mesh.NumberOfFaces(), n.symmetricAreaFraction);
    if (n.kind == FoldingNodeKind::Segmentation)
      std::printf(" symfrac %.3f", n.symmetricAreaFraction);
    std::printf("\n");
  }
  std::printf("stored %d / %d compression %.3f height %d folds %d time %.2fs\n", t.StoredFaces(),
    t.numberOfOriginalFaces, t.Compression(), t.Height(), t.NumberOfFolds(), t.buildSeconds);
}

FoldingTree Build(vtkPolyData* pd, double epsFraction, FoldingTreeOptions o = {})
{
  const TriangleMesh m = coretest::ToTriangleMesh(pd);
  o.epsilon = epsFraction * pm::BoundsDiagonal(pd);
  FoldingTree t;
  std::string error;
  REQUIRE(BuildFoldingTree(m, {}, o, t, error), error);
  return t;
}
}

int main(int argc, char* argv[])
{
  const int faces = argc > 1 ? std::atoi(argv[1]) : 4000;
  {
    std::printf("== three plane\n");
    auto s = pm::MakeThreePlaneShape(faces);
    PrintTree(Build(s.mesh, 0.02));
  }
  {
    std::printf("== bilateral blob\n");
    auto s = pm::MakeBilateralBlob(faces);
    PrintTree(Build(s.mesh, 0.02));
  }
  {
    std::printf("== blob + part\n");
    auto s = pm::MakeBlobWithAsymmetricPart(faces, 0.1);
    PrintTree(Build(s.mesh, 0.02));
  }
  {
    std::printf("== asymmetric blob\n");
    auto s = pm::MakeAsymmetricBlob(faces);
    PrintTree(Build(s.mesh, 0.02));
  }
  {
    std::printf("== sphere\n");
    auto s = pm::MakeSphere(faces);
    PrintTree(Build(s.mesh, 0.02));
  }
  {
    std::printf("== cylinder\n");
    auto s = pm::MakeCylinder(faces);
    PrintTree(Build(s.mesh, 0.02));
  }
  {
    std::printf("== multipart\n");
    auto s = pm::MakeMultiPartSymmetric(faces);
    PrintTree(Build(s.mesh, 0.02));
  }
  return coretest::Finish("TestFoldingTreeBuilder");
}
