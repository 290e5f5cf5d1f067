// FaceTree against brute force over all faces:
// - ClosestCompatibleFace: thousands of random query points (near the surface and anywhere in
//   an enlarged box) with random or surface-derived unit normals, several compatibility angles
//   (10, 45, 90 degrees -- the filter's range -- and 120 degrees, cosLimit < 0, allowed by
//   the core API) and maxDistance values; the reference is the minimum exact
//   point-triangle distance over the non-degenerate faces whose barycentrically interpolated
//   vertex normal at the closest point makes a cosine >= cosLimit with the query normal;
// - NearestCentroidFace: minimum centroid distance over the non-degenerate faces, including
//   exact ties (query points on the mirror plane of an exactly symmetric mesh: lowest id wins);
// - on two meshes (bilateral and asymmetric blobs);
// - two parallel plates facing each other: a point near plate A with a normal matching plate B
//   gets plate B (the plain closest face is excluded), a normal at 90 degrees gets nothing.
// - regression: a minimal fan where the cone half-angle + compatibility angle exceed 180
//   degrees (the normal-cone pruning used to skip compatible faces there); and a triangle
//   whose corner normals are 1e-8 radians apart (its cone had no width: its sine came from
//   sqrt(1 - cos^2)), queried with a normal just inside the limit at the turned corner.
// - exactness of the pruning: on a fine plate (hundreds of coplanar faces: exact ties) with
//   slivers, and on the blob, queries far off the surface (where the plane bound of
//   FaceTree::Beyond prunes most faces) give bit for bit the face and distance of an exhaustive
//   scan with the tree's own per-face rule (closest point, then the interpolated normal test
//   n . q >= cos * |n|, ties: lowest id), with and without a hint face, and with a third of
//   the faces excluded (a scan of the others; the hint may be an excluded face).
// - a soup: the blob with 60 long triangles and slivers spanning its box, checked like the
//   blob above, near and far, by ClosestFace too and on the surface (the tree holds them apart
//   under its root: LargeFaces; not when a third of the faces are large); the same with 12
//   faces, one of them large, and with the turned cylinder below (a rotated frame too); and flat
//   plates turned obliquely (where the nodes' oriented boxes, not their axis-aligned ones, prune):
//   bit for bit the exhaustive scan.
// - a capped cylinder of long slivers (the artist-like chair's legs) under a random rotation:
//   the tree builds its boxes in a rotated frame (not for the cylinder as built, axis-aligned),
//   and its answers - ClosestCompatibleFace, ClosestFace with and without excluded faces,
//   NearestCentroidFace - are still bit for bit those of the exhaustive scan, near and far,
//   exactly on corners, edges and faces, 1e-9 off and 1e3 diagonals away, and 1e6 from the
//   origin (each of the pruning's two margins is needed by some of these).
#include "CoreTestUtilities.h"
#include "FaceTree.h"
#include "PointTriangleDistance.h"
#include "ProceduralMeshes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using foldingmeshes::ClosestPointTriangle;
using foldingmeshes::FaceTree;
using foldingmeshes::PreparedMesh;
using foldingmeshes::TriangleMesh;
using foldingmeshes::Vec3;

