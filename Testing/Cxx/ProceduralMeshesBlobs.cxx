// Blob generators: bilateral creature (two tessellations), asymmetric blob, multi-part creature.
#include "ProceduralMeshesInternal.h"
#include "ProceduralMeshesShapes.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace foldingmeshes
{
namespace testing
{
using namespace procedural;

// =================================== generators ===================================

ProceduralMesh MakeBilateralBlob(int approxFaces, unsigned seed)
{
  const Creature s = CreatureShape(seed);
  return Finish(OctaSphere(OctaResolution(approxFaces), s, true, 1), { kPlaneX });
}

ProceduralMesh MakeBilateralBlobDifferentTessellation(int approxFaces, unsigned seed)
{
  const Creature s = CreatureShape(seed);
  // faces ~ 4 n^2 + 4 (1.3 n)^2
  const int n = std::max(2, int(std::lround(std::sqrt(approxFaces / 10.76))));
  const int m = std::max(n + 1, int(std::lround(1.3 * n)));
  return Finish(OctaSphereTwoResolutions(n, m, s), { kPlaneX });
}

ProceduralMesh MakeAsymmetricBlob(int approxFaces, unsigned seed)
{
  const Lumpy s = LumpyShape(seed);
  return Finish(OctaSphere(OctaResolution(approxFaces), s, false, 0), {});
}

ProceduralMesh MakeMultiPartSymmetric(int approxFaces)
{
  const Creature body = CreatureShape(7);
  const Lumpy ear = LumpyShape(11);
  TriMesh m = OctaSphere(OctaResolution(0.6 * approxFaces), body, true, 1);
  // on the upper side of the head, pushed outwards by 0.1 along the section direction
  const double ty = body.SpineT(body.yh - 0.05), psi = 0.9, st = std::sqrt(1 - ty * ty);
  const Vec3 c = body(Vec3(st * std::sin(psi), ty, st * std::cos(psi))) +
    0.1 * Vec3(std::sin(psi), 0, std::cos(psi));
  TriMesh right = OctaSphere(
    OctaResolution(0.2 * approxFaces),
    [&](const Vec3& u) { return Vec3(c + 0.25 * ear(u)); },
    false,
    1);
  double minX = 1e300; // the ears stay clear of each other (and of the plane x = 0)
  for (const Vec3& p : right.p)
  {
    minX = std::min(minX, p.x());
  }
  for (Vec3& p : right.p)
  {
    p.x() += std::max(0.0, 0.08 - minX);
  }
  TriMesh left = right;
  for (Vec3& p : left.p)
  {
    p = MirrorX(p);
  }
  for (Tri& t : left.t)
  {
    std::swap(t[0], t[1]);
  }
  m.Append(right);
  m.Append(left);
  return Finish(m, { kPlaneX });
}
} // namespace testing
} // namespace foldingmeshes
