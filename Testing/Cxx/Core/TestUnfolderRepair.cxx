// The unfolder's final repair (UnfoldOptions::closeHoles) on small hand-made trees (one
// leaf: a sphere of about 2000 faces):
// - a hole (the faces around one vertex removed) whose vertices are not on the input's border
//   is filled: no open, non-manifold or misoriented edge is left, the volume keeps its sign,
//   every new face (FoldingFilled) lies within the root epsilon of the sphere; with
//   closeHoles off the hole stays open;
// - a hole on the input's border (inputBoundary set on its vertices) is kept and reported as
//   border; with the border edges listed (inputBorderEdges) only listed edges count; without
//   border information (older files) nothing is filled (unknown loops);
// - a hole whose fill would leave the tolerance (tiny root epsilon) is left open and
//   reported (loops, edges, length);
// - faces flipped by hand are turned back (misoriented 0, the component keeps the
//   orientation of its larger part); an extra face on an edge (non-manifold) is dropped,
//   also when the tree lists other input non-manifold edges;
// - the input's own non-manifold edges (FoldingTree::inputNonManifoldEdges) keep their faces:
//   a fan of 10 triangles on one edge, a face duplicated on the sphere, a two-sided sphere
//   (every edge used by 4 faces) come back with every face, nothing dropped or flipped; a face
//   laid on top of a listed edge (more faces than listed) is dropped (the duplicate, not the
//   input's face); without the list (older tree files) the fan loses all but two faces.
#include "CoreTestUtilities.h"
#include "FoldingTreeUnfolder.h"
#include "ProceduralMeshes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

using namespace foldingmeshes;
namespace pm = foldingmeshes::testing;

