// The sampled candidate search of DetectSymmetry (the folding-tree builder uses it on every
// region above FoldingTreeOptions::sampledSearchAboveFaces faces):
// - ClusterVertices: the copy's points are vertices of the mesh (bit for bit) with the mesh's
//   normals, about the requested number of faces, deterministic; a mesh no larger than the
//   target comes back whole; the two sides of a plate thinner than a grid cell stay apart
//   (the copy keeps the plate's area instead of folding it onto one sheet); a mesh of many
//   small parts gets a copy from larger cells that uses at most one point per face asked for
//   (at least 0.4);
// - MirrorDistance from the copy to the full mesh: every copy point gets the distance its
//   vertex gets in the full mesh (same point and face tree; the normal as PrepareMesh
//   normalises it again, to the last bits);
// - DetectSymmetry with the sampled search (finalists only scored, as the builder runs it) on
//   an exactly symmetric blob: the exact plane and the whole mesh, as the full search finds
//   them; on a blob with a 30% asymmetric attachment: the plane of the body;
// - the same plane, regions, finalists and starts with vtkSMPTools Sequential and STDThread
//   (2 threads), where several probes and finals run in parallel (the attachment).
#include "ClusteredMesh.h"
#include "CoreTestUtilities.h"
#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "ProceduralMeshes.h"
#include "RegionGrowing.h"
#include "SymmetryDetection.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

using foldingmeshes::ClusteredMesh;
using foldingmeshes::ClusterVertices;
using foldingmeshes::DistanceMetric;
using foldingmeshes::MirrorDistance;
using foldingmeshes::Plane;
using foldingmeshes::PreparedMesh;
using foldingmeshes::SymmetryOptions;
using foldingmeshes::SymmetryResult;
using foldingmeshes::TriangleMesh;
using foldingmeshes::Vec3;

