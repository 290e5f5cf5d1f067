// UnfoldOptions::removeProjectedPoints (paper §4.2's fold rule projects the far vertices of
// faces straddling a fold plane onto it; the unfolder removes them again after mirroring):
// an ellipsoid whose three mirror planes cut faces comes back with M's point and face counts
// (within 3%), closed, manifold, consistently oriented and within the root epsilon, with
// valid arrays; with the option off the counts are far above M's.
#include "CoreTestUtilities.h"

#include <cmath>
#include <cstdio>

using namespace foldingmeshes;
using coretest::Fold;
using coretest::Hausdorff;

namespace
{
/**
 * An ellipsoid (semi-axes 1, 1.6, 2.3) along 32 longitudes at (k + 1/2) * 2 pi / 32 and 15
 * latitude bands, quads split by one diagonal (planar quads: the surface is exactly
 * symmetric, the tessellation is not). Its three mirror planes pass through no vertex but
 * the poles, so every fold cuts faces and the builder projects their far vertices onto it.
 */
TriangleMesh MakeStraddlingEllipsoid()
{
  const int longitudes = 32, bands = 15;
  const Vec3 axes(1.0, 1.6, 2.3);
  TriangleMesh m;
  m.points.push_back(Vec3(0, 0, axes.z()));
  for (int j = 1; j < bands; ++j)
    for (int k = 0; k < longitudes; ++k)
    {
      const double theta = M_PI * j / bands, phi = 2.0 * M_PI * (k + 0.5) / longitudes;
      m.points.push_back(Vec3(axes.x() * std::sin(theta) * std::cos(phi),
        axes.y() * std::sin(theta) * std::sin(phi),
        axes.z() * std::cos(theta)));
    }
  m.points.push_back(Vec3(0, 0, -axes.z()));
  const int south = static_cast<int>(m.points.size()) - 1;
  auto at = [&](int j, int k) { return 1 + (j - 1) * longitudes + (k % longitudes); };
  for (int k = 0; k < longitudes; ++k)
  {
    m.triangles.push_back({ 0, at(1, k), at(1, k + 1) });
    m.triangles.push_back({ south, at(bands - 1, k + 1), at(bands - 1, k) });
    for (int j = 1; j + 1 < bands; ++j)
    {
      m.triangles.push_back({ at(j, k), at(j + 1, k), at(j + 1, k + 1) });
      m.triangles.push_back({ at(j, k), at(j + 1, k + 1), at(j, k + 1) });
    }
  }
  return m;
}

/**
 * UnfoldOptions::removeProjectedPoints: on the ellipsoid above (folded on its three planes,
 * every fold cutting faces) unfold(fold(M)) has M's point and face counts within 3% (the
 * projected vertices removed, their rings re-triangulated), is closed, manifold and
 * consistently oriented, within the root epsilon; with the option off the counts are far
 * above M's (each straddling face comes back as two): the test measures the removal.
 */
void TestRemovedProjectedPoints()
{
  const TriangleMesh m = MakeStraddlingEllipsoid();
  Vec3 lo = m.points[0], hi = m.points[0];
  for (const Vec3& x : m.points)
  {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double diagonal = (hi - lo).norm();
  FoldingTreeOptions octant;
  octant.minimumAreaFraction = 0.13; // the three planes, no local folds of the octant
  const FoldingTree tree = Fold(m, 0.02 * diagonal, octant);
  int projected = 0;
  for (int leaf : tree.Leaves())
    projected += static_cast<int>(std::count(
      tree.nodes[leaf].mesh.projected.begin(), tree.nodes[leaf].mesh.projected.end(), 1));
  UnfoldOptions keep;
  keep.removeProjectedPoints = false;
  const UnfoldedMesh with = coretest::Unfold(tree), without = coretest::Unfold(tree, keep);
  const int np = static_cast<int>(m.points.size()), nf = static_cast<int>(m.triangles.size());
  std::printf("straddling ellipsoid: %d folds, %d projected leaf points; M %d points %d faces; "
              "unfolded %d points %d faces (removed %d, left %d), kept: %d points %d faces\n",
    tree.NumberOfFolds(),
    projected,
    np,
    nf,
    with.NumberOfPoints(),
    with.NumberOfFaces(),
    with.removedProjectedPoints,
    with.projectedPoints,
    without.NumberOfPoints(),
    without.NumberOfFaces());
  REQUIRE(tree.NumberOfFolds() == 3 && projected > 0,
    "straddling ellipsoid: " << tree.NumberOfFolds() << " folds, " << projected
                             << " projected points");
  EXPECT(std::abs(with.NumberOfPoints() - np) <= 0.03 * np &&
      std::abs(with.NumberOfFaces() - nf) <= 0.03 * nf,
    "straddling ellipsoid: " << with.NumberOfPoints() << " points " << with.NumberOfFaces()
                             << " faces, M " << np << " / " << nf);
  EXPECT(without.NumberOfPoints() > 1.1 * np && without.NumberOfFaces() > 1.1 * nf,
    "straddling ellipsoid, projected points kept: " << without.NumberOfPoints() << " points "
                                                    << without.NumberOfFaces() << " faces");
  EXPECT(without.removedProjectedPoints == 0 && with.removedProjectedPoints > 0 &&
      with.projectedPoints < without.projectedPoints,
    "straddling ellipsoid: removed "
      << with.removedProjectedPoints << " (off: " << without.removedProjectedPoints << "), left "
      << with.projectedPoints << " (off: " << without.projectedPoints << ")");
  for (const UnfoldedMesh* u : { &with, &without })
  {
    const char* name = u == &with ? "removed" : "kept";
    const coretest::EdgeStats e = coretest::CountEdges(u->triangles);
    const double h = Hausdorff(m, *u) / diagonal;
    const double volume = coretest::SignedVolume(u->points, u->triangles) /
      coretest::SignedVolume(m.points, m.triangles);
    std::printf("  %s: open %d non-manifold %d misoriented %d, Hausdorff/diag %.2e, volume ratio "
                "%.5f\n",
      name,
      e.open,
      e.nonManifold,
      e.misoriented,
      h,
      volume);
    EXPECT(e.open == 0 && e.nonManifold == 0 && e.misoriented == 0,
      "straddling ellipsoid (" << name << "): " << e.open << " open, " << e.nonManifold
                               << " non-manifold, " << e.misoriented << " misoriented edges");
    EXPECT(h <= 0.02, "straddling ellipsoid (" << name << "): Hausdorff/diag " << h);
    EXPECT(std::abs(volume - 1.0) < 0.01,
      "straddling ellipsoid (" << name << "): volume ratio " << volume);
    // Every per-point and per-face array follows the points and faces.
    const size_t p = u->points.size(), f = u->triangles.size();
    EXPECT(u->pointOriginalIds.size() == p && u->pointCopy.size() == p &&
        u->pointMirrored.size() == p && u->pointAdded.size() == p &&
        u->faceOriginalIds.size() == f && u->faceLeaf.size() == f && u->faceCopy.size() == f &&
        u->faceMirrored.size() == f && u->faceFilled.size() == f,
      "straddling ellipsoid (" << name << "): array sizes");
    // Ids in range; each point the image of its input point under its copy's map (within
    // the snap distance), except the projected ones (moved by the builder).
    int badIds = 0;
    for (size_t v = 0; v < p; ++v)
      badIds += u->pointOriginalIds[v] < 0 || u->pointOriginalIds[v] >= np ||
        (u->projectedPoints == 0 &&
          (u->points[v] - u->copies[u->pointCopy[v]].linear * m.points[u->pointOriginalIds[v]] -
            u->copies[u->pointCopy[v]].translation)
              .norm() > 1e-2 * 0.02 * diagonal);
    for (size_t t = 0; t < f; ++t)
      badIds += u->faceOriginalIds[t] < 0 || u->faceOriginalIds[t] >= nf;
    EXPECT(badIds == 0, "straddling ellipsoid (" << name << "): " << badIds << " bad ids");
  }
}
} // namespace

int main()
{
  TestRemovedProjectedPoints();
  return coretest::Finish("TestRemovedProjectedPoints");
}
