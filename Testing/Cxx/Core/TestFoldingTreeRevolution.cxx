// Folding a chess piece (the paper's queen: "all planar symmetries are recursively
// discovered resulting in one eighth of the original surface being stored", Table 1: 82.1%)
// on a procedural surface of revolution whose symmetry is exact by construction: rings of n
// vertices, every quad split into four triangles around its centre (so the tessellation has
// every mirror plane of the regular n-gon), fan caps; moved by a rigid motion.
// - n = 16: the mirror planes every 11.25 degrees contain three mutually nested ones (0, 90,
//   45 degrees), so the first three nodes on the path to the first leaf are folding nodes with
//   epsilon halving, and the compression reaches at least the paper's 82.1%;
// - n = 18 (the ring size of our shared queen mesh): the planes every 10 degrees contain no
//   third plane nested in the first two (45 degrees is not a multiple of 10), so after two
//   folds the quarter is segmented (a sub-wedge symmetric about a 10-degree multiple, and the
//   rest), and the compression still reaches the paper's 82.1%;
// - n = 18 with the uneven spacing of the shared queen mesh's base ring (gaps of 19.3 to 21
//   degrees, symmetric about one plane only): still at least 82.1%. (The shared queen mesh
//   itself stays below: each of its rings is uneven in its own way, and its base and crown
//   rings are farther than epsilon / 2 from their mirror images under the second plane.)
//
//   TestFoldingTreeRevolution
#include "CoreTestUtilities.h"
#include "FoldingTreeBuilder.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace foldingmeshes;

namespace
{
/// A queen-like profile: (radius, height) from the base to the top.
const double Profile[][2] = { { 1.00, 0.00 },
  { 1.00, 0.15 },
  { 0.90, 0.25 },
  { 0.85, 0.40 },
  { 0.70, 0.50 },
  { 0.55, 0.70 },
  { 0.45, 1.10 },
  { 0.38, 1.60 },
  { 0.34, 2.00 },
  { 0.45, 2.10 },
  { 0.34, 2.20 },
  { 0.40, 2.50 },
  { 0.55, 2.80 },
  { 0.62, 3.00 },
  { 0.50, 3.05 },
  { 0.30, 3.15 },
  { 0.15, 3.30 } };

/// Angular gaps of the base ring of the shared queen mesh (degrees, 18 vertices): uneven,
/// symmetric about one plane only.
const std::vector<double> QueenBaseGaps = { 21.0,
  19.8,
  19.5,
  19.4,
  19.7,
  20.9,
  20.8,
  19.6,
  19.3,
  19.3,
  19.6,
  20.8,
  20.9,
  19.7,
  19.4,
  19.5,
  19.8,
  21.0 };

/// Rings of n vertices, evenly spaced or (gaps: n values, scaled to 360 degrees) not.
TriangleMesh MakeChessPiece(int n,
  const Eigen::Affine3d& motion,
  const std::vector<double>& gaps = {})
{
  TriangleMesh m;
  const int rings = static_cast<int>(sizeof(Profile) / sizeof(Profile[0]));
  const double pi = std::acos(-1.0);
  auto add = [&](const Vec3& p)
  {
    m.points.push_back(motion * p);
    return static_cast<int>(m.points.size()) - 1;
  };
  auto ringPoint = [&](int ring, double angle)
  {
    const double r = Profile[ring][0], y = Profile[ring][1];
    return Vec3(r * std::cos(angle), y, r * std::sin(angle));
  };
  std::vector<double> angles(n + 1, 0.0);
  double total = 0.0;
  for (int i = 0; i < n; ++i)
    total += gaps.empty() ? 1.0 : gaps[i];
  for (int i = 0; i < n; ++i)
    angles[i + 1] = angles[i] + 2.0 * pi * (gaps.empty() ? 1.0 : gaps[i]) / total;
  std::vector<std::vector<int>> ids(rings, std::vector<int>(n));
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < n; ++i)
      ids[j][i] = add(ringPoint(j, angles[i]));
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < n; ++i)
    {
      const int a = ids[j][i], b = ids[j][(i + 1) % n], c = ids[j + 1][(i + 1) % n],
                d = ids[j + 1][i];
      const Vec3 centre = 0.25 *
        (ringPoint(j, angles[i]) + ringPoint(j, angles[i + 1]) + ringPoint(j + 1, angles[i]) +
          ringPoint(j + 1, angles[i + 1]));
      const int e = add(centre);
      // One orientation for all (PrepareMesh orients consistently anyway).
      m.triangles.push_back({ a, e, b });
      m.triangles.push_back({ b, e, c });
      m.triangles.push_back({ c, e, d });
      m.triangles.push_back({ d, e, a });
    }
  const int bottom = add(Vec3(0, Profile[0][1], 0));
  const int top = add(Vec3(0, Profile[rings - 1][1] + 0.05, 0));
  for (int i = 0; i < n; ++i)
  {
    m.triangles.push_back({ bottom, ids[0][i], ids[0][(i + 1) % n] });
    m.triangles.push_back({ top, ids[rings - 1][(i + 1) % n], ids[rings - 1][i] });
  }
  return m;
}

FoldingTree Fold(const TriangleMesh& m, bool rotationNodes = false)
{
  FoldingTreeOptions o;
  o.epsilon = 0.02 * coretest::Diagonal(m);
  o.rotationNodes = rotationNodes;
  o.rotationNodesWhenAxial = false; // off: the planes alone (the default would turn them on)
  FoldingTree tree;
  std::string error;
  EXPECT(BuildFoldingTree(m, {}, o, tree, error), "BuildFoldingTree: " << error);
  return tree;
}