namespace
{
const double kInf = std::numeric_limits<double>::infinity();

bool Same(const Vec3& a, const Vec3& b)
{
  return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0;
}

double AngleDegrees(const Vec3& a, const Vec3& b)
{
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180.0 / M_PI;
}

PreparedMesh PrepareCopy(const ClusteredMesh& c)
{
  PreparedMesh copy;
  std::string error;
  REQUIRE(foldingmeshes::PrepareMesh(c.mesh, c.normals, copy, error), "copy: " << error);
  return copy;
}

/// `shape` under the random rigid motion of `seed`, prepared.
PreparedMesh Moved(foldingmeshes::testing::ProceduralMesh& shape, unsigned seed)
{
  using namespace foldingmeshes::testing;
  ApplyRigidMotion(shape, RandomRigidMotion(seed));
  return coretest::Prepare(coretest::ToTriangleMesh(shape.mesh));
}

/// The builder's detection settings at a region: sampled search, finalists only scored.
SymmetryOptions SampledOptions(double epsilon)
{
  SymmetryOptions o;
  o.epsilon = epsilon;
  o.sampledSearchAboveFaces = 0;
  o.refineSampledFinalists = false;
  return o;
}

void CheckClusterVertices()
{
  using namespace foldingmeshes::testing;
  ProceduralMesh blob = MakeBilateralBlob(8000, 5);
  const PreparedMesh m = Moved(blob, 5);
  const int target = m.NumberOfFaces() / 4;
  const ClusteredMesh c = ClusterVertices(m, target);
  const int nf = static_cast<int>(c.mesh.triangles.size());
  std::printf("ClusterVertices: %d faces -> %d (target %d), %zu points\n",
    m.NumberOfFaces(),
    nf,
    target,
    c.mesh.points.size());
  EXPECT(
    nf > target / 2 && nf < 2 * target, "copy has " << nf << " faces for a target of " << target);
  REQUIRE(c.vertex.size() == c.mesh.points.size() && c.normals.size() == c.mesh.points.size(),
    "one vertex id and normal per copy point");
  bool exact = true, distinct = true;
  std::vector<char> seen(m.NumberOfPoints(), 0);
  for (size_t i = 0; i < c.vertex.size(); ++i)
  {
    const int v = c.vertex[i];
    REQUIRE(v >= 0 && v < m.NumberOfPoints(), "copy point " << i << ": vertex id " << v);
    exact = exact && Same(c.mesh.points[i], m.points[v]) && Same(c.normals[i], m.vertexNormals[v]);
    distinct = distinct && !seen[v];
    seen[v] = 1;
  }
  EXPECT(exact, "every copy point is its mesh vertex, with that vertex's normal, bit for bit");
  EXPECT(distinct, "no vertex represents two clusters");

  const ClusteredMesh again = ClusterVertices(m, target);
  EXPECT(again.vertex == c.vertex && again.mesh.triangles == c.mesh.triangles,
    "ClusterVertices is deterministic");

  const ClusteredMesh whole = ClusterVertices(m, m.NumberOfFaces());
  int used = 0;
  for (int f = 0; f < m.NumberOfFaces(); ++f)
    used += !m.faceDegenerate[f];
  EXPECT(static_cast<int>(whole.mesh.triangles.size()) == used &&
      whole.mesh.points.size() == m.points.size(),
    "a mesh no larger than the target comes back whole");

  // A plate 50 times thinner than a grid cell: both sheets must survive.
  ProceduralMesh box = MakeThreePlaneShape(8000);
  TriangleMesh plate = coretest::ToTriangleMesh(box.mesh);
  for (Vec3& p : plate.points)
    p.z() *= 0.02;
  const PreparedMesh thin = coretest::Prepare(plate);
  const PreparedMesh thinCopy = PrepareCopy(ClusterVertices(thin, thin.NumberOfFaces() / 4));
  const double ratio = thinCopy.totalArea / thin.totalArea;
  std::printf("thin plate: area of the copy / area of the plate %.3f\n", ratio);
  EXPECT(ratio > 0.85 && ratio < 1.05,
    "the copy of a thin plate keeps both sheets (area ratio " << ratio << ")");
}

/// Points of the copy that its triangles use (the ones detection queries).
int PointsUsed(const ClusteredMesh& c)
{
  std::vector<char> used(c.mesh.points.size(), 0);
  for (const auto& t : c.mesh.triangles)
    for (int v : t)
      used[v] = 1;
  return static_cast<int>(std::count(used.begin(), used.end(), 1));
}

/// `count` closed boxes (8 points, 12 faces each) on a grid in a slab, sizes 0.3-1.7 times
/// `size` along each of their axes, turned at random (seeded).
TriangleMesh ManyBoxes(int count, double size)
{
  TriangleMesh mesh;
  unsigned state = 12345;
  auto uniform = [&]()
  {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / 16777216.0;
  };
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  static const int faces[12][3] = { { 0, 2, 1 },
    { 0, 3, 2 },
    { 4, 5, 6 },
    { 4, 6, 7 },
    { 0, 1, 5 },
    { 0, 5, 4 },
    { 2, 3, 7 },
    { 2, 7, 6 },
    { 1, 2, 6 },
    { 1, 6, 5 },
    { 0, 4, 7 },
    { 0, 7, 3 } };
  for (int b = 0; b < count; ++b)
  {
    const Vec3 center(3.0 * size * (b % side), 3.0 * size * (b / side), 0.0);
    // One draw per statement: the order of a call's arguments is unspecified.
    const double hx = uniform(), hy = uniform(), hz = uniform();
    const Vec3 half = 0.5 * size * Vec3(0.3 + 1.4 * hx, 0.3 + 1.4 * hy, 0.3 + 1.4 * hz);
    const double angle = 2.0 * M_PI * uniform(), ax = uniform(), ay = uniform();
    const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(angle, Vec3(ax, ay, 1.0).normalized()).toRotationMatrix();
    const int first = static_cast<int>(mesh.points.size());
    for (int k = 0; k < 8; ++k)
    {
      const Vec3 corner((k == 1 || k == 2 || k == 5 || k == 6) ? 1.0 : -1.0,
        (k == 2 || k == 3 || k == 6 || k == 7) ? 1.0 : -1.0,
        k >= 4 ? 1.0 : -1.0);
      mesh.points.push_back(center + turn * corner.cwiseProduct(half));
    }
    for (const auto& f : faces)
      mesh.triangles.push_back({ first + f[0], first + f[1], first + f[2] });
  }
  return mesh;
}

/// A mesh of many small parts keeps most of its vertices at the connected surface's cell size
/// (its parts' corners); the copy then comes from larger cells: at most one point per face
/// asked for, at least 0.4 (where parts of one size collapse all at once, no size gives that
/// and the first copy stays: the artist-like rack_exact, TestArtistFolds).
void CheckManySmallParts()
{
  const PreparedMesh varied = coretest::Prepare(ManyBoxes(1200, 1.0));
  const int target = varied.NumberOfFaces() / 4;
  const ClusteredMesh c = ClusterVertices(varied, target);
  const int used = PointsUsed(c);
  std::printf("1200 boxes of varied sizes and turns: %d faces, %d points -> copy of %zu faces "
              "using %d points (target %d)\n",
    varied.NumberOfFaces(),
    varied.NumberOfPoints(),
    c.mesh.triangles.size(),
    used,
    target);
  EXPECT(used <= target && used >= 0.4 * target,
    "the copy of many small parts uses " << used << " points for a target of " << target
                                         << " faces (0.4-1 per face)");
  bool exact = true;
  for (size_t i = 0; i < c.vertex.size(); ++i)
    exact = exact && Same(c.mesh.points[i], varied.points[c.vertex[i]]);
  EXPECT(exact, "the coarser copy's points are vertices of the mesh");
  const ClusteredMesh again = ClusterVertices(varied, target);
  EXPECT(again.vertex == c.vertex && again.mesh.triangles == c.mesh.triangles,
    "the coarser copy is deterministic");

  // The same boxes, 400 of them (4,800 faces): below 5000 faces the copy is not made again,
  // and it uses more points than faces asked for - what the larger mesh's copy did too.
  const PreparedMesh fewer = coretest::Prepare(ManyBoxes(400, 1.0));
  const int fewerTarget = fewer.NumberOfFaces() / 4;
  const int fewerUsed = PointsUsed(ClusterVertices(fewer, fewerTarget));
  std::printf("400 boxes: copy using %d points (target %d)\n", fewerUsed, fewerTarget);
  EXPECT(fewerUsed > fewerTarget,
    "400 boxes keep their first copy, " << fewerUsed << " points for " << fewerTarget
                                        << " faces asked for");
}

void CheckDistancesToFullMesh()
{
  using namespace foldingmeshes::testing;
  ProceduralMesh blob = MakeBilateralBlob(6000, 3);
  const PreparedMesh m = Moved(blob, 3);
  const ClusteredMesh c = ClusterVertices(m, m.NumberOfFaces() / 4);
  const PreparedMesh copy = PrepareCopy(c);
  REQUIRE(copy.NumberOfPoints() == static_cast<int>(c.vertex.size()),
    "PrepareMesh keeps the copy's points");
  Plane plane;
  plane.origin = blob.planes[0].origin;
  plane.normal = blob.planes[0].normal.normalized();
  const Vec3 tilt = plane.normal.unitOrthogonal();
  for (const Plane& p : { plane, Plane{ plane.origin, (plane.normal + 0.05 * tilt).normalized() } })
  {
    const MirrorDistance full(m, 45.0), sampled(copy, m, 45.0);
    std::vector<double> dFull, dCopy;
    full.Compute(p, DistanceMetric::Fine, 6.0 * 0.02 * m.diagonal, dFull);
    sampled.Compute(p, DistanceMetric::Fine, 6.0 * 0.02 * m.diagonal, dCopy);
    int compared = 0, equal = 0, finite = 0;
    for (size_t i = 0; i < c.vertex.size(); ++i)
    {
      // Only points whose prepared normal is the vertex's (PrepareMesh normalises the given
      // normal again and may turn it to the side of the copy's own surface).
      if ((copy.vertexNormals[i] - m.vertexNormals[c.vertex[i]]).norm() > 1e-12)
        continue;
      ++compared;
      const double a = dCopy[i], b = dFull[c.vertex[i]];
      finite += std::isfinite(a);
      equal += (a == kInf && b == kInf) || std::abs(a - b) <= 1e-12 * m.diagonal;
    }
    std::printf("distances to the full mesh: %d of %zu copy points compared, %d equal, %d finite\n",
      compared,
      c.vertex.size(),
      equal,
      finite);
    EXPECT(compared > 0.95 * c.vertex.size(), "copy points keep their vertex normals");
    EXPECT(equal == compared, "a copy point's distance is its vertex's distance in the full mesh");
    EXPECT(finite > 0, "some distances are finite");
  }
}

struct Detected
{
  SymmetryResult result;
  double angle = 0.0, regionFraction = 0.0;
};

Detected Detect(const PreparedMesh& m, const SymmetryOptions& o, const Vec3& normal)
{
  Detected d;
  d.result = foldingmeshes::DetectSymmetry(m, o);
  d.angle = AngleDegrees(d.result.plane.normal, normal);
  d.regionFraction = d.result.symmetricAreaFraction;
  return d;
}

void CheckDetection()
{
  using namespace foldingmeshes::testing;
  {
    ProceduralMesh blob = MakeBilateralBlob(8000, 7);
    const PreparedMesh m = Moved(blob, 7);
    const Vec3 normal = blob.planes[0].normal;
    const double eps = 0.02 * m.diagonal;
    const Detected sampled = Detect(m, SampledOptions(eps), normal);
    SymmetryOptions fullOptions;
    fullOptions.epsilon = eps;
    fullOptions.sampledSearchAboveFaces = std::numeric_limits<int>::max();
    const Detected full = Detect(m, fullOptions, normal);
    std::printf("symmetric blob: sampled %.4f deg region %.4f starts %d | full %.4f deg region "
                "%.4f starts %d\n",
      sampled.angle,
      sampled.regionFraction,
      sampled.result.startsTried,
      full.angle,
      full.regionFraction,
      full.result.startsTried);
    EXPECT(sampled.angle < 0.05 &&
        std::abs(blob.planes[0].normal.normalized().dot(
          sampled.result.plane.origin - blob.planes[0].origin)) < 1e-4 * m.diagonal,
      "sampled search: the exact plane (" << sampled.angle << " deg)");
    EXPECT(sampled.regionFraction > 0.99 && sampled.result.found,
      "sampled search: the whole blob is symmetric (" << sampled.regionFraction << ")");
    EXPECT(sampled.result.startsTried == 1,
      "sampled search: an exact global symmetry settles at the first start ("
        << sampled.result.startsTried << " starts)");
    EXPECT(std::abs(sampled.regionFraction - full.regionFraction) < 0.01,
      "sampled and full search find the same region");
  }
  {
    ProceduralMesh horned = MakeBlobWithAsymmetricPart(8000, 0.3, 8);
    const PreparedMesh m = Moved(horned, 8);
    const Detected d = Detect(m, SampledOptions(0.02 * m.diagonal), horned.planes[0].normal);
    std::vector<char> inRegion(m.NumberOfFaces(), 0);
    for (int f = 0; f < m.NumberOfFaces(); ++f)
      inRegion[f] = d.result.faceLabel[f] == 2 && !horned.symmetricFace[f];
    const double inAttachment = foldingmeshes::RegionArea(m, inRegion) / m.totalArea;
    std::printf("blob with a 30%% attachment: %.3f deg, region %.3f, %.3f of the area in the "
                "attachment, %d starts\n",
      d.angle,
      d.regionFraction,
      inAttachment,
      d.result.startsTried);
    EXPECT(d.angle < 0.5, "attachment: the plane of the body (" << d.angle << " deg)");
    EXPECT(d.regionFraction > 0.55 && inAttachment < 0.05,
      "attachment: the region is the body (" << d.regionFraction << ", " << inAttachment
                                             << " in the attachment)");

    // Thread counts: the probes after the first and the finals run as parallel tasks; the
    // result must be that of the serial order, bit for bit, sampled or full search.
    SymmetryOptions full = SampledOptions(0.02 * m.diagonal);
    full.sampledSearchAboveFaces = std::numeric_limits<int>::max();
    for (const SymmetryOptions& o : { SampledOptions(0.02 * m.diagonal), full })
    {
      const char* search = o.sampledSearchAboveFaces == 0 ? "sampled" : "full";
      REQUIRE(vtkSMPTools::SetBackend("Sequential"), "SetBackend(Sequential) failed");
      const SymmetryResult serial = foldingmeshes::DetectSymmetry(m, o);
      REQUIRE(vtkSMPTools::SetBackend("STDThread"), "SetBackend(STDThread) failed");
      vtkSMPTools::Initialize(2);
      const SymmetryResult threaded = foldingmeshes::DetectSymmetry(m, o);
      REQUIRE(vtkSMPTools::SetBackend("Sequential"), "SetBackend(Sequential) failed");
      bool sameFinalists = serial.finalists.size() == threaded.finalists.size();
      for (size_t k = 0; sameFinalists && k < serial.finalists.size(); ++k)
        sameFinalists = Same(serial.finalists[k].normal, threaded.finalists[k].normal) &&
          Same(serial.finalists[k].origin, threaded.finalists[k].origin);
      std::printf("attachment, %s search: %d starts, %zu finalists\n",
        search,
        serial.startsTried,
        serial.finalists.size());
      EXPECT(serial.startsTried > 1,
        search << " search: several probes ran in parallel (" << serial.startsTried << ")");
      EXPECT(Same(serial.plane.normal, threaded.plane.normal) &&
          Same(serial.plane.origin, threaded.plane.origin) &&
          serial.faceLabel == threaded.faceLabel && sameFinalists &&
          serial.startsTried == threaded.startsTried,
        search << " search: the same result with 1 and 2 threads");
    }
  }
}
}

int main()
{
  vtkSMPTools::SetBackend("Sequential");
  CheckClusterVertices();
  CheckManySmallParts();
  CheckDistancesToFullMesh();
  CheckDetection();
  return coretest::Finish("TestSampledSearch");
}