namespace
{


/// A one-leaf tree of the unit sphere's mesh `m` (diagonal 2 sqrt 3).
FoldingTree UnitSphereTree(const TriangleMesh& m, double rootEpsilon)
{
  return coretest::LeafTree(m, rootEpsilon, 2.0 * std::sqrt(3.0));
}

/// The sphere without the faces around vertex `center`; `loop` gets the hole's vertices.
TriangleMesh Holed(const TriangleMesh& sphere, int center, std::set<int>& loop)
{
  TriangleMesh m;
  m.points = sphere.points;
  for (const Triangle& t : sphere.triangles)
  {
    if (std::find(t.begin(), t.end(), center) == t.end())
    {
      m.triangles.push_back(t);
      continue;
    }
    for (int v : t)
      if (v != center)
        loop.insert(v);
  }
  return m;
}

void TestHoles(const TriangleMesh& sphere)
{
  const double volume = coretest::SignedVolume(sphere.points, sphere.triangles);
  std::set<int> loop;
  const TriangleMesh holed = Holed(sphere, 0, loop);
  REQUIRE(loop.size() >= 3, "no hole made");
  const int n = static_cast<int>(loop.size());

  // Filled (root epsilon 0.2: the fill lies within 0.1 of the loop).
  const FoldingTree tree = UnitSphereTree(holed, 0.2);
  const UnfoldedMesh u = coretest::Unfold(tree);
  const coretest::EdgeStats s = coretest::CountEdges(u.triangles);
  std::printf("hole of %d edges: filled %d loops, %d faces; open %d non-manifold %d "
              "misoriented %d\n",
    n,
    u.repair.filledLoops,
    u.repair.filledFaces,
    s.open,
    s.nonManifold,
    s.misoriented);
  EXPECT(u.repair.filledLoops == 1 && u.repair.filledFaces == n - 2,
    "hole: " << u.repair.filledLoops << " loops, " << u.repair.filledFaces << " faces filled");
  EXPECT(s.open == 0 && s.nonManifold == 0 && s.misoriented == 0,
    "hole: not closed and consistently oriented");
  EXPECT(u.openEdges == s.open && u.nonManifoldEdges == s.nonManifold &&
      u.misorientedEdges == s.misoriented,
    "hole: the report differs from the mesh");
  EXPECT(u.repair.openLoops == 0 && u.repair.borderLoops == 0, "hole: loops left open");
  EXPECT(
    coretest::SignedVolume(u.points, u.triangles) * volume > 0.0, "hole: orientation reversed");
  int filled = 0;
  for (int f = 0; f < u.NumberOfFaces(); ++f)
    if (u.faceFilled[f])
    {
      ++filled;
      const Triangle& t = u.triangles[f];
      const Vec3 c = (u.points[t[0]] + u.points[t[1]] + u.points[t[2]]) / 3.0;
      EXPECT(std::abs(c.norm() - 1.0) <= tree.rootEpsilon,
        "hole: a new face lies " << std::abs(c.norm() - 1.0) << " from the sphere");
    }
  EXPECT(filled == n - 2 && u.filledFaces == filled, "hole: FoldingFilled marks " << filled);

  UnfoldOptions off;
  off.closeHoles = false;
  EXPECT(coretest::CountEdges(coretest::Unfold(tree, off).triangles).open == n,
    "closeHoles off: the hole is not open");

  // The input's own border: kept.
  FoldingTree bordered = tree;
  for (int v : loop)
    bordered.nodes[0].mesh.inputBoundary[v] = 1;
  const UnfoldedMesh b = coretest::Unfold(bordered);
  EXPECT(coretest::CountEdges(b.triangles).open == n && b.repair.filledLoops == 0,
    "input border: filled (" << coretest::CountEdges(b.triangles).open << " open edges)");
  EXPECT(b.repair.borderLoops == 1 && b.repair.borderEdges == n && b.repair.borderLength > 0.0,
    "input border: reported as " << b.repair.borderLoops << " loops, " << b.repair.borderEdges
                                 << " edges");

  // With the input's border edges listed (FoldingTree::inputBorderEdges): the flags alone do
  // not make a border - a hole whose edges are not listed is filled, one whose edges are is
  // kept.
  {
    std::vector<std::pair<int, int>> holeEdges;
    for (const Triangle& t : holed.triangles)
      for (int k = 0; k < 3; ++k)
      {
        const int a = t[k], b = t[(k + 1) % 3];
        if (loop.count(a) && loop.count(b))
          holeEdges.push_back({ std::min(a, b), std::max(a, b) });
      }
    std::sort(holeEdges.begin(), holeEdges.end());
    holeEdges.erase(std::unique(holeEdges.begin(), holeEdges.end()), holeEdges.end());
    FoldingTree listed = bordered;
    listed.inputBorderEdges = holeEdges; // (contains the loop's edges, and maybe chords)
    const UnfoldedMesh kept = coretest::Unfold(listed);
    EXPECT(kept.repair.borderLoops == 1 && kept.repair.filledLoops == 0,
      "listed border edges: the border was filled");
    FoldingTree other = bordered;
    other.inputBorderEdges = { { 1000000, 1000001 } }; // another border elsewhere
    const UnfoldedMesh filledAnyway = coretest::Unfold(other);
    EXPECT(filledAnyway.repair.borderLoops == 0 && filledAnyway.repair.filledLoops == 1 &&
        coretest::CountEdges(filledAnyway.triangles).open == 0,
      "border flags without a listed border edge: the hole was not filled");
  }

  // Unknown border (a tree file without InputBoundary): nothing filled.
  FoldingTree unknown = tree;
  unknown.nodes[0].mesh.inputBoundary.clear();
  const UnfoldedMesh k = coretest::Unfold(unknown);
  EXPECT(coretest::CountEdges(k.triangles).open == n && k.repair.unknownLoops == 1 &&
      k.repair.filledLoops == 0,
    "unknown border: filled or not reported");

  // Beyond the tolerance: left open and reported.
  const FoldingTree tight = UnitSphereTree(holed, 1e-4);
  const UnfoldedMesh r = coretest::Unfold(tight);
  EXPECT(coretest::CountEdges(r.triangles).open == n && r.repair.openLoops == 1 &&
      r.repair.openEdges == n && r.repair.openLength > 0.0 && r.repair.filledLoops == 0,
    "tolerance: " << r.repair.filledLoops << " loops filled, " << r.repair.openLoops
                  << " reported open");
}

void TestOrientationAndNonManifold(const TriangleMesh& sphere)
{
  const double volume = coretest::SignedVolume(sphere.points, sphere.triangles);
  // Flip the faces of a small cap around vertex 0 (its 1-ring) and one lone face.
  TriangleMesh flipped = sphere;
  int count = 0;
  for (Triangle& t : flipped.triangles)
    if (std::find(t.begin(), t.end(), 0) != t.end())
    {
      std::swap(t[1], t[2]);
      ++count;
    }
  for (Triangle& t : flipped.triangles) // and the first face far from vertex 0
    if ((sphere.points[t[0]] - sphere.points[0]).norm() > 1.0)
    {
      std::swap(t[1], t[2]);
      ++count;
      break;
    }
  const FoldingTree tree = UnitSphereTree(flipped, 0.04);
  UnfoldOptions off;
  off.closeHoles = false;
  const coretest::EdgeStats before = coretest::CountEdges(coretest::Unfold(tree, off).triangles);
  const UnfoldedMesh u = coretest::Unfold(tree);
  const coretest::EdgeStats after = coretest::CountEdges(u.triangles);
  std::printf("orientation: %d faces flipped by hand, %d misoriented edges; repair flipped %d, "
              "misoriented %d\n",
    count,
    before.misoriented,
    u.repair.flippedFaces,
    after.misoriented);
  EXPECT(before.misoriented > 0, "flipped faces: no misoriented edge to repair");
  EXPECT(after.misoriented == 0 && after.open == 0 && after.nonManifold == 0 &&
      u.NumberOfFaces() == static_cast<int>(sphere.triangles.size()),
    "orientation: not repaired");
  EXPECT(u.repair.flippedFaces == count, "orientation: " << u.repair.flippedFaces << " flipped");
  EXPECT(
    coretest::SignedVolume(u.points, u.triangles) * volume > 0.0, "orientation: the majority lost");

  // A fin: an extra face on an edge of the sphere (to a far vertex).
  TriangleMesh fin = sphere;
  const Triangle& t0 = sphere.triangles[0];
  int far = 0;
  for (int v = 0; v < static_cast<int>(sphere.points.size()); ++v)
    if ((sphere.points[v] - sphere.points[t0[0]]).norm() >
      (sphere.points[far] - sphere.points[t0[0]]).norm())
      far = v;
  fin.triangles.push_back({ t0[0], t0[1], far });
  FoldingTree finTree = UnitSphereTree(fin, 0.04);
  EXPECT(coretest::CountEdges(coretest::Unfold(finTree, off).triangles).nonManifold == 1,
    "fin: not non-manifold");
  // (Another input non-manifold edge listed, not this one: the fin is still dropped.)
  const Triangle& t1 = sphere.triangles[sphere.triangles.size() / 2];
  for (int listed = 0; listed < 2; ++listed)
  {
    if (listed)
      finTree.inputNonManifoldEdges = { { std::min(t1[0], t1[1]), std::max(t1[0], t1[1]), 3 } };
    const UnfoldedMesh g = coretest::Unfold(finTree);
    const coretest::EdgeStats gs = coretest::CountEdges(g.triangles);
    EXPECT(gs.nonManifold == 0 && gs.misoriented == 0 && gs.open == 0 &&
        g.NumberOfFaces() == static_cast<int>(sphere.triangles.size()) &&
        g.repair.droppedFaces == 1,
      "fin (other edges listed: " << listed << "): " << gs.nonManifold << " non-manifold, "
                                  << gs.open << " open edges, " << g.repair.droppedFaces
                                  << " faces dropped");
  }
}

/// The non-manifold edges of `m` (more than two faces) as FoldingTree lists them.
std::vector<InputNonManifoldEdge> NonManifoldEdges(const TriangleMesh& m)
{
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) }];
  std::vector<InputNonManifoldEdge> edges;
  for (const auto& e : uses)
    if (e.second > 2)
      edges.push_back({ e.first.first, e.first.second, e.second });
  return edges;
}

