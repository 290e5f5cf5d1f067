// FaceTree's two split rules: by surface area (the default) and at the median from a given
// depth on (the constructor's areaSplitDepth; the median is the rule from depth 64 on, which
// keeps the traversal's stack safe). The median tree of 3,000 faces is 9 levels deep (3000 ->
// 1500 -> ... -> 6), the area rule's with the median from depth 3 on at most 3 more; and the
// search is exact whatever the tree's shape: the three trees answer ClosestFace,
// ClosestCompatibleFace and NearestCentroidFace bit for bit alike (TestFaceTree checks the
// default tree against an exhaustive scan).
#include "CoreTestUtilities.h"
#include "FaceTree.h"
#include "ProceduralMeshes.h"

#include <cmath>
#include <limits>
#include <random>

using foldingmeshes::FaceTree;
using foldingmeshes::PreparedMesh;
using foldingmeshes::Vec3;

int main()
{
  using namespace foldingmeshes::testing;
  const PreparedMesh m = coretest::Prepare(coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh));
  int medianDepth = 0;
  for (int count = m.NumberOfFaces(); count > 8; count -= count / 2)
    ++medianDepth;
  const FaceTree area(m), areaThenMedian(m, 3), median(m, 0);
  EXPECT(median.Depth() == medianDepth,
    "median splits: depth " << median.Depth() << ", expected " << medianDepth);
  EXPECT(areaThenMedian.Depth() <= 3 + medianDepth,
    "area splits to depth 3: tree " << areaThenMedian.Depth() << " deep");

  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> offset(-0.1, 0.1);
  const double cos45 = std::cos(3.14159265358979323846 / 4),
               inf = std::numeric_limits<double>::infinity();
  int differ = 0;
  const int queries = 2000;
  for (int q = 0; q < queries; ++q)
  {
    const int v = static_cast<int>(rng() % m.NumberOfPoints());
    const Vec3 direction = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    const Vec3 p = m.points[v] + offset(rng) * m.diagonal * direction;
    const Vec3 n = q % 2 == 0 ? direction : m.vertexNormals[v];
    const double maxDistance = q % 3 == 0 ? 0.05 * m.diagonal : inf;
    const FaceTree::Hit plain = area.ClosestFace(p, maxDistance),
                        compatible = area.ClosestCompatibleFace(p, n, cos45, maxDistance);
    const int centroid = area.NearestCentroidFace(p);
    for (const FaceTree* other : { &areaThenMedian, &median })
    {
      const FaceTree::Hit otherPlain = other->ClosestFace(p, maxDistance),
                          otherCompatible = other->ClosestCompatibleFace(p, n, cos45, maxDistance);
      differ += otherPlain.face != plain.face || otherPlain.distance != plain.distance ||
        otherCompatible.face != compatible.face ||
        otherCompatible.distance != compatible.distance ||
        other->NearestCentroidFace(p) != centroid;
    }
  }
  EXPECT(differ == 0, differ << " of " << 2 * queries << " answers differ between the split rules");
  return coretest::Finish("TestFaceTreeSplits");
}
