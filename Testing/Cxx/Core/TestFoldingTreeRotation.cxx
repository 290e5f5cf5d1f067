// Rotation nodes of the folding tree (issue 22; FoldingTreeOptions::rotationNodes) on
// procedural shapes whose axis and order are exact by construction (RotationTestShapes.h),
// each moved by a seeded rigid motion:
// - twisted k-fold vases, k = 2..12 (no mirror plane): the root is a rotation node of order
//   k about the moved z axis (within 0.5 degrees, 0.5% of the diagonal), the tree stores at
//   most 1/k of the faces plus a seam's worth, and unfold(fold(M)) is closed, consistently and
//   outward oriented (same volume within 1%), within epsilon of M (brute-force Hausdorff,
//   independent of the builder's own proof, which must hold too);
// - the same with noise of 0.05 epsilon per coordinate;
// - a surface of revolution with rings of 48 vertices: "continuous", the order is the largest
//   whose sector has whole faces (48), and the sector is folded again below it;
// - a surface of revolution whose rings each have their own phase (no column of vertices):
//   the builder cuts the faces along the sector's half-planes; fewer faces than planes alone;
//   with polygon caps (the axis through a cap's diagonal) a rotation node too, whose sectors
//   (cut) hold at most three times the input's faces;
// - the verification's fallback, forced on that vase with a distance query that lies about the
//   rotation tree's unfold: rebuilt without second orders, then with the planes alone, which
//   stand, within epsilon;
// - a vase beside a separate box: the vase is a remaining region of the root's segmentation
//   and becomes a rotation node of its own;
// - with rotation nodes off, or on a shape with no rotational symmetry (a lumpy vase), no
//   rotation node;
// - flat fans of 5, 6 and 12 triangles about a centre (the root a rotation node, its sector
//   one face): the turned copies meet in one pole, the faces and area those of the input.
// Run with FOLDINGMESHES_TRACE set to see the builder's decisions.
//
//   TestFoldingTreeRotation
#include "CoreTestUtilities.h"
#include "RotationTestShapes.h"

#include "ClosestFaceQuery.h"
#include "FoldingTreeBuilder.h"
#include "PointTriangleDistance.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

using namespace foldingmeshes;
using namespace rotationtest;