/// Unfolds `m` (one leaf, every point on the input's border unless `closed`, the non-manifold
/// edges listed) and checks that every face comes back, none dropped, flipped or added.
void ExpectAllFacesKept(const char* name, const TriangleMesh& m, bool closed)
{
  FoldingTree tree = UnitSphereTree(m, 0.04);
  if (!closed)
    tree.nodes[0].mesh.inputBoundary.assign(m.points.size(), 1);
  tree.inputNonManifoldEdges = NonManifoldEdges(m);
  REQUIRE(!tree.inputNonManifoldEdges.empty(), name << ": no non-manifold edge");
  const UnfoldedMesh u = coretest::Unfold(tree);
  const coretest::EdgeStats in = coretest::CountEdges(m.triangles);
  const coretest::EdgeStats out = coretest::CountEdges(u.triangles);
  std::printf("%s: %zu faces, %zu non-manifold edges -> %d faces, %d non-manifold, dropped %d "
              "flipped %d filled %d\n",
    name,
    m.triangles.size(),
    tree.inputNonManifoldEdges.size(),
    u.NumberOfFaces(),
    out.nonManifold,
    u.repair.droppedFaces,
    u.repair.flippedFaces,
    u.repair.filledFaces);
  EXPECT(u.NumberOfFaces() == static_cast<int>(m.triangles.size()) &&
      u.repair.droppedFaces == 0 && u.repair.flippedFaces == 0 && u.repair.filledFaces == 0,
    name << ": " << u.NumberOfFaces() << " faces of " << m.triangles.size() << ", dropped "
         << u.repair.droppedFaces << " flipped " << u.repair.flippedFaces << " filled "
         << u.repair.filledFaces);
  std::multiset<int> faces(u.faceOriginalIds.begin(), u.faceOriginalIds.end());
  for (int f = 0; f < static_cast<int>(m.triangles.size()); ++f)
    EXPECT(faces.count(f) == 1, name << ": input face " << f << " not kept once");
  EXPECT(out.nonManifold == in.nonManifold && out.open == in.open &&
      out.misoriented == in.misoriented && u.nonManifoldEdges == out.nonManifold,
    name << ": edges changed: non-manifold " << out.nonManifold << " (input " << in.nonManifold
         << "), open " << out.open << " (" << in.open << "), misoriented " << out.misoriented
         << " (" << in.misoriented << ")");
}

