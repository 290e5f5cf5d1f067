// Checks that the procedural test meshes are what ProceduralMeshes.h promises: triangles only, no
// duplicate points, closed, edge- and vertex-manifold, consistently and outwardly oriented, face
// counts near the request, exact mirror planes (also after a rigid motion and a scaling), the
// surface-only symmetry of the differently tessellated blob, area fractions, components,
// determinism, and that the ground truth is unambiguous for the detector at its default
// tolerance (2% of the diagonal): no other plane gives a comparable symmetric region.
// Prints one line per mesh; returns nonzero with a message per failed check.
//
// The symmetric regions are measured with FoldingMeshesCore (PrepareMesh, MirrorDistance,
// LargestConnectedRegion) when that library is linked to this test, else with an equivalent
// implementation of the same rule in TestProceduralMeshesRegion.cxx. The shared check helpers are
// in TestProceduralMeshesChecks.h/.cxx; this file holds main() and the order of the checks.
#include "ProceduralMeshes.h"
#include "TestProceduralMeshesChecks.h"
#include "TestProceduralMeshesRegion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

using namespace tpm;

int main()
{
  const auto start = std::chrono::steady_clock::now();
  auto section = [&](const char* title) { std::printf("[%.1f s] %s\n", Seconds(start), title); };
  const std::vector<Gen> gens = {
    { "BilateralBlob", [](int f) { return MakeBilateralBlob(f); }, true, true, 1 },
    { "BilateralBlobDifferentTessellation",
      [](int f) { return MakeBilateralBlobDifferentTessellation(f); },
      false,
      false,
      1 },
    { "ThreePlaneShape", [](int f) { return MakeThreePlaneShape(f); }, true, true, 1 },
    { "BlobWithAsymmetricPart(0.25)",
      [](int f) { return MakeBlobWithAsymmetricPart(f, 0.25); },
      true,
      true,
      1 },
    { "AsymmetricBodyWithSymmetricPart(0.2)",
      [](int f) { return MakeAsymmetricBodyWithSymmetricPart(f, 0.2); },
      true,
      true,
      1 },
    { "AsymmetricBlob", [](int f) { return MakeAsymmetricBlob(f); }, false, false, 1 },
    { "Sphere", [](int f) { return MakeSphere(f); }, true, true, 1 },
    { "Cylinder", [](int f) { return MakeCylinder(f); }, true, false, 1 },
    { "MultiPartSymmetric", [](int f) { return MakeMultiPartSymmetric(f); }, true, true, 3 },
  };

  section("the checks catch broken meshes");
  {
    const Gen& g = gens[0];
    const ProceduralMesh m = MakeBilateralBlob(500);
    ExpectCaught(g, m, "one flipped triangle", [](Soup& s) { std::swap(s.t[7][0], s.t[7][1]); });
    ExpectCaught(g,
      m,
      "all triangles flipped (inward)",
      [](Soup& s)
      {
        for (Tri& t : s.t)
          std::swap(t[0], t[1]);
      });
    ExpectCaught(g, m, "one triangle removed (hole)", [](Soup& s) { s.t.pop_back(); });
    ExpectCaught(g, m, "one triangle doubled", [](Soup& s) { s.t.push_back(s.t[3]); });
    ExpectCaught(g,
      m,
      "a duplicated point",
      [](Soup& s)
      {
        s.p.push_back(s.p[s.t[5][0]]);
        s.t[5][0] = vtkIdType(s.p.size() - 1);
      });
    ExpectCaught(g, m, "an unused point", [](Soup& s) { s.p.push_back(Vec3(9, 9, 9)); });
    ExpectCaught(g, m, "a vertex moved by 1e-7", [](Soup& s) { s.p[s.t[0][0]].y() += 1e-7; });
    ExpectCaught(g,
      m,
      "two spheres sharing a vertex (pinch)",
      [](Soup& s)
      {
        Soup o = s;
        const vtkIdType off = vtkIdType(s.p.size());
        vtkIdType pin = 0; // the vertex of largest x: the mirrored copy touches only there
        for (size_t i = 0; i < s.p.size(); ++i)
          pin = s.p[i].x() > s.p[size_t(pin)].x() ? vtkIdType(i) : pin;
        const Vec3 shift = s.p[pin] - Vec3(-s.p[pin].x(), s.p[pin].y(), s.p[pin].z());
        for (Vec3& p : o.p)
          s.p.push_back(Vec3(-p.x(), p.y(), p.z()) + shift);
        for (Tri t : o.t)
        {
          for (vtkIdType& v : t)
            v = v == pin ? pin : v + off;
          s.t.push_back({ t[1], t[0], t[2] });
        }
        s.p[size_t(pin + off)] = s.p.back(); // no unused point: the last one fills the pin's slot
        s.p.pop_back();
        for (Tri& t : s.t)
          for (vtkIdType& v : t)
            v = v == vtkIdType(s.p.size()) ? pin + off : v;
      });
  }

  section("generators at 500, 2000, 200000 faces");
  for (const Gen& g : gens)
  {
    for (int F : { 500, 2000, 200000 })
    {
      const auto t0 = std::chrono::steady_clock::now();
      const ProceduralMesh m = g.make(F);
      CheckMesh(g, m, g.name + "@" + std::to_string(F), F, Seconds(t0));
    }
  }

  section("exact planes after RandomRigidMotion + ScaleUniformly(2.5)");
  for (const Gen& g : gens)
  {
    ProceduralMesh m = g.make(2000);
    ApplyRigidMotion(m, RandomRigidMotion(3));
    ScaleUniformly(m, 2.5);
    CheckMesh(g, m, g.name + " moved", 0);
    for (size_t k = 0; k < m.planes.size(); ++k)
    {
      const PlaneMatch pm = BestPlaneMatch(m, m.planes[k].origin, m.planes[k].normal);
      EXPECT(pm.angleDegrees < 1e-9 && pm.offsetError < 1e-12,
        g.name << " moved: BestPlaneMatch of plane " << k << " gives " << pm.angleDegrees
               << " deg, " << pm.offsetError);
    }
  }

  section("different tessellation: symmetric surface, not vertex set");
  {
    const ProceduralMesh m = MakeBilateralBlobDifferentTessellation(20000);
    Soup s;
    Extract("DifferentTessellation", m.mesh, s);
    const Reflection r = ReflectVertices(m.mesh, s, m.planes[0], nullptr);
    std::vector<Vec3> q;
    for (const Vec3& p : s.p)
    {
      q.push_back(Reflect(p, m.planes[0]));
    }
    const std::vector<double> d = SurfaceDistances(s, q);
    const double diag = BoundsDiagonal(m.mesh);
    const double maxd = *std::max_element(d.begin(), d.end()) / diag;
    std::printf("  %zu faces: %.1f%% of reflected vertices on a vertex, max surface distance "
                "%.2e diag\n",
      s.t.size(),
      100 * r.matchedFraction,
      maxd);
    EXPECT(r.matchedFraction < 0.2, "DifferentTessellation: the vertex set is symmetric");
    EXPECT(maxd < 1e-3, "DifferentTessellation: reflected vertex " << maxd << " diag off surface");
  }

  section("no other symmetry (RMS reflected-vertex distance, principal planes)");
  for (const auto& named : { std::make_pair(std::string("BilateralBlob"), MakeBilateralBlob(2000)),
         std::make_pair(std::string("AsymmetricBlob"), MakeAsymmetricBlob(2000)),
         std::make_pair(std::string("AsymmetricBlob seed 2"), MakeAsymmetricBlob(2000, 2)) })
  {
    Soup s;
    Extract(named.first, named.second.mesh, s);
    for (const auto& res : PrincipalPlaneResiduals(named.second.mesh, s))
    {
      const bool isTrue = !named.second.planes.empty() &&
        PlaneAngleDegrees(res.first, named.second.planes[0].normal) < 5;
      std::printf("  %-22s normal (%6.3f %6.3f %6.3f): RMS %.4f%s\n",
        named.first.c_str(),
        res.first.x(),
        res.first.y(),
        res.first.z(),
        res.second,
        isTrue ? " (true plane)" : "");
      EXPECT(isTrue ? res.second < 2e-3 : res.second > 1e-2,
        named.first << ": principal plane residual " << res.second);
    }
  }

  section("unambiguous ground truth at epsilon = 2% of the diagonal (RegionFraction)");
  std::printf("  measured with %s\n",
    FOLDINGMESHES_TEST_HAS_CORE
      ? "FoldingMeshesCore (PrepareMesh, MirrorDistance fine, LargestConnectedRegion)"
      : "this test's implementation of the detector's fine metric (FoldingMeshesCore not linked)");
  {
    auto report = [](const std::string& name, const Competition& c)
    {
      char truth[16] = "    -";
      if (c.truth >= 0)
      {
        std::snprintf(truth, sizeof(truth), "%6.3f", c.truth);
      }
      std::printf("  %-36s true %s  other principal %.3f  random %.3f",
        name.c_str(),
        truth,
        c.principal,
        c.random);
      if (c.refined > 0)
      {
        std::printf("  refined %.3f", c.refined);
      }
      std::printf("  (%d near the true plane skipped)\n", c.skipped);
    };
    // Bilateral creatures: the true plane keeps everything, the two other principal planes and
    // 200 random planes through the centroid at least 20 degrees away keep less than half.
    const std::vector<std::pair<std::string, ProceduralMesh>> bilateral = {
      { "BilateralBlob", MakeBilateralBlob(4000) },
      { "BilateralBlob seed 3", MakeBilateralBlob(4000, 3) },
      { "DifferentTessellation", MakeBilateralBlobDifferentTessellation(4000) },
      { "DifferentTessellation seed 7", MakeBilateralBlobDifferentTessellation(4000, 7) },
    };
    for (const auto& named : bilateral)
    {
      const RegionMeasure rm(named.second.mesh);
      const Competition c = Compete(named.second, rm, { rm.Centroid() }, 200, 20, 11, false);
      report(named.first, c);
      EXPECT(c.truth > 0.97, named.first << ": true plane keeps only " << c.truth);
      EXPECT(c.principal < 0.5, named.first << ": another principal plane keeps " << c.principal);
      EXPECT(c.random < 0.5, named.first << ": a random plane keeps " << c.random);
    }
    // Asymmetric blobs: no plane keeps 40% (principal planes, 500 random planes through the
    // centroid and a local refinement of the 5 best).
    for (unsigned seed : { 1u, 13u })
    {
      const ProceduralMesh m = MakeAsymmetricBlob(4000, seed);
      const RegionMeasure rm(m.mesh);
      const Competition c = Compete(m, rm, { rm.Centroid() }, 500, 0, seed, true);
      const std::string name = "AsymmetricBlob seed " + std::to_string(seed);
      report(name, c);
      EXPECT(c.Best() < 0.4, name << ": a plane keeps " << c.Best());
    }
    // Creature with a horn: the true plane keeps the body (all but the attachment, give or take
    // 5%), and every other plane keeps less: principal planes, 200 random planes through the
    // centroid and 200 through the body's centroid, at least 10 degrees from the true plane.
    for (double a : { 0.3, 0.5 })
    {
      const ProceduralMesh m = MakeBlobWithAsymmetricPart(4000, a);
      const RegionMeasure rm(m.mesh);
      const Competition c =
        Compete(m, rm, { rm.Centroid(), rm.Centroid(m.symmetricFace) }, 200, 10, 12, false);
      const std::string name = "BlobWithAsymmetricPart(" + std::to_string(a).substr(0, 3) + ")";
      report(name, c);
      EXPECT(c.truth > 1 - a - 0.05, name << ": true plane keeps only " << c.truth);
      EXPECT(c.Best() < c.truth, name << ": another plane keeps " << c.Best() << " >= " << c.truth);
    }
    // Lumpy body with a symmetric head: the true plane keeps most of the head, every other plane
    // (principal, 200 random through the centroid, 200 through the head's centroid, at least 10
    // degrees away) keeps less.
    for (double f : { 0.2, 0.3 })
    {
      const ProceduralMesh m = MakeAsymmetricBodyWithSymmetricPart(4000, f);
      const RegionMeasure rm(m.mesh);
      const Competition c =
        Compete(m, rm, { rm.Centroid(), rm.Centroid(m.symmetricFace) }, 200, 10, 13, false);
      const std::string name =
        "AsymmetricBodyWithSymmetricPart(" + std::to_string(f).substr(0, 3) + ")";
      report(name, c);
      EXPECT(c.truth > 0.8 * f, name << ": true plane keeps only " << c.truth);
      EXPECT(c.Best() < c.truth, name << ": another plane keeps " << c.Best() << " >= " << c.truth);
    }
  }

  section("area fractions");
  for (int F : { 2000, 200000 })
  {
    for (double f : { 0.1, 0.25, 0.4, 0.6 })
    {
      const ProceduralMesh a = MakeBlobWithAsymmetricPart(F, f);
      std::vector<char> notSym(a.symmetricFace.size());
      for (size_t i = 0; i < notSym.size(); ++i)
      {
        notSym[i] = !a.symmetricFace[i];
      }
      const double fa = MaskAreaFraction(a.mesh, notSym);
      const ProceduralMesh b = MakeAsymmetricBodyWithSymmetricPart(F, f);
      const double fb = MaskAreaFraction(b.mesh, b.symmetricFace);
      std::printf("  F=%6d request %.2f: asymmetric attachment %.3f (%lld faces), symmetric part "
                  "%.3f (%lld faces)\n",
        F,
        f,
        fa,
        (long long)a.mesh->GetNumberOfCells(),
        fb,
        (long long)b.mesh->GetNumberOfCells());
      EXPECT(std::abs(fa - f) <= 0.1, "BlobWithAsymmetricPart(" << F << ", " << f << "): " << fa);
      EXPECT(std::abs(fb - f) <= 0.1,
        "AsymmetricBodyWithSymmetricPart(" << F << ", " << f << "): " << fb);
      Gen ga = gens[3], gb = gens[4];
      CheckMesh(ga, a, "  attachment " + std::to_string(f), F);
      CheckMesh(gb, b, "  symmetric part " + std::to_string(f), F);
    }
  }

  section("determinism");
  {
    const std::vector<std::function<ProceduralMesh(unsigned)>> seeded = {
      [](unsigned s) { return MakeBilateralBlob(3000, s); },
      [](unsigned s) { return MakeBilateralBlobDifferentTessellation(3000, s); },
      [](unsigned s) { return MakeBlobWithAsymmetricPart(3000, 0.3, s); },
      [](unsigned s) { return MakeAsymmetricBodyWithSymmetricPart(3000, 0.3, s); },
      [](unsigned s) { return MakeAsymmetricBlob(3000, s); },
    };
    for (size_t k = 0; k < seeded.size(); ++k)
    {
      EXPECT(SamePoints(seeded[k](5).mesh, seeded[k](5).mesh),
        "generator " << k << " not deterministic");
      EXPECT(
        !SamePoints(seeded[k](5).mesh, seeded[k](6).mesh), "generator " << k << " ignores seed");
    }
    for (const Gen& g : gens)
    {
      EXPECT(SamePoints(g.make(1000).mesh, g.make(1000).mesh), g.name << " not deterministic");
    }
    EXPECT(
      RandomRigidMotion(9).matrix() == RandomRigidMotion(9).matrix(), "motion not deterministic");
    ProceduralMesh a = MakeSphere(2000), b = MakeSphere(2000);
    AddGaussianNoise(a, 0.01, 4);
    AddGaussianNoise(b, 0.01, 4);
    EXPECT(SamePoints(a.mesh, b.mesh), "noise not deterministic");
  }

  section("transformations and measures");
  {
    const Eigen::Isometry3d T = RandomRigidMotion(11);
    EXPECT(std::abs(T.linear().determinant() - 1) < 1e-12 &&
        (T.linear().transpose() * T.linear() - Eigen::Matrix3d::Identity()).norm() < 1e-12 &&
        T.translation().cwiseAbs().maxCoeff() <= 5,
      "RandomRigidMotion is not a rotation + translation in [-5,5]^3");
    ProceduralMesh clean = MakeSphere(20000), noisy = MakeSphere(20000);
    AddGaussianNoise(noisy, 0.01, 1);
    double ss = 0;
    for (vtkIdType i = 0; i < clean.mesh->GetNumberOfPoints(); ++i)
    {
      Vec3 p, q;
      clean.mesh->GetPoint(i, p.data());
      noisy.mesh->GetPoint(i, q.data());
      ss += (q - p).squaredNorm();
    }
    const double rms = std::sqrt(ss / double(clean.mesh->GetNumberOfPoints()));
    const double want = 0.01 * BoundsDiagonal(clean.mesh);
    std::printf("  noise RMS %.5f for sigma %.5f\n", rms, want);
    EXPECT(std::abs(rms / want - 1) < 0.05, "AddGaussianNoise: RMS " << rms << " vs " << want);

    EXPECT(std::abs(PlaneAngleDegrees(Vec3(1, 0, 0), Vec3(-2, 0, 0))) < 1e-12, "angle sign");
    EXPECT(std::abs(PlaneAngleDegrees(Vec3(1, 0, 0), Vec3(0, 0, 3)) - 90) < 1e-12, "angle 90");
    EXPECT(std::abs(PlaneAngleDegrees(Vec3(1, 0, 0), Vec3(1, 1, 0)) - 45) < 1e-12, "angle 45");
    const KnownPlane truth{ Vec3(0, 0, 0), Vec3(1, 0, 0) };
    EXPECT(std::abs(PlaneOffsetError(truth, Vec3(0.3, 7, 1), Vec3(-1, 0, 0), Vec3(0, 1, 2), 3) -
             0.1) < 1e-12,
      "PlaneOffsetError");
    // sphere: any plane through the centre; cylinder: any plane containing the axis
    const ProceduralMesh sp = MakeSphere(2000), cy = MakeCylinder(2000);
    const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
    const PlaneMatch ms = BestPlaneMatch(sp, Vec3::Zero(), n);
    EXPECT(ms.index == -1 && ms.angleDegrees < 1e-9 && ms.offsetError < 1e-12, "sphere family");
    const PlaneMatch mc = BestPlaneMatch(cy, Vec3(0, 0, 0.4), Vec3(0.6, 0.8, 0));
    EXPECT(mc.index == -1 && mc.angleDegrees < 1e-9 && mc.offsetError < 1e-12, "cylinder family");
    const PlaneMatch mz = BestPlaneMatch(cy, Vec3(0, 0, 0.1), Vec3(0, 0.02, 1));
    EXPECT(mz.index == 4 && std::abs(mz.angleDegrees - 1.1457628) < 1e-6, "cylinder mid plane");
    const PlaneMatch mt = BestPlaneMatch(cy, Vec3(0, 0, 0), Vec3(0.6, 0.8, 0.1));
    EXPECT(mt.index == -1 &&
        std::abs(
          mt.angleDegrees - std::asin(0.1 / std::sqrt(1.01)) * 180 / 3.14159265358979323846) < 1e-9,
      "cylinder tilted plane " << mt.angleDegrees);
    // IoU
    const ProceduralMesh bb = MakeBilateralBlob(2000);
    const size_t nf = bb.symmetricFace.size();
    std::vector<char> left(nf, 0), right(nf, 0), all(nf, 1);
    for (size_t f = 0; f < nf; ++f)
    {
      (f < nf / 2 ? right : left)[f] = 1;
    }
    EXPECT(std::abs(RegionIoU(bb.mesh, all, bb.symmetricFace) - 1) < 1e-12, "IoU identical");
    EXPECT(RegionIoU(bb.mesh, left, right) == 0, "IoU disjoint");
    EXPECT(std::abs(RegionIoU(bb.mesh, left, all) - 0.5) < 1e-9, "IoU half (mirror halves)");
    EXPECT(RegionIoU(bb.mesh, std::vector<char>(nf, 0), std::vector<char>(nf, 0)) == 1, "IoU 0/0");
  }

  section("1M-face bilateral blob");
  {
    const auto t0 = std::chrono::steady_clock::now();
    const ProceduralMesh m = MakeBilateralBlob(1000000);
    const double dt = Seconds(t0);
    std::printf("  MakeBilateralBlob(1000000): %lld faces in %.3f s\n",
      (long long)m.mesh->GetNumberOfCells(),
      dt);
    CheckMesh(gens[0], m, "BilateralBlob@1000000", 1000000);
  }

  section("done");
  if (failures)
  {
    std::printf("TestProceduralMeshes: %d check(s) FAILED\n", failures);
    return 1;
  }
  std::printf("TestProceduralMeshes: all checks passed\n");
  return 0;
}
