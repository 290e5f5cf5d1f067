// Folding tree construction (paper §4.2) on procedural meshes whose symmetry is known by
// construction (epsilon = 2% of the diagonal unless stated):
// - MakeThreePlaneShape (planes x, y, z): the first three nodes are folding nodes whose planes
//   are the three known planes; with minimumAreaFraction 0.13 the tree is exactly three folds
//   and a leaf storing 1/8 of the faces; with the defaults the octant may fold further (its
//   flat strips are translation invariant) and stores at most about 1/8;
// - MakeBilateralBlob: the root folds on x = 0 into exactly half the faces (the half may
//   fold again on approximate local symmetries; with maximumFolds 1 it stores exactly half);
// - MakeBlobWithAsymmetricPart: the root is a segmentation node whose first child folds on
//   x = 0; its region matches the known symmetric faces (IoU); the tear bits of level 0 mark
//   exactly the leaf points whose input point is shared by faces of two different children;
//   every tear vertex removed by the fold is recorded (MirroredFlag) on a kept point within
//   epsilon of its mirror image;
// - each stop criterion triggers on a case built for it (minimum faces, minimum area,
//   maximum folds, no meaningful symmetry - and the same blob folds when that criterion is
//   off -, maximum depth), and a disabled criterion does not;
// - keep side: on MakeBilateralBlobDifferentTessellation "more faces" stores more than
//   "fewer faces";
// - on every tree: Validate(); epsilon halves below folding nodes and only there; regions
//   partition their parent's (folding: kept + discarded = region); leaf triangles refer to
//   their input triangles (same input points, same orientation); unmoved points are the input
//   points, moved ones the input point projected onto the fold planes it is flagged on or
//   (slid onto one plane) a point of the input surface; points flagged on a fold plane lie on
//   it; statistics are consistent;
// - determinism, progress (monotonic, ends at 1) and abort, bad input.
#include "CoreTestUtilities.h"
#include "FoldingTreeBuilder.h"
#include "ProceduralMeshes.h"
#include "SurfaceDistance.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

using namespace foldingmeshes;
namespace pm = foldingmeshes::testing;

