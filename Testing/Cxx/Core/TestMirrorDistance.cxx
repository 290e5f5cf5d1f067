// MirrorDistance on an exactly symmetric procedural blob (plane x = 0, after a rigid motion):
// - fine metric at the true plane: every vertex within 1e-9 * diagonal, closest points at d;
// - fine metric at the plane tilted by 10 degrees: most vertices far (a reflection composed
//   with the true one is a 20-degree rotation, moving points by ~0.35 x their distance to the
//   axis);
// - coarse metric = brute force of the paper's definition (reflect vertex and normal; face with
//   the nearest centroid; distance to its plane; infinite if the normals are >= 90 degrees
//   apart), with its closest point (foot of the perpendicular) and normal, at several planes;
// - vtkSMPTools Sequential vs STDThread (2 threads): bit-identical results;
// - the fast path (SetFastPath, issue 19) with an exact plain closest-face query and with one
//   that answers some far face: bit-identical fine results to the face tree alone.
#include "CoreTestUtilities.h"
#include "MirrorDistance.h"
#include "PointTriangleDistance.h"
#include "ProceduralMeshes.h"

#include <vtkSMPTools.h>

#include <Eigen/Geometry>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

using foldingmeshes::DistanceMetric;
using foldingmeshes::MirrorDistance;
using foldingmeshes::Plane;
using foldingmeshes::PreparedMesh;
using foldingmeshes::Vec3;