void TestInputNonManifold(const TriangleMesh& sphere)
{
  // A fan of 10 triangles on the edge 0-1 (every other edge is the input's border).
  TriangleMesh fan;
  fan.points = { Vec3(0, 0, 0), Vec3(0, 0, 1) };
  for (int j = 0; j < 10; ++j)
  {
    const double a = 2.0 * std::acos(-1.0) * j / 10.0;
    fan.points.push_back(Vec3(std::cos(a), std::sin(a), 0.5));
    fan.triangles.push_back({ 0, 1, 2 + j });
  }
  ExpectAllFacesKept("fan of 10", fan, false);

  // Without the list (a tree file written before it existed): the old repair, two kept.
  {
    FoldingTree old = UnitSphereTree(fan, 0.04);
    old.nodes[0].mesh.inputBoundary.assign(fan.points.size(), 1);
    const UnfoldedMesh u = coretest::Unfold(old);
    EXPECT(u.NumberOfFaces() == 2 && u.repair.droppedFaces == 8,
      "fan without the list: " << u.NumberOfFaces() << " faces kept");
  }

  // More faces than the input edge had: the extra one (on a point next to face 3's third
  // point, a copy laid on top) goes, face 3 stays.
  {
    TriangleMesh more = fan;
    more.points.push_back(fan.points[5] + Vec3(0.0, 0.0, 0.01));
    more.triangles.push_back({ 0, 1, 12 });
    FoldingTree tree = UnitSphereTree(more, 0.04);
    tree.nodes[0].mesh.inputBoundary.assign(more.points.size(), 1);
    tree.inputNonManifoldEdges = NonManifoldEdges(fan); // 10 faces
    const UnfoldedMesh u = coretest::Unfold(tree);
    std::multiset<int> faces(u.faceOriginalIds.begin(), u.faceOriginalIds.end());
    EXPECT(u.NumberOfFaces() == 10 && u.repair.droppedFaces == 1 && faces.count(3) == 1 &&
        faces.count(10) == 0,
      "fan with a face on top: " << u.NumberOfFaces() << " faces, dropped "
                                 << u.repair.droppedFaces << ", face 10 kept "
                                 << faces.count(10));
  }

  // A face of the sphere duplicated (its edges used by 3 faces).
  TriangleMesh duplicated = sphere;
  duplicated.triangles.push_back(sphere.triangles[7]);
  ExpectAllFacesKept("duplicated face", duplicated, true);

  // A two-sided sphere: every face also reversed (every edge used by 4 faces).
  TriangleMesh twoSided = sphere;
  for (const Triangle& t : sphere.triangles)
    twoSided.triangles.push_back({ t[0], t[2], t[1] });
  ExpectAllFacesKept("two-sided sphere", twoSided, true);
}
}

int main()
{
  const TriangleMesh sphere = coretest::ToTriangleMesh(pm::MakeSphere(2000).mesh);
  REQUIRE(coretest::CountEdges(sphere.triangles).open == 0 &&
      coretest::CountEdges(sphere.triangles).misoriented == 0,
    "the sphere is not closed and oriented");
  TestHoles(sphere);
  TestOrientationAndNonManifold(sphere);
  TestInputNonManifold(sphere);
  return coretest::Finish("TestUnfolderRepair");
}