namespace
{
const double kInf = std::numeric_limits<double>::infinity();
const double kPi = 3.14159265358979323846;

std::mt19937 rng(2024);
double U(double a, double b)
{
  return a + (b - a) * (static_cast<double>(rng()) / 4294967296.0);
}
Vec3 RandomUnit()
{
  for (;;)
  {
    const Vec3 v(U(-1, 1), U(-1, 1), U(-1, 1));
    if (v.norm() > 0.1 && v.norm() <= 1.0)
      return v.normalized();
  }
}

struct Reference
{
  int face = -1;
  double distance = kInf;
};

/// Brute force: the nearest compatible face (ties: lowest id), no distance limit.
Reference BruteCompatible(const PreparedMesh& m, const Vec3& p, const Vec3& n, double cosLimit)
{
  Reference best;
  double best2 = kInf;
  for (int f = 0; f < m.NumberOfFaces(); ++f)
  {
    if (m.faceDegenerate[f])
      continue;
    const auto& t = m.triangles[f];
    const auto cp = ClosestPointTriangle(p, m.points[t[0]], m.points[t[1]], m.points[t[2]]);
    const Vec3 ni = cp.barycentric[0] * m.vertexNormals[t[0]] +
      cp.barycentric[1] * m.vertexNormals[t[1]] + cp.barycentric[2] * m.vertexNormals[t[2]];
    if (!(ni.norm() > 0.0) || ni.normalized().dot(n) < cosLimit)
      continue;
    if (cp.squaredDistance < best2)
    {
      best2 = cp.squaredDistance;
      best.face = f;
    }
  }
  best.distance = std::sqrt(best2);
  return best;
}

double FaceDistance(const PreparedMesh& m, int f, const Vec3& p)
{
  const auto& t = m.triangles[f];
  return std::sqrt(
    ClosestPointTriangle(p, m.points[t[0]], m.points[t[1]], m.points[t[2]]).squaredDistance);
}

void CheckMesh(const char* name,
  const PreparedMesh& m,
  int queries,
  const std::vector<double>& angles,
  bool mirrorX)
{
  const FaceTree tree(m);
  const double diag = m.diagonal;
  const double tol = 1e-12 * diag;
  const Vec3 lo = m.boundsMin - 0.2 * (m.boundsMax - m.boundsMin);
  const Vec3 hi = m.boundsMax + 0.2 * (m.boundsMax - m.boundsMin);
  int compared = 0, found = 0, sameFace = 0, mismatches = 0;
  for (double angle : angles)
  {
    const double cosLimit = std::cos(angle * kPi / 180.0);
    for (int q = 0; q < queries; ++q)
    {
      Vec3 p, n;
      if (q % 2 == 0)
      {
        // Near the surface: a random vertex, moved a little, with its normal perturbed or a
        // random one (so both compatible and incompatible nearby faces occur).
        const int v = static_cast<int>(rng() % m.NumberOfPoints());
        p = m.points[v] + U(0, 0.05) * diag * RandomUnit();
        n = q % 4 == 0 ? Vec3((m.vertexNormals[v] + U(0, 1.5) * RandomUnit()).normalized())
                       : RandomUnit();
      }
      else
      {
        p = Vec3(U(lo.x(), hi.x()), U(lo.y(), hi.y()), U(lo.z(), hi.z()));
        n = RandomUnit();
      }
      const Reference ref = BruteCompatible(m, p, n, cosLimit);
      for (double maxDistance : { kInf, 0.2 * diag, 0.05 * diag, 0.01 * diag })
      {
        ++compared;
        const FaceTree::Hit hit = tree.ClosestCompatibleFace(p, n, cosLimit, maxDistance);
        // The reference under a distance limit: the unlimited answer if it is within the limit.
        const bool expectHit = ref.face >= 0 && ref.distance <= maxDistance;
        if (std::abs(ref.distance - maxDistance) <= tol)
          continue; // on the limit itself: either answer is right
        bool ok = (hit.face >= 0) == expectHit;
        if (ok && expectHit)
        {
          ++found;
          sameFace += hit.face == ref.face;
          // A different face is only right for an exact tie (shared vertex or edge).
          ok = std::abs(hit.distance - ref.distance) <= tol &&
            std::abs(FaceDistance(m, hit.face, p) - ref.distance) <= tol &&
            std::abs((hit.point - p).norm() - ref.distance) <= tol;
          if (ok && hit.face != ref.face)
          {
            // ... and the tree's face must be compatible too.
            const auto& t = m.triangles[hit.face];
            const auto cp = ClosestPointTriangle(p, m.points[t[0]], m.points[t[1]], m.points[t[2]]);
            const Vec3 ni = cp.barycentric[0] * m.vertexNormals[t[0]] +
              cp.barycentric[1] * m.vertexNormals[t[1]] + cp.barycentric[2] * m.vertexNormals[t[2]];
            ok = ni.normalized().dot(n) >= cosLimit - 1e-12;
          }
        }
        if (!ok && !expectHit)
          ok = hit.face < 0 && hit.distance == kInf;
        if (!ok && ++mismatches <= 5)
          EXPECT(false,
            name << ": angle " << angle << " maxDistance/diag " << maxDistance / diag << " query "
                 << p.transpose() << " n " << n.transpose() << ": tree face " << hit.face << " d "
                 << hit.distance << ", brute force face " << ref.face << " d " << ref.distance);
      }
    }
  }
  EXPECT(mismatches == 0, name << ": " << mismatches << " ClosestCompatibleFace mismatches");
  // The test must exercise hits and misses, and ties must be rare.
  EXPECT(found > compared / 5 && found < compared,
    name << ": only " << found << " hits of " << compared);
  EXPECT(
    sameFace >= 0.95 * found, name << ": only " << sameFace << " of " << found << " same faces");
  std::printf("%s: %d faces, %d queries, %d hits (%d same face)\n",
    name,
    m.NumberOfFaces(),
    compared,
    found,
    sameFace);

  // NearestCentroidFace. On a mesh exactly symmetric about x = 0, points on that plane are
  // exactly equidistant from mirrored centroids: ties, which must go to the lowest face id.
  int centroidMismatches = 0, ties = 0;
  for (int q = 0; q < 4 * queries; ++q)
  {
    Vec3 p = q % 2 ? Vec3(U(lo.x(), hi.x()), U(lo.y(), hi.y()), U(lo.z(), hi.z()))
                   : Vec3(m.faceCentroids[rng() % m.NumberOfFaces()] + 0.01 * diag * RandomUnit());
    if (mirrorX && q % 3 == 0)
      p.x() = 0.0;
    int best = -1, atBest = 0;
    double best2 = kInf;
    for (int f = 0; f < m.NumberOfFaces(); ++f)
    {
      const double d2 = (m.faceCentroids[f] - p).squaredNorm();
      if (m.faceDegenerate[f])
        continue;
      if (d2 < best2)
      {
        best2 = d2;
        best = f;
        atBest = 1;
      }
      else if (d2 == best2)
        ++atBest;
    }
    ties += atBest > 1;
    const int got = tree.NearestCentroidFace(p);
    if (got != best && ++centroidMismatches <= 5)
      EXPECT(false,
        name << ": NearestCentroidFace " << got << " brute force " << best << " at "
             << p.transpose() << (atBest > 1 ? " (tie)" : ""));
  }
  if (mirrorX)
    EXPECT(ties > queries / 4, name << ": only " << ties << " exact centroid ties were tested");
  EXPECT(centroidMismatches == 0,
    name << ": " << centroidMismatches << " NearestCentroidFace mismatches");
}

/// Exhaustive scan with FaceTree's per-face rule: over the non-degenerate faces (without those
/// `excluded` marks) closer than maxDistance whose closest point `accept`s, the closest point,
/// ties to the lowest id - the result the tree must give bit for bit.
template <typename Accept>
FaceTree::Hit ExhaustiveScan(const PreparedMesh& m,
  const Vec3& p,
  double maxDistance,
  const std::vector<char>* excluded,
  Accept accept)
{
  FaceTree::Hit hit;
  double best2 = maxDistance * maxDistance;
  for (int f = 0; f < m.NumberOfFaces(); ++f)
  {
    if (m.faceDegenerate[f] || (excluded && (*excluded)[f]))
      continue;
    const auto& t = m.triangles[f];
    const auto cp = ClosestPointTriangle(p, m.points[t[0]], m.points[t[1]], m.points[t[2]]);
    if (cp.squaredDistance > best2 || (cp.squaredDistance == best2 && hit.face >= 0))
      continue; // ascending ids: on a tie the earlier (lower) id stays
    if (!accept(t, cp))
      continue;
    best2 = cp.squaredDistance;
    hit.face = f;
    hit.point = cp.point;
  }
  if (hit.face >= 0)
    hit.distance = std::sqrt(best2);
  return hit;
}

/// ClosestCompatibleFace's rule: the interpolated vertex normal n_i at the closest point
/// satisfies n_i . n >= cosLimit |n_i|.
FaceTree::Hit ExhaustiveCompatible(const PreparedMesh& m,
  const Vec3& p,
  const Vec3& n,
  double cosLimit,
  double maxDistance,
  const std::vector<char>* excluded = nullptr)
{
  return ExhaustiveScan(m,
    p,
    maxDistance,
    excluded,
    [&](const foldingmeshes::Triangle& t, const foldingmeshes::ClosestPointOnTriangle& cp)
    {
      const Vec3 ni = cp.barycentric[0] * m.vertexNormals[t[0]] +
        cp.barycentric[1] * m.vertexNormals[t[1]] + cp.barycentric[2] * m.vertexNormals[t[2]];
      const double len = ni.norm();
      return len > 0.0 && ni.dot(n) >= cosLimit * len;
    });
}

/// ClosestFace's rule: every face.
FaceTree::Hit ExhaustiveClosest(const PreparedMesh& m,
  const Vec3& p,
  double maxDistance,
  const std::vector<char>* excluded = nullptr)
{
  return ExhaustiveScan(m,
    p,
    maxDistance,
    excluded,
    [](const foldingmeshes::Triangle&, const foldingmeshes::ClosestPointOnTriangle&)
    { return true; });
}

/// Queries at heights of up to `farthest` above or below random surface points, with the
/// surface normal (compatible) or a tilted one; the tree's answers must equal the exhaustive
/// scan's exactly, with no hint, the answer as hint, and a random hint - also with a third of
/// the faces excluded.
void CheckExact(const char* name, const PreparedMesh& m, int queries, double farthest)
{
  const FaceTree tree(m);
  const double cos45 = std::cos(kPi / 4);
  std::vector<char> excluded(m.NumberOfFaces());
  for (char& x : excluded)
    x = rng() % 3 == 0;
  int mismatches = 0, hits = 0, excludedMismatches = 0;
  for (int q = 0; q < queries; ++q)
  {
    const int v = static_cast<int>(rng() % m.NumberOfPoints());
    const double height = U(-farthest, farthest) * m.diagonal;
    const Vec3 p =
      m.points[v] + height * m.vertexNormals[v] + U(0, 0.01) * m.diagonal * RandomUnit();
    const Vec3 n = q % 3 == 0 ? RandomUnit()
                              : Vec3((m.vertexNormals[v] + U(0, 0.6) * RandomUnit()).normalized());
    const double maxDistance = q % 2 == 0 ? kInf : 0.5 * farthest * m.diagonal;
    const FaceTree::Hit ref = ExhaustiveCompatible(m, p, n, cos45, maxDistance);
    hits += ref.face >= 0;
    const int hints[3] = { -1, ref.face, static_cast<int>(rng() % m.NumberOfFaces()) };
    for (int hint : hints)
    {
      const FaceTree::Hit hit = tree.ClosestCompatibleFace(p, n, cos45, maxDistance, hint);
      const bool same = hit.face == ref.face && hit.distance == ref.distance &&
        (ref.face < 0 || hit.point == ref.point);
      if (!same && ++mismatches <= 5)
        EXPECT(false,
          name << ": query " << p.transpose() << " n " << n.transpose() << " hint " << hint
               << ": tree face " << hit.face << " d " << hit.distance << ", exhaustive face "
               << ref.face << " d " << ref.distance);
    }
    const FaceTree::Hit without = ExhaustiveCompatible(m, p, n, cos45, maxDistance, &excluded);
    for (int hint : hints)
    {
      const FaceTree::Hit hit =
        tree.ClosestCompatibleFace(p, n, cos45, maxDistance, hint, &excluded);
      const bool same = hit.face == without.face && hit.distance == without.distance &&
        (without.face < 0 || hit.point == without.point);
      if (!same && ++excludedMismatches <= 5)
        EXPECT(false,
          name << ", faces excluded: query " << p.transpose() << " hint " << hint << ": tree face "
               << hit.face << " d " << hit.distance << ", exhaustive face " << without.face << " d "
               << without.distance);
    }
  }
  EXPECT(mismatches == 0, name << ": " << mismatches << " answers differ from the exhaustive scan");
  EXPECT(excludedMismatches == 0,
    name << ": " << excludedMismatches << " answers with excluded faces differ from the scan");
  EXPECT(hits > queries / 3, name << ": only " << hits << " of " << queries << " queries hit");
}

/// ClosestFace against the exhaustive scan with its rule (closest point, ties: lowest id), with
/// and without a third of the faces excluded, and a distance limit on every other query.
void CheckPlainExact(const char* name, const PreparedMesh& m, int queries, double farthest)
{
  const FaceTree tree(m);
  std::vector<char> excluded(m.NumberOfFaces());
  for (char& x : excluded)
    x = rng() % 3 == 0;
  int mismatches = 0, hits = 0;
  for (int q = 0; q < queries; ++q)
  {
    const int v = static_cast<int>(rng() % m.NumberOfPoints());
    const Vec3 p = m.points[v] + U(-farthest, farthest) * m.diagonal * m.vertexNormals[v] +
      U(0, 0.01) * m.diagonal * RandomUnit();
    const double maxDistance = q % 2 == 0 ? kInf : 0.5 * farthest * m.diagonal;
    const std::vector<char>* const masks[2] = { nullptr, &excluded };
    for (const std::vector<char>* mask : masks)
    {
      const FaceTree::Hit ref = ExhaustiveClosest(m, p, maxDistance, mask);
      hits += ref.face >= 0;
      const FaceTree::Hit hit = tree.ClosestFace(p, maxDistance, mask);
      const bool same = hit.face == ref.face && hit.distance == ref.distance &&
        (ref.face < 0 || hit.point == ref.point);
      if (!same && ++mismatches <= 5)
        EXPECT(false,
          name << (mask ? ", faces excluded" : "") << ": ClosestFace " << p.transpose()
               << ": tree face " << hit.face << " d " << hit.distance << ", exhaustive face "
               << ref.face << " d " << ref.distance);
    }
  }
  EXPECT(
    mismatches == 0, name << ": " << mismatches << " ClosestFace answers differ from the scan");
  EXPECT(hits > queries, name << ": only " << hits << " of " << 2 * queries << " queries hit");
}

/// Queries where the pruning margins of a rotated box frame matter: exactly on a corner, an
/// edge's midpoint, inside a face, at a centroid, 1e-9 of the diagonal off a corner (the
/// absolute margin), and 1e3 diagonals away (the relative one); ClosestFace with maxDistance
/// infinite, 0 and 0.01 of the diagonal, ClosestCompatibleFace with any normal and 45 degrees,
/// NearestCentroidFace - each bit for bit the exhaustive scan's.
void CheckExactAtSurface(const char* name, const PreparedMesh& m, int queries)
{
  const FaceTree tree(m);
  int mismatches = 0;
  for (int q = 0; q < queries; ++q)
  {
    const auto& t = m.triangles[rng() % m.NumberOfFaces()];
    const Vec3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    const double u = U(0, 1), v = U(0, 1 - u);
    const Vec3 points[6] = { a,
      0.5 * (a + b),
      a + u * (b - a) + v * (c - a),
      (a + b + c) / 3.0,
      a + 1e-9 * m.diagonal * RandomUnit(),
      a + 1e3 * m.diagonal * RandomUnit() };
    const Vec3& p = points[q % 6];
    for (double maxDistance : { kInf, 0.0, 0.01 * m.diagonal })
    {
      const FaceTree::Hit ref = ExhaustiveClosest(m, p, maxDistance);
      const FaceTree::Hit hit = tree.ClosestFace(p, maxDistance);
      if (!(hit.face == ref.face && hit.distance == ref.distance &&
            (ref.face < 0 || hit.point == ref.point)) &&
        ++mismatches <= 5)
        EXPECT(false,
          name << ": ClosestFace at " << p.transpose() << " within " << maxDistance << ": face "
               << hit.face << " d " << hit.distance << ", exhaustive " << ref.face << " d "
               << ref.distance);
    }
    const Vec3 n = RandomUnit();
    for (double cosLimit : { -1.0, std::cos(kPi / 4) })
    {
      const FaceTree::Hit ref = ExhaustiveCompatible(m, p, n, cosLimit, kInf);
      const FaceTree::Hit hit = tree.ClosestCompatibleFace(p, n, cosLimit, kInf);
      if (!(hit.face == ref.face && hit.distance == ref.distance &&
            (ref.face < 0 || hit.point == ref.point)) &&
        ++mismatches <= 5)
        EXPECT(false,
          name << ": ClosestCompatibleFace at " << p.transpose() << ": face " << hit.face
               << ", exhaustive " << ref.face);
    }
    int nearest = -1;
    double nearest2 = kInf;
    for (int f = 0; f < m.NumberOfFaces(); ++f)
      if (!m.faceDegenerate[f] && (m.faceCentroids[f] - p).squaredNorm() < nearest2)
      {
        nearest2 = (m.faceCentroids[f] - p).squaredNorm();
        nearest = f;
      }
    if (tree.NearestCentroidFace(p) != nearest && ++mismatches <= 5)
      EXPECT(false, name << ": NearestCentroidFace at " << p.transpose());
  }
  EXPECT(mismatches == 0, name << ": " << mismatches << " answers differ from the scan");
}

TriangleMesh Plate(double z, bool up, int n)
{
  TriangleMesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      m.points.push_back(Vec3(double(i) / n, double(j) / n, z));
  auto id = [n](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      // (i,j) -> (i+1,j) -> (i+1,j+1): counter-clockwise seen from +z.
      foldingmeshes::Triangle a{ id(i, j), id(i + 1, j), id(i + 1, j + 1) };
      foldingmeshes::Triangle b{ id(i, j), id(i + 1, j + 1), id(i, j + 1) };
      if (!up)
      {
        std::swap(a[1], a[2]);
        std::swap(b[1], b[2]);
      }
      m.triangles.push_back(a);
      m.triangles.push_back(b);
    }
  return m;
}
}