namespace
{
const double kInf = std::numeric_limits<double>::infinity();
const double kPi = 3.14159265358979323846;

/// A plain closest-face query by brute force over every triangle (`far`: it answers the
/// triangle after the closest one instead, a wrong answer the fast path must survive).
class BruteForceQuery : public foldingmeshes::ClosestFaceQuery
{
public:
  BruteForceQuery(const PreparedMesh& m, bool far)
    : Mesh(m)
    , Far(far)
  {
  }
  foldingmeshes::ClosestFaceHit Closest(const Vec3& p) const override
  {
    ++this->Calls;
    foldingmeshes::ClosestFaceHit hit;
    for (int f = 0; f < this->Mesh.NumberOfFaces(); ++f)
    {
      const auto& t = this->Mesh.triangles[f];
      const auto cp = foldingmeshes::ClosestPointTriangle(
        p, this->Mesh.points[t[0]], this->Mesh.points[t[1]], this->Mesh.points[t[2]]);
      if (std::sqrt(cp.squaredDistance) < hit.distance)
        hit = { f, std::sqrt(cp.squaredDistance), cp.point };
    }
    if (this->Far && hit.face >= 0)
      hit.face = (hit.face + 1) % this->Mesh.NumberOfFaces();
    return hit;
  }
  mutable std::atomic<long> Calls{ 0 };

private:
  const PreparedMesh& Mesh;
  bool Far;
};

/// The paper's coarse distance, by brute force over all faces.
void BruteCoarse(const PreparedMesh& m,
  const Plane& plane,
  std::vector<double>& d,
  std::vector<Vec3>& closest,
  std::vector<Vec3>& normals)
{
  const int nv = m.NumberOfPoints();
  d.assign(nv, kInf);
  closest.assign(nv, Vec3::Zero());
  normals.assign(nv, Vec3::Zero());
  for (int i = 0; i < nv; ++i)
  {
    const Vec3 r = plane.Reflect(m.points[i]);
    const Vec3 rn = plane.ReflectDirection(m.vertexNormals[i]);
    int best = -1;
    double best2 = kInf;
    for (int f = 0; f < m.NumberOfFaces(); ++f)
    {
      const double d2 = (m.faceCentroids[f] - r).squaredNorm();
      if (!m.faceDegenerate[f] && d2 < best2)
      {
        best2 = d2;
        best = f;
      }
    }
    // Angle < 90 degrees <=> positive cosine.
    if (best >= 0 && m.faceNormals[best].dot(rn) > 0.0)
    {
      const double h = m.faceNormals[best].dot(r - m.faceCentroids[best]);
      d[i] = std::abs(h);
      closest[i] = r - h * m.faceNormals[best];
      normals[i] = m.faceNormals[best];
    }
  }
}

bool BitIdentical(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
bool BitIdentical(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

Plane Tilted(const Plane& p, double degrees, const Vec3& axis, const Vec3& about)
{
  Plane t;
  t.normal = Eigen::AngleAxisd(degrees * kPi / 180.0, axis.normalized()) * p.normal;
  t.origin = p.Project(about);
  return t;
}
}

int main()
{
  const auto t0 = std::chrono::steady_clock::now();
  using namespace foldingmeshes::testing;
  ProceduralMesh blob = MakeBilateralBlob(4000, 3);
  ApplyRigidMotion(blob, RandomRigidMotion(11));
  const PreparedMesh m = coretest::Prepare(coretest::ToTriangleMesh(blob.mesh));
  REQUIRE(blob.planes.size() == 1, "the bilateral blob should have one plane");
  Plane truth;
  truth.origin = blob.planes[0].origin;
  truth.normal = blob.planes[0].normal.normalized();
  const double diag = m.diagonal;
  Vec3 center = Vec3::Zero();
  for (const Vec3& p : m.points)
    center += p / m.NumberOfPoints();

  vtkSMPTools::SetBackend("Sequential");
  const MirrorDistance distances(m, 45.0);
  std::vector<double> d;
  std::vector<Vec3> closest, normals;

  // ---- Fine metric at the true plane ----
  distances.Compute(truth, DistanceMetric::Fine, kInf, d, &closest, &normals);
  double worst = 0.0;
  for (int i = 0; i < m.NumberOfPoints(); ++i)
  {
    worst = std::max(worst, d[i]);
    const double dc = (closest[i] - truth.Reflect(m.points[i])).norm();
    EXPECT(std::abs(dc - d[i]) <= 1e-12 * diag,
      "fine: closest point of vertex " << i << " is at " << dc << ", distance " << d[i]);
    EXPECT(std::abs(normals[i].norm() - 1.0) < 1e-12, "fine: closest normal " << i << " not unit");
  }
  EXPECT(
    worst < 1e-9 * diag, "fine distance at the true plane: max " << worst / diag << " x diagonal");
  // Sensitivity: the origin moved by 1e-3 diagonal gives distances of about 2e-3 diagonal.
  {
    Plane shifted = truth;
    shifted.origin += 1e-3 * diag * truth.normal;
    distances.Compute(shifted, DistanceMetric::Fine, kInf, d);
    int far = 0;
    for (double v : d)
      far += v > 1e-4 * diag;
    EXPECT(far > m.NumberOfPoints() / 2,
      "fine: a shifted plane still gives small distances (" << far << ")");
  }

  // ---- Fine metric at the plane tilted by 10 degrees ----
  const Vec3 tiltAxis = truth.normal.unitOrthogonal();
  const Plane tilted = Tilted(truth, 10.0, tiltAxis, center);
  EXPECT(
    std::abs(foldingmeshes::PlaneAngleDegrees(tilted, truth) - 10.0) < 1e-9, "tilt construction");
  distances.Compute(tilted, DistanceMetric::Fine, kInf, d);
  int far = 0;
  for (double v : d)
    far += v > 1e-3 * diag;
  EXPECT(far > 0.5 * m.NumberOfPoints(),
    "tilted 10 degrees: only " << far << " of " << m.NumberOfPoints()
                               << " vertices beyond 1e-3 diagonal");

  // ---- Coarse metric vs brute force, at several planes ----
  std::vector<Plane> planes = { truth,
    tilted,
    Tilted(truth, 45.0, tiltAxis, center),
    Tilted(truth, 90.0, truth.normal.cross(tiltAxis), center) };
  for (size_t k = 0; k < planes.size(); ++k)
  {
    std::vector<double> bd;
    std::vector<Vec3> bc, bn;
    BruteCoarse(m, planes[k], bd, bc, bn);
    distances.Compute(planes[k], DistanceMetric::Coarse, kInf, d, &closest, &normals);
    int mismatches = 0, infinite = 0;
    for (int i = 0; i < m.NumberOfPoints(); ++i)
    {
      infinite += !std::isfinite(bd[i]);
      const bool same = (std::isinf(bd[i]) && std::isinf(d[i])) ||
        (std::abs(bd[i] - d[i]) <= 1e-12 * diag && (bc[i] - closest[i]).norm() <= 1e-12 * diag &&
          (bn[i] - normals[i]).norm() <= 1e-12);
      if (!same && ++mismatches <= 3)
        EXPECT(false,
          "coarse, plane " << k << ", vertex " << i << ": " << d[i] << " brute force " << bd[i]);
    }
    EXPECT(mismatches == 0, "coarse, plane " << k << ": " << mismatches << " mismatches");
    std::printf(
      "plane %zu: coarse metric infinite for %d of %d vertices\n", k, infinite, m.NumberOfPoints());
  }

  // ---- Sequential vs STDThread ----
  std::vector<double> seqFine, seqCoarse, thrFine, thrCoarse;
  std::vector<Vec3> seqClosest, thrClosest, seqNormals, thrNormals;
  for (int backend = 0; backend < 2; ++backend)
  {
    const bool threads = backend == 1;
    REQUIRE(vtkSMPTools::SetBackend(threads ? "STDThread" : "Sequential"), "SetBackend failed");
    vtkSMPTools::Initialize(2);
    REQUIRE(std::strcmp(vtkSMPTools::GetBackend(), threads ? "STDThread" : "Sequential") == 0,
      "backend is " << vtkSMPTools::GetBackend());
    if (threads)
      EXPECT(vtkSMPTools::GetEstimatedNumberOfThreads() == 2,
        "STDThread threads: " << vtkSMPTools::GetEstimatedNumberOfThreads());
    const MirrorDistance md(m, 45.0);
    md.Compute(tilted,
      DistanceMetric::Fine,
      0.1 * diag,
      threads ? thrFine : seqFine,
      threads ? &thrClosest : &seqClosest,
      threads ? &thrNormals : &seqNormals);
    md.Compute(planes[2], DistanceMetric::Coarse, kInf, threads ? thrCoarse : seqCoarse);
  }
  EXPECT(BitIdentical(seqFine, thrFine) && BitIdentical(seqClosest, thrClosest) &&
      BitIdentical(seqNormals, thrNormals),
    "fine distances differ between Sequential and STDThread");
  EXPECT(
    BitIdentical(seqCoarse, thrCoarse), "coarse distances differ between Sequential and STDThread");
  vtkSMPTools::SetBackend("Sequential");

  // ---- The fast path: bit for bit the face tree's answers, whatever the plain query says ----
  for (const bool far : { false, true })
  {
    const BruteForceQuery plain(m, far);
    MirrorDistance fast(m, 45.0);
    fast.SetFastPath(&plain);
    const MirrorDistance tree(m, 45.0);
    for (const Plane& plane : { truth, tilted })
      for (const double reach : { kInf, 0.05 * diag })
      {
        std::vector<double> d0, d1;
        std::vector<Vec3> c0, c1, n0, n1;
        std::vector<int> f0, f1;
        tree.Compute(plane, DistanceMetric::Fine, reach, d0, &c0, &n0, &f0);
        fast.Compute(plane, DistanceMetric::Fine, reach, d1, &c1, &n1, &f1);
        EXPECT(BitIdentical(d0, d1) && BitIdentical(c0, c1) && BitIdentical(n0, n1) && f0 == f1,
          "fast path (" << (far ? "a far face" : "exact") << " plain query, reach " << reach
                        << "): results differ from the face tree alone");
      }
    EXPECT(plain.Calls > 0, "the fast path never asked its plain query");
  }

  std::printf("TestMirrorDistance: %.2f s\n", coretest::Seconds(t0));
  return coretest::Finish("TestMirrorDistance");
}