namespace
{
TriangleMesh Moved(TriangleMesh m, const Eigen::Isometry3d& motion)
{
  for (Vec3& p : m.points)
    p = motion * p;
  return m;
}

/// Adds noise of `amount` per coordinate (seeded, uniform).
void AddNoise(TriangleMesh& m, double amount, unsigned seed)
{
  std::mt19937 g(seed);
  for (Vec3& p : m.points)
    p += amount * Vec3(Uniform(g), Uniform(g), Uniform(g));
}

int CountRotationNodes(const FoldingTree& tree, int& first)
{
  int count = 0;
  first = -1;
  for (int i = 0; i < tree.NumberOfNodes(); ++i)
    if (tree.nodes[i].kind == FoldingNodeKind::Rotation)
    {
      if (first < 0)
        first = i;
      ++count;
    }
  return count;
}

/// Folds m (rotation nodes on unless `rotation` is false) and checks the round trip (closed
/// and oriented, volume, Hausdorff within epsilon, the proved bound); returns the tree.
FoldingTree FoldAndCheck(const char* name, const TriangleMesh& m, bool rotation = true)
{
  const double epsilon = 0.02 * coretest::Diagonal(m);
  FoldingTreeOptions o;
  o.rotationNodes = rotation;
  o.rotationNodesWhenAxial = false;       // off: the planes alone (the default would turn them on)
  if (std::getenv("FOLDINGMESHES_TRACE")) // the builder's decisions, for a failing case
    o.trace = [](const std::string& line) { std::printf("%s\n", line.c_str()); };
  const FoldingTree tree = coretest::Fold(m, epsilon, o);
  EXPECT(tree.Validate().empty(), name << ": invalid tree: " << tree.Validate());
  const UnfoldedMesh u = coretest::Unfold(tree);
  // Closed and oriented where rotation nodes are on (with them off, the mirror folds of the
  // chiral vases leave a few open seam edges: issue 21's open seams, not this test's subject).
  const coretest::EdgeStats edges = coretest::CountEdges(u.triangles);
  EXPECT(!rotation || (edges.open == 0 && edges.nonManifold == 0 && edges.misoriented == 0),
    name << ": unfolded mesh not closed and oriented: " << edges.open << " open, "
         << edges.nonManifold << " non-manifold, " << edges.misoriented << " misoriented edges");
  const double v0 = coretest::SignedVolume(m.points, m.triangles);
  const double v1 = coretest::SignedVolume(u.points, u.triangles);
  EXPECT(std::abs(v1 - v0) <= 0.01 * std::abs(v0),
    name << ": volume " << v1 << " instead of " << v0 << " (orientation or shape lost)");
  const double h = coretest::Hausdorff(m, u);
  EXPECT(h <= epsilon, name << ": Hausdorff distance " << h << " above epsilon " << epsilon);
  EXPECT(tree.verifiedBound >= 0.0 && tree.verifiedBound <= epsilon,
    name << ": proved bound " << tree.verifiedBound << " (epsilon " << epsilon << ")");
  std::printf("%-28s faces %6d -> %5d (%.1f%%), nodes %3d, Hausdorff %.3g eps, bound %.3g eps\n",
    name,
    tree.numberOfOriginalFaces,
    tree.StoredFaces(),
    100.0 * tree.Compression(),
    tree.NumberOfNodes(),
    h / epsilon,
    tree.verifiedBound / epsilon);
  return tree;
}

/// The rotation node `index` has order k about the z axis moved by `motion`.
void CheckAxis(const char* name,
  const FoldingTree& tree,
  int index,
  int k,
  const Eigen::Isometry3d& motion)
{
  REQUIRE(index >= 0, name << ": no rotation node");
  const FoldingNode& node = tree.nodes[index];
  EXPECT(node.rotationOrder == k, name << ": order " << node.rotationOrder << " instead of " << k);
  RotationAxis truth;
  truth.origin = motion * Vec3(0, 0, 1);
  truth.direction = motion.linear() * Vec3::UnitZ();
  const double angle = AxisAngleDegrees(node.axis, truth);
  const double offset = AxisOffsetAt(node.axis, truth, truth.origin) / tree.diagonal;
  EXPECT(angle < 0.5 && offset < 0.005,
    name << ": axis off by " << angle << " degrees, " << offset << " diagonals");
}

void TwistedVases(bool noisy)
{
  for (int k = 2; k <= 12; ++k)
  {
    VaseShape s;
    s.order = k;
    s.amplitude = 0.25;
    const int segments = k * ((48 + k - 1) / k);
    const Eigen::Isometry3d motion = Motion(100 + k);
    TriangleMesh m = Moved(MakeVase(s, segments, 24), motion);
    if (noisy)
      AddNoise(m, 0.05 * 0.02 * coretest::Diagonal(m), 7 + k);
    char name[64];
    std::snprintf(name, sizeof(name), "twisted vase k=%d%s", k, noisy ? " noisy" : "");
    const FoldingTree tree = FoldAndCheck(name, m);
    int first = -1;
    const int rotations = CountRotationNodes(tree, first);
    EXPECT(rotations == 1 && first == 0,
      name << ": " << rotations << " rotation nodes, the first at " << first
           << " (expected one, the root)");
    CheckAxis(name, tree, first, k, motion);
    // One sector of faces, plus the faces along one seam (twice a ring's faces / k, rounded).
    const int sector = static_cast<int>(m.triangles.size()) / k;
    EXPECT(tree.StoredFaces() <= sector + 2 * 24 + 4,
      name << ": stores " << tree.StoredFaces() << " faces, one sector has " << sector);
  }
}

void Revolution()
{
  VaseShape s; // amplitude 0: a surface of revolution
  const Eigen::Isometry3d motion = Motion(31);
  const TriangleMesh m = Moved(MakeVase(s, 48, 24), motion);
  const FoldingTree tree = FoldAndCheck("revolution, 48 segments", m);
  int first = -1;
  CountRotationNodes(tree, first);
  CheckAxis("revolution, 48 segments", tree, first, 48, motion);
  EXPECT(tree.Compression() >= 0.95,
    "revolution: compression " << tree.Compression() << " below 95% (one 48th is 97.9%)");
}

/// Fine rings (40 vertices): whole faces, seams turned onto the half-planes. Coarse rings (12
/// vertices): turning the seams would flip faces, so the faces are cut along the half-planes.
/// With polygon caps (no vertex on the axis: the axis passes through a diagonal of each cap,
/// triangulated in large faces across it), the sectors of whole faces do not cover the caps
/// once, and the cut sectors of those orders (the second pass) are cut at the axis too: the
/// root is a rotation node there (before the second pass: the planes alone). Never more
/// faces than the planes alone, k sectors hold at most three times the input's faces, nothing
/// open. A rotation tree whose unfolded area is above RotationAreaRatioLimit times the input's
/// (surface laid twice) is rebuilt with the planes alone, which the builder keeps where they lay
/// less twice: since 2026-12-07 the 12-segment vase with poles keeps its planes' tree (335
/// faces, about its own area; its rotation tree, 210 faces, came back with 1.217 times it); the
/// other two keep their rotation trees.
void Staggered()
{
  for (int segments : { 40, 12, -12 })
  {
    const Eigen::Isometry3d motion = Motion(77 + std::abs(segments));
    VaseShape s; // a surface of revolution whose rings are turned against each other
    s.staggered = 1.0;
    s.polygonCaps = segments < 0;
    segments = std::abs(segments);
    const TriangleMesh m = Moved(MakeVase(s, segments, 24), motion);
    char name[64];
    std::snprintf(name,
      sizeof(name),
      "staggered revolution %d%s",
      segments,
      s.polygonCaps ? " with polygon caps" : "");
    const FoldingTree tree = FoldAndCheck(name, m);
    int first = -1;
    const int rotations = CountRotationNodes(tree, first);
    const double area = coretest::SurfaceArea(m.points, m.triangles);
    auto areaRatio = [&](const FoldingTree& t)
    {
      const UnfoldedMesh unfolded = coretest::Unfold(t);
      return coretest::SurfaceArea(unfolded.points, unfolded.triangles) / area;
    };
    // The tree before the verification's rebuilds: a rotation tree at the root.
    FoldingTreeOptions unverified;
    unverified.rotationNodes = true;
    unverified.verifyBound = false;
    const FoldingTree firstTree = coretest::Fold(m, 0.02 * coretest::Diagonal(m), unverified);
    int firstTreeRoot = -1;
    EXPECT(CountRotationNodes(firstTree, firstTreeRoot) == 1 && firstTreeRoot == 0,
      name << ": the first tree has no rotation node at its root");
    const double firstArea = areaRatio(firstTree);
    const double keptArea = areaRatio(tree);
    // The 12-segment vase with poles lays surface twice: its planes' tree is kept.
    const bool planesKept = segments == 12 && !s.polygonCaps;
    EXPECT(planesKept ? rotations == 0 && firstArea > RotationAreaRatioLimit && keptArea < firstArea
                      : rotations == 1 && first == 0 && keptArea <= RotationAreaRatioLimit,
      name << ": " << rotations << " rotation nodes, the first at " << first << ", area "
           << keptArea << " of the input's (the first tree's " << firstArea << ")");
    FoldingTreeOptions planesAlone;
    planesAlone.rotationNodesWhenAxial = false;
    const FoldingTree planes = coretest::Fold(m, 0.02 * coretest::Diagonal(m), planesAlone);
    EXPECT(rotations == 0 ? tree.StoredFaces() <= planes.StoredFaces()
                          : tree.StoredFaces() < planes.StoredFaces(),
      name << ": " << tree.StoredFaces() << " faces stored, " << planes.StoredFaces()
           << " with planes alone");
    EXPECT(first < 0 ||
        tree.nodes[first].rotationOrder * tree.nodes[first + 1].numberOfFaces <=
          3.0 * m.triangles.size(),
      name << ": the sectors hold more than three times the faces");
    // A cut sector holds more faces than its share of the input (the 12-segment vases'): its k
    // copies, the sector included, are thinned towards the region's face count, as a fold's
    // mirrored copy is (Unfolder::Turn; FoldAndCheck proved the bound with them): the rotation
    // node's own line of the thinning's trace says how many faces its result had above the region's
    // count and how many points it removed - some wherever there were at least two faces above it
    // (a sector of whole faces, the 40-segment vase's: none above, none removed).
    UnfoldOptions traced;
    int above = -1, removed = -1;
    traced.trace = [&](const std::string& line)
    {
      if (line.rfind("[density] rotation at depth 0", 0) != 0)
        return;
      const size_t result = line.find("result ");
      const size_t points = line.find("removed ");
      int faces = 0;
      if (result == std::string::npos ||
        std::sscanf(line.c_str() + result, "result %d faces, %d above", &faces, &above) != 2)
        above = -2;
      removed = 0;
      if (points != std::string::npos)
        std::sscanf(line.c_str() + points, "removed %d points", &removed);
    };
    const UnfoldedMesh u = coretest::Unfold(tree, traced);
    UnfoldOptions unthinned;
    unthinned.matchDiscardedDensity = false;
    const size_t thick = coretest::Unfold(tree, unthinned).triangles.size();
    EXPECT(first != 0 || (above >= 0 && (above < 2 ? removed == 0 : removed > 0)),
      name << ": the rotation node's thinning: " << above << " faces above its region's, "
           << removed << " points removed");
    EXPECT(removed <= 0 || u.triangles.size() < thick,
      name << ": " << u.triangles.size() << " unfolded faces, " << thick << " unthinned");
    std::printf("%-28s unfolded %zu faces (unthinned %zu) for %zu; the rotation's result %d "
                "faces above its region's, %d points removed\n",
      name,
      u.triangles.size(),
      thick,
      m.triangles.size(),
      above,
      removed);
  }
}

void VaseBesideBox()
{
  VaseShape s;
  s.order = 5;
  s.amplitude = 0.25;
  TriangleMesh m = MakeVase(s, 50, 24);
  AddBox(m, Vec3(2.5, 0, 1), 0.8);
  const Eigen::Isometry3d motion = Motion(55);
  m = Moved(m, motion);
  const FoldingTree tree = FoldAndCheck("k=5 vase beside a box", m);
  int first = -1;
  const int rotations = CountRotationNodes(tree, first);
  EXPECT(rotations == 1 && first > 0,
    "vase beside a box: " << rotations << " rotation nodes, the first at " << first
                          << " (expected one, below the root)");
  CheckAxis("vase beside a box", tree, first, 5, motion);
}

void NoRotation()
{
  VaseShape s;
  s.order = 6;
  s.amplitude = 0.25;
  const TriangleMesh m = Moved(MakeVase(s, 48, 24), Motion(9));
  int first = -1;
  const FoldingTree off = FoldAndCheck("k=6 vase, rotation off", m, false);
  EXPECT(CountRotationNodes(off, first) == 0, "rotation off: a rotation node was made");
  VaseShape lumpy;
  lumpy.lumpy = true;
  const FoldingTree tree = FoldAndCheck("lumpy vase", Moved(MakeVase(lumpy, 48, 24), Motion(12)));
  EXPECT(CountRotationNodes(tree, first) == 0, "lumpy vase: a rotation node was made");
}

/// Flat regular n-gons as fans about their centre, moved: where the root is a rotation node
/// (its sector one face), the n turned copies meet in one pole (before, rounding left the
/// turned poles apart and the stitch welded them into two points, with faces laid over the
/// hole between them: a fan of 6 came back with 9 faces and 1.5 times its area). The fans of 5
/// and 6 must get a rotation node; the octagon's planes may win (a tie goes to the fold).
void Fans()
{
  int rotated = 0, onePole = 0;
  for (int n : { 5, 6, 8, 12 })
    for (unsigned seed = 1; seed <= 6; ++seed)
    {
      const TriangleMesh fan = Moved(MakeFan(n), Motion(100 + seed));
      FoldingTreeOptions o;
      o.rotationNodes = true;
      o.useMinimumFaces = false;
      const double epsilon = 0.02 * coretest::Diagonal(fan);
      const FoldingTree tree = coretest::Fold(fan, epsilon, o);
      int first = -1;
      CountRotationNodes(tree, first);
      EXPECT(first == 0 || n > 6,
        "fan of " << n << ", motion " << seed << ": the root is not a rotation node");
      if (first != 0)
        continue;
      ++rotated;
      const UnfoldedMesh u = coretest::Unfold(tree);
      int poles = 0;
      for (const Vec3& p : u.points)
        poles += (p - fan.points[0]).norm() <= 1e-9;
      const double ratio = coretest::SurfaceArea(u.points, u.triangles) /
        coretest::SurfaceArea(fan.points, fan.triangles);
      const bool ok =
        poles == 1 && static_cast<int>(u.triangles.size()) == n && std::abs(ratio - 1.0) < 1e-9;
      onePole += ok;
      EXPECT(ok,
        "fan of " << n << ", motion " << seed << ": " << poles << " points at the pole, "
                  << u.triangles.size() << " faces, area ratio " << ratio);
    }
  std::printf("fans of 5, 6, 8, 12 triangles, 6 motions each: %d with a rotation node at the "
              "root, %d of them unfolded with one pole and their own faces\n",
    rotated,
    onePole);
}

/// Closest faces of a surface (a copy) by trying every face; `lie`: face 0 only, whatever is
/// nearer (a query that proves nothing near).
class PlainQuery : public ClosestFaceQuery
{
public:
  PlainQuery(const TriangleMesh& surface, bool lie)
    : Surface(surface)
    , Lie(lie)
  {
  }
  ClosestFaceHit Closest(const Vec3& p) const override
  {
    ClosestFaceHit hit;
    const int faces = this->Lie ? 1 : static_cast<int>(this->Surface.triangles.size());
    for (int f = 0; f < faces; ++f)
    {
      const Triangle& t = this->Surface.triangles[f];
      const ClosestPointOnTriangle cp = ClosestPointTriangle(
        p, this->Surface.points[t[0]], this->Surface.points[t[1]], this->Surface.points[t[2]]);
      if (std::sqrt(cp.squaredDistance) < hit.distance)
        hit = { f, std::sqrt(cp.squaredDistance), cp.point };
    }
    return hit;
  }

private:
  const TriangleMesh Surface;
  const bool Lie;
};

/// The verification's fallback (docs/builder.md, "Rotation nodes" step 8): a tree with rotation
/// nodes that misses the bound is rebuilt without its second orders, if it kept any, then with
/// the planes alone. No shared mesh misses since the rotation check measures the removed faces,
/// so the miss is forced: the verification's distances go through a query that lies (face 0
/// only) for surfaces with more than 1.2 times the input's faces - the unfold of a tree with
/// sectors cut along their half-planes -, and tell the truth for the others (the input, the
/// trims' parts, the planes' unfold). (The unfolder thins the sector's copies since 2026-12-06,
/// fifteenth session; this vase's budgets are spent and its unfold keeps 3.2 times the input's
/// faces, so the test still tells them apart - the REQUIRE below says when it no longer does.)
void FallbackToPlanes()
{
  VaseShape s;
  s.staggered = 1.0;
  s.polygonCaps = true;
  const TriangleMesh m = Moved(MakeVase(s, 12, 24), Motion(89));
  const double epsilon = 0.02 * coretest::Diagonal(m);
  FoldingTreeOptions o;
  o.rotationNodes = true;
  int first = -1;
  const FoldingTree honest = coretest::Fold(m, epsilon, o);
  const size_t unfoldedFaces = coretest::Unfold(honest).triangles.size();
  REQUIRE(CountRotationNodes(honest, first) == 1 && unfoldedFaces > 1.2 * m.triangles.size(),
    "fallback: the vase's tree has no rotation node or unfolds to only " << unfoldedFaces
                                                                         << " faces");
  const double limit = 1.2 * m.triangles.size();
  o.verificationQueries = [limit](const TriangleMesh& surface)
  { return std::make_unique<PlainQuery>(surface, surface.triangles.size() > limit); };
  std::mutex lock;
  std::vector<std::string> lines;
  o.trace = [&](const std::string& line)
  {
    std::lock_guard<std::mutex> guard(lock);
    if (line.rfind("[verify]", 0) == 0)
      lines.push_back(line);
  };
  const FoldingTree tree = coretest::Fold(m, epsilon, o);
  bool planesAlone = false;
  for (const std::string& line : lines)
  {
    planesAlone = planesAlone || line.find("rebuilt with planes alone") != std::string::npos;
    std::printf("fallback: %s\n", line.c_str());
  }
  EXPECT(planesAlone,
    "fallback: no rebuild with the planes alone (" << lines.size() << " [verify] lines)");
  EXPECT(CountRotationNodes(tree, first) == 0 && tree.verificationRounds >= 1,
    "fallback: the kept tree has a rotation node, or no verification round");
  EXPECT(tree.verifiedBound >= 0.0 && tree.verifiedBound <= epsilon &&
      coretest::Hausdorff(m, coretest::Unfold(tree)) <= epsilon,
    "fallback: the planes' tree is not within epsilon (proved " << tree.verifiedBound << ")");
  std::printf("fallback: %zu [verify] lines, the planes' tree stores %d faces (rotation %d)\n",
    lines.size(),
    tree.StoredFaces(),
    honest.StoredFaces());
}
}

int main()
{
  Fans();
  TwistedVases(false);
  TwistedVases(true);
  Revolution();
  Staggered();
  FallbackToPlanes();
  VaseBesideBox();
  NoRotation();
  return coretest::Finish("TestFoldingTreeRotation");
}