namespace
{
struct Case
{
  pm::ProceduralMesh shape;
  TriangleMesh mesh;
  double diagonal = 0.0;
};

Case MakeCase(pm::ProceduralMesh shape)
{
  Case c;
  c.shape = std::move(shape);
  c.mesh = coretest::ToTriangleMesh(c.shape.mesh);
  c.diagonal = pm::BoundsDiagonal(c.shape.mesh);
  return c;
}

FoldingTreeOptions Options(const Case& c, double fraction = 0.02)
{
  FoldingTreeOptions o;
  o.epsilon = fraction * c.diagonal;
  return o;
}

FoldingTree Build(const Case& c, const FoldingTreeOptions& o)
{
  FoldingTree tree;
  std::string error;
  const bool ok = BuildFoldingTree(c.mesh, {}, o, tree, error);
  REQUIRE(ok, "BuildFoldingTree failed: " << error);
  return tree;
}

void Print(const char* name, const FoldingTree& t)
{
  std::printf("%s: faces %d stored %d compression %.4f height %d folds %d (max %d on a path) "
              "leaves %d time %.2fs\n",
    name,
    t.numberOfOriginalFaces,
    t.StoredFaces(),
    t.Compression(),
    t.Height(),
    t.NumberOfFolds(),
    t.MaximumFoldsOnPath(),
    t.NumberOfLeaves(),
    t.buildSeconds);
  for (int i = 0; i < t.NumberOfNodes(); ++i)
  {
    const FoldingNode& n = t.nodes[i];
    std::printf("  %*s#%d %s eps/diag %.5f faces %d",
      2 * n.depth,
      "",
      i,
      ToString(n.kind),
      n.epsilon / t.diagonal,
      n.numberOfFaces);
    if (n.kind == FoldingNodeKind::Folding)
      std::printf(" n=(%.3f %.3f %.3f) discarded %d projected %d",
        n.plane.normal.x(),
        n.plane.normal.y(),
        n.plane.normal.z(),
        n.discardedFaces,
        n.projectedPoints);
    if (n.kind == FoldingNodeKind::Leaf)
      std::printf(" %s", ToString(n.leafReason));
    std::printf("\n");
  }
}

bool Matches(const pm::KnownPlane& k, const Plane& p, double diagonal, double degrees)
{
  Plane q;
  q.origin = k.origin;
  q.normal = k.normal.normalized();
  return PlaneAngleDegrees(p, q) <= degrees && PlaneOffsetAt(q, p, p.origin) <= 1e-3 * diagonal;
}

/// Closest point to x on the intersection of the planes (x itself for none).
Vec3 ProjectOntoIntersection(const Vec3& x, const std::vector<Plane>& planes)
{
  if (planes.empty())
    return x;
  Eigen::MatrixXd A(planes.size(), 3);
  Eigen::VectorXd r(planes.size());
  for (size_t k = 0; k < planes.size(); ++k)
  {
    A.row(k) = planes[k].normal.transpose();
    r[k] = -planes[k].SignedDistance(x);
  }
  return x + Eigen::Vector3d(A.completeOrthogonalDecomposition().solve(r));
}

/// The chain of nodes from the root following first children.
std::vector<int> FirstPath(const FoldingTree& t)
{
  std::vector<int> path{ 0 };
  while (!t.nodes[path.back()].children.empty())
    path.push_back(t.nodes[path.back()].children[0]);
  return path;
}

/// Checks that hold for every tree.
void CheckInvariants(const char* name, const Case& c, const FoldingTree& t, double rootEpsilon)
{
  const std::string problem = t.Validate();
  EXPECT(problem.empty(), name << ": Validate: " << problem);
  if (!problem.empty())
    return;
  EXPECT(t.numberOfOriginalFaces == static_cast<int>(c.mesh.triangles.size()),
    name << ": original faces");
  // The requested epsilon, or the smaller one of a near-miss rebuild (NearMissBoundRatio).
  const bool nearMiss = t.verificationRounds >= 1 && t.rootEpsilon < rootEpsilon &&
    t.rootEpsilon >= rootEpsilon * NearMissEpsilonMargin / NearMissBoundRatio;
  EXPECT((t.rootEpsilon == rootEpsilon || nearMiss) && t.nodes[0].epsilon == t.rootEpsilon,
    name << ": root epsilon " << t.rootEpsilon << " of " << rootEpsilon << ", "
         << t.verificationRounds << " verification rounds");
  if (nearMiss)
    std::printf("%s: a near-miss rebuild at %.4f of epsilon\n", name, t.rootEpsilon / rootEpsilon);
  int stored = 0;
  const SurfaceDistanceQuery inputSurface(c.mesh);
  for (int i = 0; i < t.NumberOfNodes(); ++i)
  {
    const FoldingNode& n = t.nodes[i];
    EXPECT(n.numberOfFaces == static_cast<int>(n.originalFaces.size()),
      name << ": node " << i << " face count");
    if (n.parent >= 0)
    {
      const FoldingNode& p = t.nodes[n.parent];
      const double expected = p.kind == FoldingNodeKind::Folding ? 0.5 * p.epsilon : p.epsilon;
      EXPECT(n.epsilon == expected,
        name << ": node " << i << " epsilon " << n.epsilon << " parent (" << ToString(p.kind)
             << ") " << p.epsilon);
    }
    // Partition of the region among the children (plus the discarded faces of a fold).
    if (n.kind != FoldingNodeKind::Leaf)
    {
      std::vector<int> all = n.discardedOriginalFaces;
      for (int child : n.children)
        all.insert(
          all.end(), t.nodes[child].originalFaces.begin(), t.nodes[child].originalFaces.end());
      std::sort(all.begin(), all.end());
      EXPECT(all == n.originalFaces,
        name << ": node " << i << " children (and discarded faces) do not partition its region");
    }
    if (n.kind == FoldingNodeKind::Folding)
      EXPECT(n.discardedFaces == static_cast<int>(n.discardedOriginalFaces.size()),
        name << ": node " << i << " discarded count");
    if (n.kind != FoldingNodeKind::Leaf)
      continue;
    const FoldingLeafMesh& m = n.mesh;
    stored += m.NumberOfFaces();
    std::vector<int> sortedFaces = m.originalFaceIds;
    std::sort(sortedFaces.begin(), sortedFaces.end());
    EXPECT(sortedFaces == n.originalFaces, name << ": leaf " << i << " face ids != region");
    int badTriangles = 0, movedPoints = 0, offPlane = 0;
    for (int f = 0; f < m.NumberOfFaces(); ++f)
    {
      const Triangle& in = c.mesh.triangles[m.originalFaceIds[f]];
      const Triangle& lt = m.triangles[f];
      bool same = false;
      for (int r = 0; r < 3; ++r)
        same = same ||
          (m.originalPointIds[lt[0]] == in[r] && m.originalPointIds[lt[1]] == in[(r + 1) % 3] &&
            m.originalPointIds[lt[2]] == in[(r + 2) % 3]);
      badTriangles += !same;
    }
    for (int v = 0; v < m.NumberOfPoints(); ++v)
    {
      const Vec3& input = c.mesh.points[m.originalPointIds[v]];
      EXPECT(!m.projected[v] || m.planeMask[v] != 0, name << ": projected point without plane");
      // Points flagged on fold planes lie on them and are the input point projected onto
      // their intersection; the others are the input points.
      std::vector<Plane> planes;
      for (int a = n.parent; a >= 0; a = t.nodes[a].parent)
        if (t.nodes[a].kind == FoldingNodeKind::Folding &&
          (m.planeMask[v] & (uint64_t(1) << t.nodes[a].depth)))
        {
          planes.push_back(t.nodes[a].plane);
          offPlane += std::abs(t.nodes[a].plane.SignedDistance(m.points[v])) > 1e-9 * c.diagonal;
        }
      // A projected point may instead have slid along an input edge onto its plane
      // (slideOntoPlane): then it lies on the input surface (up to later snaps onto other
      // planes, planeSnapFraction * epsilon each).
      const bool slid = m.projected[v] &&
        inputSurface.Distance(m.points[v]) <=
          1e-9 * c.diagonal + 0.01 * rootEpsilon * static_cast<double>(planes.size());
      movedPoints +=
        !slid && (m.points[v] - ProjectOntoIntersection(input, planes)).norm() > 1e-9 * c.diagonal;
    }
    EXPECT(badTriangles == 0,
      name << ": leaf " << i << ": " << badTriangles
           << " triangles differ from their input triangle");
    EXPECT(movedPoints == 0,
      name << ": leaf " << i << ": " << movedPoints << " points moved without reason");
    EXPECT(offPlane == 0,
      name << ": leaf " << i << ": " << offPlane << " points flagged on a fold plane lie off it");
  }
  EXPECT(stored == t.StoredFaces(), name << ": StoredFaces");
  EXPECT(std::abs(t.Compression() - (1.0 - static_cast<double>(stored) / t.numberOfOriginalFaces)) <
      1e-12,
    name << ": Compression");
}

int LeafAt(const FoldingTree& t, int depth, LeafReason reason)
{
  for (int i = 0; i < t.NumberOfNodes(); ++i)
    if (t.nodes[i].kind == FoldingNodeKind::Leaf && t.nodes[i].depth == depth &&
      t.nodes[i].leafReason == reason)
      return i;
  return -1;
}

void TestThreePlaneShape()
{
  const Case c = MakeCase(pm::MakeThreePlaneShape(4000));
  const int F = static_cast<int>(c.mesh.triangles.size());
  {
    FoldingTreeOptions o = Options(c);
    const FoldingTree t = Build(c, o);
    Print("three-plane shape, defaults", t);
    CheckInvariants("three-plane defaults", c, t, o.epsilon);
    const std::vector<int> path = FirstPath(t);
    std::set<int> matched;
    for (int k = 0; k < 3 && k < static_cast<int>(path.size()); ++k)
    {
      const FoldingNode& n = t.nodes[path[k]];
      EXPECT(n.kind == FoldingNodeKind::Folding,
        "three-plane: node at depth " << k << " is " << ToString(n.kind));
      EXPECT(n.epsilon == o.epsilon / (1 << k), "three-plane: epsilon at depth " << k);
      for (size_t j = 0; j < c.shape.planes.size(); ++j)
        if (Matches(c.shape.planes[j], n.plane, c.diagonal, 0.5))
          matched.insert(static_cast<int>(j));
    }
    EXPECT(matched.size() == 3,
      "three-plane: the first three folds use " << matched.size() << " of the 3 planes");
    EXPECT(t.StoredFaces() <= F / 8 + 0.02 * F && t.StoredFaces() >= 0.05 * F,
      "three-plane defaults: stored " << t.StoredFaces() << " of " << F << " (about 1/8 expected)");
  }
  {
    // Leaves once the area is below 13% (the octant has 12.5%): exactly the three planes.
    FoldingTreeOptions o = Options(c);
    o.minimumAreaFraction = 0.13;
    const FoldingTree t = Build(c, o);
    Print("three-plane shape, minimum area 0.13", t);
    CheckInvariants("three-plane area 0.13", c, t, o.epsilon);
    EXPECT(t.NumberOfFolds() == 3 && t.NumberOfNodes() == 4 && t.Height() == 4,
      "three-plane area 0.13: " << t.NumberOfFolds() << " folds, " << t.NumberOfNodes()
                                << " nodes, height " << t.Height());
    EXPECT(std::abs(t.StoredFaces() - F / 8.0) <= 0.01 * F,
      "three-plane area 0.13: stored " << t.StoredFaces() << ", 1/8 is " << F / 8.0);
    EXPECT(LeafAt(t, 3, LeafReason::MinimumArea) >= 0,
      "three-plane area 0.13: no MinimumArea leaf "
      "at depth 3");
    const int leaf = LeafAt(t, 3, LeafReason::MinimumArea);
    if (leaf >= 0)
      EXPECT(t.nodes[leaf].epsilon == o.epsilon / 8, "three-plane: leaf epsilon not eps/8");
  }
}

void TestBilateralBlob()
{
  const Case c = MakeCase(pm::MakeBilateralBlob(4000));
  const int F = static_cast<int>(c.mesh.triangles.size());
  FoldingTreeOptions o = Options(c);
  const FoldingTree t = Build(c, o);
  Print("bilateral blob", t);
  CheckInvariants("bilateral blob", c, t, o.epsilon);
  const FoldingNode& root = t.nodes[0];
  EXPECT(root.kind == FoldingNodeKind::Folding &&
      Matches(c.shape.planes[0], root.plane, c.diagonal, 0.5),
    "bilateral blob: root is not a fold on x = 0");
  // The half has F/2 faces; it may fold further on approximate local symmetries.
  EXPECT(t.nodes[1].numberOfFaces == F / 2 && t.StoredFaces() <= F / 2,
    "bilateral blob: half " << t.nodes[1].numberOfFaces << ", stored " << t.StoredFaces() << " of "
                            << F);
  o.maximumFolds = 1;
  const FoldingTree once = Build(c, o);
  CheckInvariants("bilateral blob, one fold", c, once, o.epsilon);
  EXPECT(once.NumberOfFolds() == 1 && once.StoredFaces() == F / 2,
    "bilateral blob, one fold: " << once.NumberOfFolds() << " folds, stored " << once.StoredFaces()
                                 << " of " << F);
}

void TestAsymmetricAttachment()
{
  // Attachment fraction 0.1: at 0.15 and above the detector prefers a spurious plane on some
  // seeds (found = false), see the report.
  const Case c = MakeCase(pm::MakeBlobWithAsymmetricPart(4000, 0.1));
  FoldingTreeOptions o = Options(c);
  const FoldingTree t = Build(c, o);
  Print("blob with asymmetric attachment", t);
  CheckInvariants("attachment", c, t, o.epsilon);
  const FoldingNode& root = t.nodes[0];
  REQUIRE(root.kind == FoldingNodeKind::Segmentation && root.children.size() >= 2,
    "attachment: the root is " << ToString(root.kind) << " with " << root.children.size()
                               << " children, expected a segmentation node");
  const FoldingNode& fold = t.nodes[root.children[0]];
  EXPECT(fold.kind == FoldingNodeKind::Folding &&
      Matches(c.shape.planes[0], fold.plane, c.diagonal, 1.0),
    "attachment: first child is not a fold on x = 0");
  std::vector<char> S(c.mesh.triangles.size(), 0);
  for (int f : fold.originalFaces)
    S[f] = 1;
  const double iou = pm::RegionIoU(c.shape.mesh, S, c.shape.symmetricFace);
  std::printf("attachment: IoU(S, truth) = %.4f\n", iou);
  EXPECT(iou >= 0.9, "attachment: IoU of S with the known symmetric part " << iou);

  // Expected tear vertices of level 0: input points used by faces of two different children.
  std::vector<int> childOfFace(c.mesh.triangles.size(), -1);
  for (size_t k = 0; k < root.children.size(); ++k)
    for (int f : t.nodes[root.children[k]].originalFaces)
      childOfFace[f] = static_cast<int>(k);
  std::vector<int> firstChild(c.mesh.points.size(), -1);
  std::vector<char> expected(c.mesh.points.size(), 0);
  for (size_t f = 0; f < c.mesh.triangles.size(); ++f)
    for (int v : c.mesh.triangles[f])
    {
      if (firstChild[v] < 0)
        firstChild[v] = childOfFace[f];
      else if (firstChild[v] != childOfFace[f])
        expected[v] = 1;
    }
  int expectedCount = 0, flagged = 0, wrong = 0;
  for (char e : expected)
    expectedCount += e;
  std::vector<char> present(c.mesh.points.size(), 0);
  for (int leaf : t.Leaves())
  {
    const FoldingLeafMesh& m = t.nodes[leaf].mesh;
    for (int v = 0; v < m.NumberOfPoints(); ++v)
    {
      const int id = m.originalPointIds[v];
      const bool bit = (m.tearMask[v] & 1) != 0;
      present[id] = 1;
      flagged += bit;
      wrong += bit != bool(expected[id]);
    }
  }
  std::printf("attachment: %d tear vertices at level 0, %d flagged leaf points, %d wrong\n",
    expectedCount,
    flagged,
    wrong);
  EXPECT(expectedCount > 10, "attachment: only " << expectedCount << " boundary vertices");
  EXPECT(wrong == 0, "attachment: " << wrong << " leaf points with a wrong level-0 tear bit");
  // Tear vertices removed by a fold (of S or of an attachment region): recorded on a kept
  // point near their mirror image through that fold.
  int removed = 0, recorded = 0;
  for (size_t v = 0; v < expected.size(); ++v)
  {
    if (!expected[v] || present[v])
      continue;
    ++removed;
    bool found = false;
    for (int leaf : t.Leaves())
    {
      const FoldingLeafMesh& m = t.nodes[leaf].mesh;
      for (int a = t.nodes[leaf].parent; a >= 0; a = t.nodes[a].parent)
      {
        const FoldingNode& f = t.nodes[a];
        if (f.kind != FoldingNodeKind::Folding)
          continue;
        const Vec3 mirror = f.plane.Reflect(c.mesh.points[v]);
        for (const MirroredFlag& r : m.mirroredFlags)
          found = found ||
            (r.flag == LevelFlag::Tear && r.level == 0 &&
              (r.mirrorMask & (uint64_t(1) << f.depth)) &&
              (m.points[r.point] - mirror).norm() <= o.epsilon);
      }
    }
    recorded += found;
  }
  std::printf("attachment: %d tear vertices removed by folds, %d recorded on mirror points\n",
    removed,
    recorded);
  EXPECT(removed > 0 && recorded == removed,
    "attachment: " << recorded << " of " << removed << " removed tear vertices recorded");
}

void TestStopCriteria()
{
  const Case box = MakeCase(pm::MakeThreePlaneShape(4000));
  const int F = static_cast<int>(box.mesh.triangles.size());
  {
    FoldingTreeOptions o = Options(box);
    o.useMinimumAreaFraction = false;
    o.minimumFaces = F / 4 + 10; // the quarter is below it
    const FoldingTree t = Build(box, o);
    CheckInvariants("minimum faces", box, t, o.epsilon);
    EXPECT(t.NumberOfFolds() == 2 && LeafAt(t, 2, LeafReason::MinimumFaces) >= 0,
      "minimum faces: " << t.NumberOfFolds() << " folds, no MinimumFaces leaf at depth 2");
  }
  {
    FoldingTreeOptions o = Options(box);
    o.useMinimumFaces = false;
    o.minimumAreaFraction = 0.3; // the quarter (0.25) is below it
    const FoldingTree t = Build(box, o);
    CheckInvariants("minimum area", box, t, o.epsilon);
    EXPECT(t.NumberOfFolds() == 2 && LeafAt(t, 2, LeafReason::MinimumArea) >= 0,
      "minimum area: " << t.NumberOfFolds() << " folds, no MinimumArea leaf at depth 2");
    // Disabled: the same threshold has no effect.
    o.useMinimumAreaFraction = false;
    o.minimumAreaFraction = 0.9;
    const FoldingTree u = Build(box, o);
    EXPECT(u.NumberOfFolds() >= 3, "minimum area disabled: only " << u.NumberOfFolds() << " folds");
    EXPECT(LeafAt(u, 3, LeafReason::MinimumArea) < 0, "disabled minimum area still triggered");
  }
  {
    FoldingTreeOptions o = Options(box);
    o.maximumFolds = 1;
    const FoldingTree t = Build(box, o);
    CheckInvariants("maximum folds", box, t, o.epsilon);
    EXPECT(t.NumberOfFolds() == 1 && LeafAt(t, 1, LeafReason::MaximumFolds) >= 0 &&
        t.StoredFaces() == F / 2,
      "maximum folds 1: " << t.NumberOfFolds() << " folds, stored " << t.StoredFaces());
    o.maximumFolds = 2;
    const FoldingTree u = Build(box, o);
    EXPECT(u.MaximumFoldsOnPath() == 2 && LeafAt(u, 2, LeafReason::MaximumFolds) >= 0,
      "maximum folds 2: " << u.MaximumFoldsOnPath() << " folds on a path");
  }
  {
    FoldingTreeOptions o = Options(box);
    o.maximumDepth = 2;
    const FoldingTree t = Build(box, o);
    CheckInvariants("maximum depth", box, t, o.epsilon);
    EXPECT(t.Height() <= 2 && LeafAt(t, 1, LeafReason::MaximumDepth) >= 0,
      "maximum depth 2: height " << t.Height());
  }
  {
    const Case blob = MakeCase(pm::MakeAsymmetricBlob(4000));
    FoldingTreeOptions o = Options(blob);
    // By default an accidental epsilon-symmetric patch may be folded (within the bound).
    const FoldingTree loose = Build(blob, o);
    CheckInvariants("no symmetry, loose", blob, loose, o.epsilon);
    // With the residual rule, the blob has no symmetry at all.
    o.requireTightSymmetry = true;
    const FoldingTree t = Build(blob, o);
    CheckInvariants("no symmetry", blob, t, o.epsilon);
    EXPECT(t.NumberOfNodes() == 1 && t.nodes[0].leafReason == LeafReason::NoSymmetry &&
        t.nodes[0].detectionRun,
      "asymmetric blob: expected a NoSymmetry root leaf");
    EXPECT(t.StoredFaces() == t.numberOfOriginalFaces, "asymmetric blob: faces not all stored");
    // Without the criterion the (meaningless) region is folded.
    o.requireMeaningfulSymmetry = false;
    const FoldingTree u = Build(blob, o);
    CheckInvariants("no symmetry off", blob, u, o.epsilon);
    EXPECT(u.nodes[0].kind != FoldingNodeKind::Leaf,
      "asymmetric blob without the meaningful-symmetry criterion: root is still a leaf");
  }
}

void TestKeepSide()
{
  const Case c = MakeCase(pm::MakeBilateralBlobDifferentTessellation(4000));
  FoldingTreeOptions o = Options(c);
  o.maximumFolds = 1;
  const FoldingTree more = Build(c, o);
  o.keepSide = KeepSide::FewerFaces;
  const FoldingTree fewer = Build(c, o);
  CheckInvariants("keep more", c, more, o.epsilon);
  CheckInvariants("keep fewer", c, fewer, o.epsilon);
  std::printf("keep side: more faces -> stored %d, fewer faces -> stored %d (of %d)\n",
    more.StoredFaces(),
    fewer.StoredFaces(),
    more.numberOfOriginalFaces);
  EXPECT(more.nodes[0].kind == FoldingNodeKind::Folding &&
      fewer.nodes[0].kind == FoldingNodeKind::Folding,
    "keep side: the root is not a fold");
  EXPECT(more.StoredFaces() > 1.2 * fewer.StoredFaces(),
    "keep side: more " << more.StoredFaces() << " vs fewer " << fewer.StoredFaces());
  // The stored plane normal points into the kept half: opposite for the two choices.
  EXPECT(more.nodes[0].plane.normal.dot(fewer.nodes[0].plane.normal) < -0.99,
    "keep side: the kept halves are not opposite");
}

void TestDeterminismProgressAbort()
{
  const Case c = MakeCase(pm::MakeBlobWithAsymmetricPart(3000, 0.1, 2));
  FoldingTreeOptions o = Options(c);
  std::vector<double> values;
  o.progress = [&](double p)
  {
    values.push_back(p);
    return true;
  };
  const FoldingTree a = Build(c, o);
  o.progress = nullptr;
  const FoldingTree b = Build(c, o);
  EXPECT(coretest::SameTree(a, b), "determinism: two builds differ");
  bool monotonic = !values.empty();
  for (size_t k = 0; k < values.size(); ++k)
    monotonic =
      monotonic && values[k] >= 0.0 && values[k] <= 1.0 && (k == 0 || values[k] >= values[k - 1]);
  EXPECT(monotonic && values.back() == 1.0,
    "progress: " << values.size() << " calls, not monotonic in [0,1] ending at 1");

  int calls = 0;
  o.progress = [&](double) { return ++calls < 3; };
  const FoldingTree aborted = Build(c, o);
  EXPECT(aborted.aborted, "abort: tree not marked aborted");
  EXPECT(aborted.Validate().empty(), "abort: invalid tree: " << aborted.Validate());
  EXPECT(LeafAt(aborted, aborted.nodes.back().depth, LeafReason::Aborted) >= 0 ||
      aborted.nodes[0].leafReason == LeafReason::Aborted,
    "abort: no Aborted leaf");
}

void TestBadInput()
{
  FoldingTreeOptions o;
  o.epsilon = 0.01;
  FoldingTree t;
  std::string error;
  TriangleMesh empty;
  EXPECT(!BuildFoldingTree(empty, {}, o, t, error) && !error.empty() && t.Empty(),
    "empty mesh accepted");
  TriangleMesh tri;
  tri.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) };
  tri.triangles = { { 0, 1, 2 } };
  o.epsilon = 0.0;
  EXPECT(!BuildFoldingTree(tri, {}, o, t, error), "zero epsilon accepted");
  o.epsilon = 0.01;
  EXPECT(BuildFoldingTree(tri, {}, o, t, error) && t.NumberOfNodes() == 1 &&
      t.nodes[0].leafReason == LeafReason::MinimumFaces && t.StoredFaces() == 1,
    "a single triangle: " << error);
  TriangleMesh bad = tri;
  bad.triangles.push_back({ 0, 1, 7 });
  EXPECT(!BuildFoldingTree(bad, {}, o, t, error), "index out of range accepted");
  bad = tri;
  bad.points[1].x() = std::nan("");
  EXPECT(!BuildFoldingTree(bad, {}, o, t, error), "NaN accepted");
  EXPECT(!BuildFoldingTree(tri, { Vec3::UnitZ() }, o, t, error), "wrong normal count accepted");
  // Degenerate input triangles (repeated index) are dropped and counted.
  bad = tri;
  bad.triangles.push_back({ 0, 0, 1 });
  EXPECT(
    BuildFoldingTree(bad, {}, o, t, error) && t.numberOfDroppedFaces == 1 && t.StoredFaces() == 1,
    "repeated-index triangle not dropped");
}
}

int main()
{
  TestThreePlaneShape();
  TestBilateralBlob();
  TestAsymmetricAttachment();
  TestStopCriteria();
  TestKeepSide();
  TestDeterminismProgressAbort();
  TestBadInput();
  return coretest::Finish("TestFoldingTreeBuilder");
}
