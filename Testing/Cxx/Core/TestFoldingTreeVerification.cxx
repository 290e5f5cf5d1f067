// The builder's verification of its error bound (FoldingTreeVerification.h,
// FoldingTreeOptions::verifyBound):
// - a one-leaf tree holding the input unchanged is proved within epsilon (bound ~0, nothing
//   pinned, its area ratio 1; the sphere scaled by 1.01: 1.0201); with one vertex moved by half of
//   epsilon it is still proved (bound at least the move, at most epsilon); moved by twice epsilon
//   it is not, and the faces to pin are the faces around that vertex (its star and two rings),
//   nowhere else on the sphere;
// - BuildFoldingTree with verifyBound on a symmetric sphere (RotationNodes WHEN_AXIAL, the
//   default since 2026-12-07, looks for rotation nodes there): a verified bound within epsilon,
//   the same tree as with the option off (nothing pinned, no extra build); off: not verified
//   (-1).
#include "CoreTestUtilities.h"
#include "FoldingTreeBuilder.h"
#include "FoldingTreeVerification.h"
#include "ProceduralMeshes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace foldingmeshes;
namespace pm = foldingmeshes::testing;

namespace
{

void TestMovedVertex(const TriangleMesh& sphere)
{
  const double diagonal = 2.0 * std::sqrt(3.0), epsilon = 0.02 * diagonal;
  const UnfoldedBoundCheck same =
    VerifyUnfoldedBound(sphere, coretest::LeafTree(sphere, epsilon, diagonal));
  EXPECT(same.within && same.upper < 1e-9 && same.pin.empty(),
    "unchanged leaf: within " << same.within << ", bound " << same.upper << ", pin "
                              << same.pin.size());
  // The unfolded area over the input's (areaRatio): 1 for the unchanged leaf, 1.01^2 for the
  // sphere (radius 1) scaled by 1.01 about its centre, a move of 0.01 within epsilon.
  TriangleMesh grown = sphere;
  for (Vec3& p : grown.points)
    p *= 1.01;
  const UnfoldedBoundCheck larger =
    VerifyUnfoldedBound(sphere, coretest::LeafTree(grown, epsilon, diagonal));
  EXPECT(std::abs(same.areaRatio - 1.0) < 1e-12 && larger.within &&
      std::abs(larger.areaRatio - 1.0201) < 1e-9,
    "area ratios " << same.areaRatio << " and " << larger.areaRatio << " (scaled by 1.01)");
  const int moved = 17;
  const Vec3 out = sphere.points[moved].normalized();
  for (const double factor : { 0.5, 2.0 })
  {
    TriangleMesh leaf = sphere;
    leaf.points[moved] += factor * epsilon * out;
    const UnfoldedBoundCheck c =
      VerifyUnfoldedBound(sphere, coretest::LeafTree(leaf, epsilon, diagonal));
    std::printf("vertex moved by %.1f epsilon: bound %.4f epsilon, %s, %zu faces to pin\n",
      factor,
      c.upper / epsilon,
      c.within ? "within" : "not within",
      c.pin.size());
    if (factor < 1.0)
    {
      EXPECT(c.within && c.pin.empty(), "moved by " << factor << " epsilon: not proved");
      EXPECT(c.upper >= 0.4 * epsilon && c.upper <= epsilon, "bound " << c.upper / epsilon);
      continue;
    }
    EXPECT(!c.within && c.upper >= 1.5 * epsilon, "moved by 2 epsilon: proved " << c.upper);
    // Every face to pin is near the moved vertex; its star is among them.
    int star = 0, pinnedStar = 0;
    for (size_t f = 0; f < sphere.triangles.size(); ++f)
    {
      const Triangle& t = sphere.triangles[f];
      const bool inStar = std::find(t.begin(), t.end(), moved) != t.end();
      star += inStar;
      pinnedStar += inStar && std::binary_search(c.pin.begin(), c.pin.end(), static_cast<int>(f));
    }
    EXPECT(star > 0 && pinnedStar == star,
      "star of the moved vertex: " << pinnedStar << " of " << star << " pinned");
    double farthest = 0.0;
    for (int f : c.pin)
      for (int v : sphere.triangles[f])
        farthest = std::max(farthest, (sphere.points[v] - sphere.points[moved]).norm());
    EXPECT(!c.pin.empty() && c.pin.size() < sphere.triangles.size() / 10 && farthest < 0.6,
      c.pin.size() << " faces to pin, reaching " << farthest << " from the vertex");
  }
}

void TestBuildVerified(const TriangleMesh& sphere)
{
  const double diagonal = 2.0 * std::sqrt(3.0);
  FoldingTreeOptions options;
  options.epsilon = 0.02 * diagonal;
  FoldingTree on, off;
  std::string error;
  EXPECT(BuildFoldingTree(sphere, {}, options, on, error), error);
  options.verifyBound = false;
  EXPECT(BuildFoldingTree(sphere, {}, options, off, error), error);
  std::printf("sphere: verified bound %.4f epsilon, %d pinned, %d rounds; stored %d / %d\n",
    on.verifiedBound / options.epsilon,
    on.pinnedFaces,
    on.verificationRounds,
    on.StoredFaces(),
    off.StoredFaces());
  EXPECT(on.verifiedBound >= 0.0 && on.verifiedBound <= options.epsilon * (1.0 + 1e-9),
    "verified bound " << on.verifiedBound);
  EXPECT(on.pinnedFaces == 0 && on.verificationRounds == 0 &&
      on.StoredFaces() == off.StoredFaces() && on.NumberOfNodes() == off.NumberOfNodes(),
    "a proved first tree changed");
  EXPECT(off.verifiedBound == -1.0 && off.pinnedFaces == 0, "verification ran while off");
  std::printf("sphere: rotation nodes tried %d, kept %d\n",
    on.rotationNodesTried ? 1 : 0,
    on.NumberOfRotations());
}
}

int main()
{
  const TriangleMesh sphere = coretest::ToTriangleMesh(pm::MakeSphere(2000).mesh);
  TestMovedVertex(sphere);
  TestBuildVerified(sphere);
  return coretest::Finish("TestFoldingTreeVerification");
}
