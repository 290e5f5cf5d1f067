// PrepareMesh and LinkNearbyParts on small hand-made meshes whose answers are known by
// construction:
// - welding: two triangles with duplicated coordinates become edge-connected; points that
//   differ by 1e-12 are not welded;
// - orientation: a closed octahedron under every one of the 256 subsets of flipped faces and a
//   cube (12 triangles, random subsets) come out consistent and outward (positive volume,
//   normals away from the centre), numberOfFlippedFaces = faces that were wrong; two closed
//   parts, one nested in the other, are both outward; an open pyramid (5 faces) keeps the
//   majority orientation for all 32 subsets;
// - parts, boundary and non-manifold edge counts, degenerate faces, input errors;
// - areas: total area and vertex areas (1/3 of the incident face areas), vertex normals unit;
// - LinkNearbyParts: two touching octahedra are linked (and the links are exactly the nearest
//   cross-part vertex pairs within the gap, by brute force), 0.0095 apart with gap 0.01 are,
//   0.0105 apart and far ones are not.
#include "CoreTestUtilities.h"

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

using foldingmeshes::LinkNearbyParts;
using foldingmeshes::PreparedMesh;
using foldingmeshes::PrepareMesh;
using foldingmeshes::Triangle;
using foldingmeshes::TriangleMesh;
using foldingmeshes::Vec3;

namespace
{
/// Octahedron with outward faces (counter-clockwise seen from outside).
TriangleMesh Octahedron(const Vec3& center, double r)
{
  TriangleMesh m;
  const Vec3 d[6] = {
    Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()
  };
  for (const Vec3& v : d)
    m.points.push_back(center + r * v);
  // (x: 0/1, y: 2/3, z: 4/5): face (sx, sy, sz) ordered so that the normal points outward.
  for (int sx : { 0, 1 })
    for (int sy : { 2, 3 })
      for (int sz : { 4, 5 })
      {
        Triangle t{ sx, sy, sz };
        const Vec3 n = (m.points[sy] - m.points[sx]).cross(m.points[sz] - m.points[sx]);
        if (n.dot(m.points[sx] + m.points[sy] + m.points[sz] - 3 * center) < 0)
          std::swap(t[1], t[2]);
        m.triangles.push_back(t);
      }
  return m;
}

/// Axis-aligned unit cube [0,1]^3 + offset, 12 outward triangles.
TriangleMesh Cube(const Vec3& offset)
{
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.points.push_back(offset + Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  const int quads[6][4] = {
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 }
  };
  for (const auto& q : quads)
  {
    m.triangles.push_back({ q[0], q[1], q[2] });
    m.triangles.push_back({ q[0], q[2], q[3] });
  }
  return m;
}

/// Open square pyramid without its base: apex 0, rim 1..5 (a pentagon), normals up/out.
TriangleMesh OpenPyramid()
{
  TriangleMesh m;
  m.points.push_back(Vec3(0, 0, 1));
  for (int k = 0; k < 5; ++k)
  {
    const double a = 2 * 3.14159265358979323846 * k / 5;
    m.points.push_back(Vec3(std::cos(a), std::sin(a), 0));
  }
  for (int k = 0; k < 5; ++k)
    m.triangles.push_back({ 0, 1 + k, 1 + (k + 1) % 5 });
  return m;
}

TriangleMesh Append(TriangleMesh a, const TriangleMesh& b)
{
  const int offset = static_cast<int>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (Triangle t : b.triangles)
    a.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  return a;
}

Triangle Reversed(const Triangle& t)
{
  return { t[0], t[2], t[1] };
}

/// True if u is a cyclic rotation of t.
bool SameCycle(const Triangle& t, const Triangle& u)
{
  for (int k = 0; k < 3; ++k)
    if (u[0] == t[k] && u[1] == t[(k + 1) % 3] && u[2] == t[(k + 2) % 3])
      return true;
  return false;
}

/// Each directed edge used at most once (so every interior edge is traversed both ways).
bool Consistent(const PreparedMesh& m)
{
  std::set<std::pair<int, int>> directed;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      if (!directed.insert({ t[k], t[(k + 1) % 3] }).second)
        return false;
  return true;
}

double SignedVolume(const PreparedMesh& m, const std::vector<int>& faces)
{
  double v = 0.0;
  for (int f : faces)
  {
    const Triangle& t = m.triangles[f];
    v += m.points[t[0]].dot(m.points[t[1]].cross(m.points[t[2]])) / 6.0;
  }
  return v;
}

std::vector<int> AllFaces(const PreparedMesh& m)
{
  std::vector<int> f(m.triangles.size());
  for (size_t k = 0; k < f.size(); ++k)
    f[k] = static_cast<int>(k);
  return f;
}

/// Checks that a closed convex mesh with centre c, whose input had `wrong` faces with reversed
/// orientation (flags), was oriented outward and reported correctly.
void CheckOutward(const TriangleMesh& input,
  const PreparedMesh& m,
  const std::vector<int>& faces,
  const Vec3& c,
  int expectedFlips,
  const std::string& what)
{
  EXPECT(Consistent(m), what << ": orientation not consistent");
  EXPECT(SignedVolume(m, faces) > 0.0, what << ": signed volume " << SignedVolume(m, faces));
  bool outward = true;
  for (int f : faces)
  {
    const Triangle& t = m.triangles[f];
    const Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
    outward = outward && n.dot(m.faceCentroids[f] - c) > 0.0 &&
      m.faceNormals[f].dot(m.faceCentroids[f] - c) > 0.0;
    const Triangle in = input.triangles[f];
    EXPECT(SameCycle(in, t) || SameCycle(Reversed(in), t),
      what << ": face " << f << " does not use its input vertices");
  }
  EXPECT(outward, what << ": some normal points towards the centre");
  EXPECT(m.numberOfFlippedFaces == expectedFlips,
    what << ": numberOfFlippedFaces " << m.numberOfFlippedFaces << ", expected " << expectedFlips);
}
}