/// Kinds of the nodes on the path from the root to the first leaf.
std::vector<FoldingNodeKind> FirstPathKinds(const FoldingTree& t)
{
  std::vector<FoldingNodeKind> kinds;
  int i = 0;
  while (i >= 0 && i < t.NumberOfNodes())
  {
    kinds.push_back(t.nodes[i].kind);
    i = t.nodes[i].children.empty() ? -1 : t.nodes[i].children[0];
  }
  return kinds;
}

void Print(const char* name, const FoldingTree& t)
{
  std::printf("%s: %d faces, stored %d, compression %.1f%%, height %d, folds %d, path:",
    name,
    t.numberOfOriginalFaces,
    t.StoredFaces(),
    100.0 * t.Compression(),
    t.Height(),
    t.NumberOfFolds());
  for (FoldingNodeKind k : FirstPathKinds(t))
    std::printf(" %s", ToString(k));
  std::printf("\n");
}
}

int main()
{
  Eigen::Affine3d motion = Eigen::Affine3d::Identity();
  motion.rotate(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  motion.pretranslate(Vec3(3.0, -1.0, 2.0));

  const FoldingTree sixteen = Fold(MakeChessPiece(16, motion));
  Print("16-gon chess piece", sixteen);
  const std::vector<FoldingNodeKind> path16 = FirstPathKinds(sixteen);
  bool threeFolds = path16.size() >= 4;
  for (size_t k = 0; k < 3 && k < path16.size(); ++k)
    threeFolds = threeFolds && path16[k] == FoldingNodeKind::Folding;
  EXPECT(threeFolds, "16-gon: the first three nodes are not three nested folds");
  for (int k = 0; k < 3 && k + 1 < sixteen.NumberOfNodes(); ++k)
    EXPECT(sixteen.nodes[k + 1].epsilon == 0.5 * sixteen.nodes[k].epsilon,
      "16-gon: epsilon does not halve below fold " << k);
  EXPECT(sixteen.Compression() >= 0.821,
    "16-gon: compression " << sixteen.Compression() << " below the paper's queen (0.821)");

  const FoldingTree eighteen = Fold(MakeChessPiece(18, motion));
  Print("18-gon chess piece", eighteen);
  const std::vector<FoldingNodeKind> path18 = FirstPathKinds(eighteen);
  EXPECT(path18.size() >= 3 && path18[0] == FoldingNodeKind::Folding &&
      path18[1] == FoldingNodeKind::Folding && path18[2] == FoldingNodeKind::Segmentation,
    "18-gon: expected two nested folds, then a segmentation of the quarter");
  EXPECT(eighteen.Compression() >= 0.821,
    "18-gon: compression " << eighteen.Compression() << " below the paper's queen (0.821)");

  const FoldingTree uneven = Fold(MakeChessPiece(18, motion, QueenBaseGaps));
  Print("18-gon chess piece, uneven rings", uneven);
  EXPECT(!uneven.nodes.empty() && uneven.nodes[0].kind == FoldingNodeKind::Folding,
    "uneven 18-gon: the root is not a fold");
  EXPECT(uneven.Compression() >= 0.821,
    "uneven 18-gon: compression " << uneven.Compression() << " below the paper's queen (0.821)");

  // With rotation nodes (issue 22) the builder keeps, at the root, whichever subtree stores
  // fewer faces: the 16-gon's three nested folds store as few as one sector folded once (a
  // tie: the folds stay), while the 18-gon, whose folds stop after two, keeps one sector of 20
  // degrees that a fold through its bisector halves (the dihedral symmetry: rotation + fold).
  // Either way at least 90% compression (issue 22's goal for the queen), never more faces
  // than without rotation nodes, and the unfolded piece closed, within epsilon.
  for (int n : { 16, 18 })
  {
    const TriangleMesh piece = MakeChessPiece(n, motion);
    const FoldingTree turned = Fold(piece, true);
    char name[64];
    std::snprintf(name, sizeof(name), "%d-gon chess piece, rotation nodes", n);
    Print(name, turned);
    const int without = (n == 16 ? sixteen : eighteen).StoredFaces();
    EXPECT(turned.StoredFaces() <= without,
      name << ": stores " << turned.StoredFaces() << " faces, " << without << " without");
    const std::vector<FoldingNodeKind> path = FirstPathKinds(turned);
    if (n == 18)
    {
      EXPECT(path.size() >= 3 && path[0] == FoldingNodeKind::Rotation &&
          path[1] == FoldingNodeKind::Folding,
        name << ": expected a rotation node, then a fold of its sector");
      EXPECT(turned.nodes[0].rotationOrder == n,
        name << ": order " << turned.nodes[0].rotationOrder << " instead of " << n);
    }
    EXPECT(turned.Compression() >= 0.90,
      name << ": compression " << turned.Compression() << " below 90%");
    EXPECT(turned.verifiedBound >= 0.0 && turned.verifiedBound <= turned.rootEpsilon,
      name << ": proved bound " << turned.verifiedBound << " of " << turned.rootEpsilon);
    const UnfoldedMesh u = coretest::Unfold(turned);
    const coretest::EdgeStats edges = coretest::CountEdges(u.triangles);
    EXPECT(edges.open == 0 && edges.nonManifold == 0 && edges.misoriented == 0,
      name << ": unfolded with " << edges.open << " open, " << edges.nonManifold
           << " non-manifold, " << edges.misoriented << " misoriented edges");
    const double h = coretest::Hausdorff(piece, u);
    EXPECT(h <= turned.rootEpsilon, name << ": Hausdorff " << h << " above epsilon");
  }
  return coretest::Finish("TestFoldingTreeRevolution");
}