int main()
{
  const auto t0 = std::chrono::steady_clock::now();
  using namespace foldingmeshes::testing;
  const std::vector<double> angles = { 10.0, 45.0, 90.0, 120.0 };
  {
    const PreparedMesh m =
      coretest::Prepare(coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh));
    CheckMesh("bilateral blob", m, 1000, angles, true);
    // The same faces in reverse order, so that ties are met in the other traversal order.
    TriangleMesh reversed = coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh);
    std::reverse(reversed.triangles.begin(), reversed.triangles.end());
    CheckMesh("bilateral blob, faces reversed", coretest::Prepare(reversed), 500, angles, true);
  }
  {
    const PreparedMesh m =
      coretest::Prepare(coretest::ToTriangleMesh(MakeAsymmetricBlob(2000, 5).mesh));
    CheckMesh("asymmetric blob", m, 600, angles, false);
  }
  {
    // Regression, minimal case: a flat fan whose corner normals lean 70 degrees outward (root cone
    // half-angle 70); at vertex 2 the normal (sin 70, 0, cos 70) is 110 degrees from -z, so with
    // a 120-degree limit the faces at vertex 2 are compatible with the query normal -z.
    TriangleMesh fan;
    fan.points = { Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0) };
    fan.triangles = { { 4, 0, 1 }, { 4, 1, 2 }, { 4, 2, 3 }, { 4, 3, 0 } };
    const double s70 = std::sin(70 * kPi / 180), c70 = std::cos(70 * kPi / 180);
    const std::vector<Vec3> normals = {
      Vec3(-s70, 0, c70), Vec3(0, -s70, c70), Vec3(s70, 0, c70), Vec3(0, s70, c70), Vec3(0, 0, 1)
    };
    PreparedMesh m;
    std::string error;
    REQUIRE(foldingmeshes::PrepareMesh(fan, normals, m, error), "fan: " << error);
    const FaceTree tree(m);
    const Vec3 p(1, 0, 0.5), n(0, 0, -1);
    const double cos120 = std::cos(120 * kPi / 180);
    const Reference ref = BruteCompatible(m, p, n, cos120);
    const FaceTree::Hit hit = tree.ClosestCompatibleFace(p, n, cos120, kInf);
    EXPECT(ref.face >= 0 && std::abs(ref.distance - 0.5) < 1e-15, "fan: brute force found no face");
    EXPECT(hit.face >= 0 && std::abs(hit.distance - 0.5) < 1e-15,
      "fan: ClosestCompatibleFace(p=(1,0,0.5), n=(0,0,-1), cos 120 deg) gave face "
        << hit.face << " d " << hit.distance << "; brute force face " << ref.face << " d 0.5");
  }
  {
    // Regression: normal cones of nearly parallel normals. Corner normals z, z turned by 1e-8
    // radians, z: 1 - cos rounds to 0 there, and a cone whose sine came from sqrt(1 - cos^2)
    // had no width, so a query normal 60 degrees - 1e-9 radians from the turned corner (a
    // 60-degree limit: compatible at that corner) was pruned with the face.
    TriangleMesh one;
    one.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0) };
    one.triangles = { { 0, 1, 2 } };
    const double a = 1e-8, b = a + kPi / 3.0 - 1e-9;
    const std::vector<Vec3> normals = {
      Vec3(0, 0, 1), Vec3(std::sin(a), 0, std::cos(a)), Vec3(0, 0, 1)
    };
    PreparedMesh m;
    std::string error;
    REQUIRE(foldingmeshes::PrepareMesh(one, normals, m, error), "narrow cone: " << error);
    const Vec3 p(1.5, -0.5, 0.1), n(std::sin(b), 0, std::cos(b)); // closest point: corner 1
    const double cos60 = std::cos(kPi / 3.0);
    const Reference ref = BruteCompatible(m, p, n, cos60);
    const FaceTree::Hit hit = FaceTree(m).ClosestCompatibleFace(p, n, cos60, kInf);
    EXPECT(ref.face == 0, "narrow cone: brute force found no compatible face");
    EXPECT(hit.face == ref.face && hit.distance == ref.distance,
      "narrow cone: ClosestCompatibleFace gave face " << hit.face << " d " << hit.distance
                                                      << "; brute force face " << ref.face);
  }

  // Two parallel plates: A at z = 0 facing up (+z), B at z = 1 facing down (-z).
  {
    TriangleMesh a = Plate(0.0, true, 4), b = Plate(1.0, false, 4);
    const int offset = static_cast<int>(a.points.size()), na = static_cast<int>(a.triangles.size());
    a.points.insert(a.points.end(), b.points.begin(), b.points.end());
    for (auto t : b.triangles)
      a.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    const PreparedMesh m = coretest::Prepare(a);
    REQUIRE(m.faceNormals[0].z() > 0.99 && m.faceNormals[na].z() < -0.99,
      "plates: unexpected orientation " << m.faceNormals[0].transpose() << " / "
                                        << m.faceNormals[na].transpose());
    const FaceTree tree(m);
    const double cos45 = std::cos(kPi / 4);
    const Vec3 p(0.37, 0.61, 0.3); // 0.3 above A, 0.7 below B
    const FaceTree::Hit down = tree.ClosestCompatibleFace(p, Vec3(0, 0, -1), cos45, kInf);
    EXPECT(down.face >= na && std::abs(down.distance - 0.7) < 1e-14 &&
        (down.point - Vec3(0.37, 0.61, 1.0)).norm() < 1e-14,
      "plates, normal -z: face " << down.face << " distance " << down.distance
                                 << ", expected plate B at 0.7");
    const FaceTree::Hit up = tree.ClosestCompatibleFace(p, Vec3(0, 0, 1), cos45, kInf);
    EXPECT(up.face >= 0 && up.face < na && std::abs(up.distance - 0.3) < 1e-14,
      "plates, normal +z: face " << up.face << " distance " << up.distance
                                 << ", expected plate A at 0.3");
    const FaceTree::Hit side = tree.ClosestCompatibleFace(p, Vec3(1, 0, 0), cos45, kInf);
    EXPECT(side.face == -1 && side.distance == kInf,
      "plates, normal +x: got face " << side.face << ", expected none");
    const FaceTree::Hit limited = tree.ClosestCompatibleFace(p, Vec3(0, 0, -1), cos45, 0.5);
    EXPECT(limited.face == -1, "plates, normal -z within 0.5: got face " << limited.face);
    // Tilted 40 degrees from -z: still compatible with B (45 degrees), not with A.
    const Vec3 tilted(std::sin(40 * kPi / 180), 0, -std::cos(40 * kPi / 180));
    const FaceTree::Hit t40 = tree.ClosestCompatibleFace(p, tilted, cos45, kInf);
    EXPECT(t40.face >= na, "plates, normal 40 degrees from -z: face " << t40.face);
    const FaceTree::Hit t50 = tree.ClosestCompatibleFace(
      p, Vec3(std::sin(50 * kPi / 180), 0, -std::cos(50 * kPi / 180)), cos45, kInf);
    EXPECT(t50.face == -1, "plates, normal 50 degrees from -z: face " << t50.face);
  }
  {
    // A fine plate (coplanar faces: exact distance ties) with a row of slivers (points pushed
    // almost onto the diagonal of their quad), and the bilateral blob, queried far off the
    // surface.
    TriangleMesh plate = Plate(0.0, true, 24);
    for (int j = 1; j < 24; j += 2)
    {
      // Point (12, j) almost onto the segment (11, j) - (12, j + 1): triangle (11, j),
      // (12, j), (12, j + 1) becomes a sliver 1e-7 of an edge wide.
      plate.points[12 * 25 + j] = Vec3(11.5 / 24, (j + 0.5 - 1e-7) / 24, 0.0);
    }
    CheckExact("fine plate with slivers", coretest::Prepare(plate), 400, 0.3);
    CheckExact("bilateral blob, far queries",
      coretest::Prepare(coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh)),
      400,
      0.15);
  }
  {
    // A soup: the blob with 60 large triangles across its bounding box (long slivers and fat
    // ones, random orientation), which the tree splits into pieces.
    const TriangleMesh soup = coretest::WithLargeTriangles(
      coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh), 60, U, RandomUnit);
    const PreparedMesh m = coretest::Prepare(soup);
    // The large triangles are held apart under the root (FaceTree::LargeFaces), the blob's
    // own faces not; a blob of 200 faces with 100 large ones has no outliers.
    const int large = FaceTree(m).LargeFaces();
    EXPECT(large > 0 && large <= 60, "blob with large triangles: " << large << " held apart");
    EXPECT(FaceTree(coretest::Prepare(coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh)))
             .LargeFaces() == 0,
      "blob: faces held apart");
    const TriangleMesh mostlyLarge = coretest::WithLargeTriangles(
      coretest::ToTriangleMesh(MakeBilateralBlob(200).mesh), 100, U, RandomUnit);
    EXPECT(FaceTree(coretest::Prepare(mostlyLarge)).LargeFaces() == 0,
      "a third of the faces large: held apart as outliers");
    CheckMesh("blob with large triangles", m, 600, angles, false);
    CheckExact("blob with large triangles, near", m, 400, 0.02);
    CheckExact("blob with large triangles, far", m, 400, 0.15);
    CheckPlainExact("blob with large triangles", m, 300, 0.1);
    CheckExactAtSurface("blob with large triangles, on the surface and far", m, 600);
    // The smallest tree with a face held apart: 12 faces, one of them 50 times the others.
    TriangleMesh few;
    for (int k = 0; k < 11; ++k)
    {
      const int base = static_cast<int>(few.points.size());
      few.points.insert(few.points.end(),
        { Vec3(0.1 * k, 0, 0), Vec3(0.1 * k + 0.05, 0, 0.01), Vec3(0.1 * k, 0.05, 0.02) });
      few.triangles.push_back({ base, base + 1, base + 2 });
    }
    few.points.insert(few.points.end(), { Vec3(-1, -1, 0.3), Vec3(2.5, -1, 0.3), Vec3(0, 2, 0.3) });
    few.triangles.push_back({ 33, 34, 35 });
    const PreparedMesh fewMesh = coretest::Prepare(few);
    EXPECT(FaceTree(fewMesh).LargeFaces() == 1, "12 faces, one large: not held apart");
    CheckExact("12 faces, one large", fewMesh, 300, 0.5);
    CheckExactAtSurface("12 faces, one large, on the surface and far", fewMesh, 300);
  }
  {
    // Long slivers, axis-aligned and turned: only the turned cylinder gets a rotated frame.
    const TriangleMesh cylinder = coretest::SliverCylinder(0.025, 0.22, 300);
    const PreparedMesh straight = coretest::Prepare(cylinder);
    EXPECT(!FaceTree(straight).RotatedFrame(), "axis-aligned cylinder: rotated box frame");
    TriangleMesh turned = cylinder;
    for (Vec3& x : turned.points)
      x = coretest::Turned(x);
    const PreparedMesh m = coretest::Prepare(turned);
    EXPECT(FaceTree(m).RotatedFrame(), "turned cylinder of slivers: boxes not in a rotated frame");
    CheckMesh("turned cylinder of slivers", m, 200, angles, false);
    CheckExact("turned cylinder of slivers, near", m, 300, 0.02);
    CheckExact("turned cylinder of slivers, far", m, 300, 0.3);
    CheckPlainExact("turned cylinder of slivers, near", m, 300, 0.02);
    CheckPlainExact("turned cylinder of slivers, far", m, 300, 0.3);
    CheckExactAtSurface("turned cylinder of slivers, on the surface and far", m, 900);
    TriangleMesh far = turned;
    for (Vec3& x : far.points)
      x += Vec3(1e6, -2e6, 3e6);
    const PreparedMesh farMesh = coretest::Prepare(far);
    EXPECT(
      FaceTree(farMesh).RotatedFrame(), "turned cylinder at 1e6: boxes not in a rotated frame");
    CheckExactAtSurface("turned cylinder of slivers 1e6 from the origin", farMesh, 900);
    // The same far away in the identity frame (the boxes relative to the tree's centre).
    TriangleMesh farStraight = cylinder;
    for (Vec3& x : farStraight.points)
      x += Vec3(1e6, -2e6, 3e6);
    const PreparedMesh farStraightMesh = coretest::Prepare(farStraight);
    EXPECT(!FaceTree(farStraightMesh).RotatedFrame(), "axis-aligned cylinder at 1e6: rotated");
    CheckExactAtSurface("axis-aligned cylinder 1e6 from the origin", farStraightMesh, 900);
    CheckExact("axis-aligned cylinder 1e6 from the origin", farStraightMesh, 300, 0.05);
    CheckPlainExact(
      "blob", coretest::Prepare(coretest::ToTriangleMesh(MakeBilateralBlob(3000).mesh)), 300, 0.1);
    // A rotated frame and large faces held apart together.
    // ... with 10 triangles 14 times the slivers' length across the axis, turned alike.
    TriangleMesh withLarge = turned;
    for (int k = 0; k < 10; ++k)
    {
      const int base = static_cast<int>(withLarge.points.size());
      const double z = 0.02 * k;
      for (const Vec3& x : { Vec3(-3.0, -3.0, z), Vec3(3.0, -3.0, z), Vec3(0.0, 3.0, z) })
        withLarge.points.push_back(coretest::Turned(x));
      withLarge.triangles.push_back({ base, base + 1, base + 2 });
    }
    const PreparedMesh both = coretest::Prepare(withLarge);
    const FaceTree bothTree(both);
    EXPECT(bothTree.RotatedFrame() && bothTree.LargeFaces() > 0,
      "turned cylinder with large triangles: rotated " << bothTree.RotatedFrame() << ", "
                                                       << bothTree.LargeFaces() << " held apart");
    CheckExact("turned cylinder with large triangles", both, 300, 0.1);
    CheckPlainExact("turned cylinder with large triangles", both, 300, 0.1);
    CheckExactAtSurface("turned cylinder with large triangles, on the surface and far", both, 600);
  }
  std::printf("TestFaceTree: %.2f s\n", coretest::Seconds(t0));
  return coretest::Finish("TestFaceTree");
}