int main()
{
  std::string error;
  PreparedMesh m;

  // ---- Welding ----
  {
    TriangleMesh in;
    in.points = {
      Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)
    };
    in.triangles = { { 0, 1, 2 }, { 4, 3, 5 } };
    REQUIRE(PrepareMesh(in, {}, m, error), "welding mesh: " << error);
    EXPECT(m.NumberOfPoints() == 4, "welding: " << m.NumberOfPoints() << " points, expected 4");
    EXPECT(m.inputToWelded[3] == m.inputToWelded[1] && m.inputToWelded[4] == m.inputToWelded[2],
      "welding: duplicated points not mapped to the same welded point");
    EXPECT(m.weldedToInput[m.inputToWelded[3]] == 1, "weldedToInput is not the first input id");
    for (int i = 0; i < 6; ++i)
      EXPECT(m.points[m.inputToWelded[i]] == in.points[i], "welded point " << i << " moved");
    const int n0 = m.faceNeighborOffsets[1] - m.faceNeighborOffsets[0];
    EXPECT(n0 == 1 && m.faceNeighbors[m.faceNeighborOffsets[0]] == 1,
      "welding: the two triangles are not edge neighbours");
    EXPECT(m.numberOfParts == 1, "welding: " << m.numberOfParts << " parts, expected 1");
    EXPECT(m.numberOfBoundaryEdges == 4, "welding: boundary edges " << m.numberOfBoundaryEdges);
    EXPECT(m.numberOfFlippedFaces == 0, "welding: consistent input was flipped");
    // Not identical coordinates: no welding, two parts.
    in.points[3] = Vec3(1 + 1e-12, 0, 0);
    in.points[4] = Vec3(0, 1 + 1e-12, 0);
    REQUIRE(PrepareMesh(in, {}, m, error), "near-duplicate mesh: " << error);
    EXPECT(m.NumberOfPoints() == 6 && m.numberOfParts == 2,
      "points 1e-12 apart were welded: " << m.NumberOfPoints() << " points, " << m.numberOfParts
                                         << " parts");
  }

  // ---- Orientation of a closed octahedron: all 256 flip subsets, far from the origin ----
  {
    const Vec3 c(100.0, -50.0, 3.0);
    const TriangleMesh good = Octahedron(c, 2.0);
    for (int subset = 0; subset < 256; ++subset)
    {
      TriangleMesh in = good;
      int wrong = 0;
      for (int f = 0; f < 8; ++f)
        if (subset & (1 << f))
        {
          in.triangles[f] = Reversed(in.triangles[f]);
          ++wrong;
        }
      REQUIRE(PrepareMesh(in, {}, m, error), "octahedron: " << error);
      CheckOutward(in, m, AllFaces(m), c, wrong, "octahedron subset " + std::to_string(subset));
      EXPECT(
        m.numberOfParts == 1 && m.numberOfBoundaryEdges == 0 && m.numberOfNonManifoldEdges == 0,
        "octahedron: parts/boundary/non-manifold " << m.numberOfParts << "/"
                                                   << m.numberOfBoundaryEdges << "/"
                                                   << m.numberOfNonManifoldEdges);
    }
  }

  // ---- Cube (12 triangles), random subsets ----
  {
    std::mt19937 rng(7);
    const Vec3 offset(-3.0, 0.5, 7.0);
    const TriangleMesh good = Cube(offset);
    for (int trial = 0; trial < 300; ++trial)
    {
      TriangleMesh in = good;
      int wrong = 0;
      for (auto& t : in.triangles)
        if (rng() & 1)
        {
          t = Reversed(t);
          ++wrong;
        }
      REQUIRE(PrepareMesh(in, {}, m, error), "cube: " << error);
      CheckOutward(in,
        m,
        AllFaces(m),
        offset + Vec3(0.5, 0.5, 0.5),
        wrong,
        "cube trial " + std::to_string(trial));
      EXPECT(std::abs(SignedVolume(m, AllFaces(m)) - 1.0) < 1e-12, "cube volume is not 1");
    }
  }

  // ---- Two closed parts, one inside the other, both wholly reversed ----
  {
    TriangleMesh outer = Octahedron(Vec3(0, 0, 0), 10.0), inner = Octahedron(Vec3(1, 1, 1), 1.0);
    for (auto& t : outer.triangles)
      t = Reversed(t);
    for (auto& t : inner.triangles)
      t = Reversed(t);
    const TriangleMesh in = Append(outer, inner);
    REQUIRE(PrepareMesh(in, {}, m, error), "nested octahedra: " << error);
    EXPECT(m.numberOfParts == 2, "nested octahedra: " << m.numberOfParts << " parts");
    std::vector<int> first, second;
    for (int f = 0; f < 16; ++f)
      (f < 8 ? first : second).push_back(f);
    CheckOutward(in, m, first, Vec3(0, 0, 0), 16, "outer octahedron");
    CheckOutward(in, m, second, Vec3(1, 1, 1), 16, "inner octahedron");
    EXPECT(m.facePart[0] != m.facePart[8], "nested octahedra share a part id");
  }

  // ---- Open pyramid: the majority orientation wins (5 faces, no ties) ----
  {
    const TriangleMesh good = OpenPyramid();
    for (int subset = 0; subset < 32; ++subset)
    {
      TriangleMesh in = good;
      int wrong = 0;
      for (int f = 0; f < 5; ++f)
        if (subset & (1 << f))
        {
          in.triangles[f] = Reversed(in.triangles[f]);
          ++wrong;
        }
      REQUIRE(PrepareMesh(in, {}, m, error), "pyramid: " << error);
      const bool majorityUp = wrong < 3; // most input faces had the upward orientation
      bool ok = Consistent(m);
      for (int f = 0; f < 5; ++f)
        ok = ok && (m.faceNormals[f].z() > 0.0) == majorityUp;
      EXPECT(ok, "open pyramid subset " << subset << ": not the majority orientation");
      EXPECT(m.numberOfFlippedFaces == std::min(wrong, 5 - wrong),
        "open pyramid subset " << subset << ": numberOfFlippedFaces " << m.numberOfFlippedFaces);
      EXPECT(
        m.numberOfBoundaryEdges == 5 && m.numberOfNonManifoldEdges == 0 && m.numberOfParts == 1,
        "open pyramid: boundary " << m.numberOfBoundaryEdges << " non-manifold "
                                  << m.numberOfNonManifoldEdges);
    }
  }

  // ---- Parts, boundary and non-manifold edges ----
  {
    TriangleMesh single;
    single.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) };
    single.triangles = { { 0, 1, 2 } };
    REQUIRE(PrepareMesh(single, {}, m, error), "single triangle: " << error);
    EXPECT(m.numberOfBoundaryEdges == 3 && m.numberOfNonManifoldEdges == 0 && m.numberOfParts == 1,
      "single triangle: boundary " << m.numberOfBoundaryEdges);

    // Three triangles sharing the edge (0,1) (a "fin"): 1 non-manifold, 6 boundary edges.
    TriangleMesh fin;
    fin.points = {
      Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0.5), Vec3(-0.5, 0.8, 0.5), Vec3(-0.5, -0.8, 0.5)
    };
    fin.triangles = { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 0, 4 } };
    REQUIRE(PrepareMesh(fin, {}, m, error), "fin: " << error);
    EXPECT(m.numberOfNonManifoldEdges == 1 && m.numberOfBoundaryEdges == 6 && m.numberOfParts == 1,
      "fin: non-manifold " << m.numberOfNonManifoldEdges << " boundary " << m.numberOfBoundaryEdges
                           << " parts " << m.numberOfParts);
    for (int f = 0; f < 3; ++f)
      EXPECT(m.faceNeighborOffsets[f + 1] - m.faceNeighborOffsets[f] == 2,
        "fin: face " << f << " should have the two other faces as neighbours");

    // Bowtie (two triangles sharing a vertex only) + a separate octahedron: 3 parts.
    TriangleMesh bowtie;
    bowtie.points = {
      Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)
    };
    bowtie.triangles = { { 0, 1, 2 }, { 0, 3, 4 } };
    const TriangleMesh three = Append(bowtie, Octahedron(Vec3(5, 5, 5), 1.0));
    REQUIRE(PrepareMesh(three, {}, m, error), "bowtie + octahedron: " << error);
    EXPECT(
      m.numberOfParts == 3, "bowtie + octahedron: " << m.numberOfParts << " parts, expected 3");
    EXPECT(
      m.numberOfBoundaryEdges == 6, "bowtie + octahedron: boundary " << m.numberOfBoundaryEdges);
    std::set<int> octaParts;
    for (int f = 2; f < 10; ++f)
      octaParts.insert(m.facePart[f]);
    EXPECT(octaParts.size() == 1 && m.facePart[0] != m.facePart[1] &&
        !octaParts.count(m.facePart[0]) && !octaParts.count(m.facePart[1]),
      "bowtie + octahedron: wrong facePart labels");
    for (int f = 0; f < 10; ++f)
      EXPECT(m.facePart[f] >= 0 && m.facePart[f] < m.numberOfParts, "facePart out of range");
  }

  // ---- Degenerate faces ----
  {
    TriangleMesh in;
    in.points = {
      Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 1)
    };
    in.triangles = {
      { 0, 1, 2 }, // fine
      { 0, 0, 1 }, // repeated index
      { 0, 1, 3 }, // collinear, distinct points
      { 0, 4, 1 }, // points 0 and 4 are welded: repeated after welding
      { 0, 2, 5 }, // fine
    };
    REQUIRE(PrepareMesh(in, {}, m, error), "degenerate faces: " << error);
    const char expected[5] = { 0, 1, 1, 1, 0 };
    for (int f = 0; f < 5; ++f)
    {
      EXPECT(m.faceDegenerate[f] == expected[f],
        "face " << f << " degenerate flag " << int(m.faceDegenerate[f]));
      if (expected[f])
        EXPECT(m.faceNormals[f] == Vec3::Zero() && m.faceAreas[f] < 1e-15,
          "degenerate face " << f << " has a normal or an area");
      else
        EXPECT(
          std::abs(m.faceNormals[f].norm() - 1) < 1e-15 && std::abs(m.faceAreas[f] - 0.5) < 1e-15,
          "face " << f << " normal/area wrong");
    }
    EXPECT(std::abs(m.totalArea - 1.0) < 1e-15, "degenerate faces: total area " << m.totalArea);
  }

  // ---- Errors ----
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    TriangleMesh good;
    good.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(5, 5, 5) };
    good.triangles = { { 0, 1, 2 } };
    REQUIRE(PrepareMesh(good, {}, m, error), "error baseline: " << error);
    std::vector<std::pair<std::string, TriangleMesh>> bad;
    bad.push_back({ "empty", TriangleMesh() });
    TriangleMesh t = good;
    t.triangles.clear();
    bad.push_back({ "no triangles", t });
    t = good;
    t.points[1].y() = nan;
    bad.push_back({ "NaN coordinate", t });
    t = good;
    t.points[3].z() = inf; // an unused point
    bad.push_back({ "infinite unused coordinate", t });
    t = good;
    t.triangles.push_back({ 0, 1, 4 });
    bad.push_back({ "index == number of points", t });
    t = good;
    t.triangles.push_back({ 0, -1, 2 });
    bad.push_back({ "negative index", t });
    t = good;
    t.points = { Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2) };
    bad.push_back({ "zero area (collinear)", t });
    t.points = { Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3) };
    bad.push_back({ "zero area (one point)", t });
    for (const auto& [name, mesh] : bad)
    {
      error.clear();
      const bool ok = PrepareMesh(mesh, {}, m, error);
      EXPECT(!ok && !error.empty(),
        name << ": PrepareMesh returned " << ok << " error '" << error << "'");
    }
  }

  // ---- Areas and normals on a random closed mesh (a perturbed octahedron, subdivided) ----
  {
    std::mt19937 rng(3);
    TriangleMesh in = Append(Octahedron(Vec3(0.1, 0.2, 0.3), 1.5), Cube(Vec3(4, 4, 4)));
    for (Vec3& p : in.points)
      p += Vec3(rng() % 1000, rng() % 1000, rng() % 1000) * 1e-4;
    REQUIRE(PrepareMesh(in, {}, m, error), "areas: " << error);
    double total = 0.0;
    std::vector<double> vertexArea(m.NumberOfPoints(), 0.0);
    for (const Triangle& t : in.triangles)
    {
      const double a =
        0.5 * (in.points[t[1]] - in.points[t[0]]).cross(in.points[t[2]] - in.points[t[0]]).norm();
      total += a;
      for (int v : t)
        vertexArea[m.inputToWelded[v]] += a / 3.0;
    }
    EXPECT(std::abs(m.totalArea - total) < 1e-12 * total,
      "total area " << m.totalArea << " expected " << total);
    double sum = 0.0;
    for (int v = 0; v < m.NumberOfPoints(); ++v)
    {
      sum += m.vertexAreas[v];
      EXPECT(std::abs(m.vertexAreas[v] - vertexArea[v]) < 1e-12 * total, "vertex area " << v);
      EXPECT(
        std::abs(m.vertexNormals[v].norm() - 1.0) < 1e-12, "vertex normal " << v << " not unit");
    }
    EXPECT(std::abs(sum - m.totalArea) < 1e-12 * total,
      "vertex areas sum to " << sum << ", total area " << m.totalArea);
  }

  // ---- LinkNearbyParts ----
  // Separations well inside, just inside and just outside the gap, and far.
  for (double delta : { 0.001, 0.0095, 0.0105, 1.0 })
  {
    const double gap = 0.01;
    // Octahedron A (radius 1 at 0) and B (radius 1 at (2 + delta, 0, 0)): the vertices
    // (1,0,0) of A and (1 + delta, 0, 0) of B are delta apart.
    const TriangleMesh in =
      Append(Octahedron(Vec3(0, 0, 0), 1.0), Octahedron(Vec3(2 + delta, 0, 0), 1.0));
    REQUIRE(PrepareMesh(in, {}, m, error), "two octahedra: " << error);
    REQUIRE(m.numberOfParts == 2, "two octahedra: " << m.numberOfParts << " parts");
    LinkNearbyParts(m, gap);
    // Brute force: every vertex with a vertex of another part within the gap gives exactly one
    // link, to its nearest such vertex.
    std::vector<int> vertexPart(m.NumberOfPoints(), -1);
    for (int f = 0; f < m.NumberOfFaces(); ++f)
      for (int v : m.triangles[f])
        vertexPart[v] = m.facePart[f];
    std::map<int, double> nearest; // vertex -> distance to its nearest other-part vertex
    for (int v = 0; v < m.NumberOfPoints(); ++v)
      for (int w = 0; w < m.NumberOfPoints(); ++w)
        if (vertexPart[w] != vertexPart[v])
        {
          const double d = (m.points[v] - m.points[w]).norm();
          if (d <= gap && (!nearest.count(v) || d < nearest[v]))
            nearest[v] = d;
        }
    EXPECT(m.proximityLinks.size() == nearest.size(),
      "delta " << delta << ": " << m.proximityLinks.size() << " links, brute force "
               << nearest.size());
    for (const auto& [v, w] : m.proximityLinks)
    {
      auto it = nearest.find(v);
      EXPECT(it != nearest.end() && (m.points[v] - m.points[w]).norm() == it->second,
        "link " << v << "-" << w << " is not a nearest cross-part pair within the gap");
    }
    if (delta < gap)
    {
      const int a = m.inputToWelded[0], b = m.inputToWelded[6 + 1]; // A's +x, B's -x vertex
      bool found = false;
      for (const auto& link : m.proximityLinks)
        found =
          found || (link.first == a && link.second == b) || (link.first == b && link.second == a);
      EXPECT(found, "the touching vertices of the two octahedra are not linked");
    }
    else
      EXPECT(m.proximityLinks.empty(), "far octahedra got " << m.proximityLinks.size() << " links");
  }
  return coretest::Finish("TestMeshPreparation");
}
