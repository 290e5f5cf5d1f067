// Composite generators: creature with an asymmetric horn, asymmetric body with a symmetric head.
#include "ProceduralMeshesInternal.h"
#include "ProceduralMeshesShapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
using namespace procedural;

// =================================== generators ===================================

ProceduralMesh MakeBlobWithAsymmetricPart(int approxFaces,
  double attachmentAreaFraction,
  unsigned seed)
{
  const double f = std::clamp(attachmentAreaFraction, 0.02, 0.7);
  const Creature s = CreatureShape(seed);
  TriMesh body = OctaSphere(OctaResolution(approxFaces * (1 - f)), s, true, 1);
  const size_t half = body.t.size() / 2;
  const double area = MeshArea(body), h = EdgeLength(body);
  const double rb = std::sqrt(area / (4 * kPi));
  auto g = Rng(seed, 303);
  const double dy = Uniform(g, -0.4, 0.1); // not too close to the head
  const double dz = Uniform(g, 0.3, 0.8);  // upper flank: clear of the legs
  const Vec3 P = s(Vec3(0.8, dy, dz).normalized());
  std::vector<char> allowed(body.t.size(), 0);
  for (size_t t = 0; t < half; ++t)
  {
    const Tri& T = body.t[t];
    allowed[t] = body.p[T[0]].x() > 0 && body.p[T[1]].x() > 0 && body.p[T[2]].x() > 0;
  }
  const double rho = std::max(1.5 * h, rb * std::clamp(0.25 + 0.5 * f, 0.25, 0.45));
  const Hole hole = CutHoleRobust(body, P, rho, h, allowed);
  for (size_t t = 0; t < half; ++t) // the mirror of the hole loses its partner
  {
    body.sym[t + half] = !hole.removed[t];
  }
  // The horn has no symmetry, not even locally: after a short bend its centreline winds along a
  // helix (a non-planar corkscrew: a mirror image has the other handedness), its elliptic
  // sections (axes ratio ~1.9) twist by up to 1.5 pi, it swells, tapers and carries one-sided
  // bumps. Lengths are absolute where a short horn could otherwise fold: the bend, the twist
  // rate, the ellipticity ramp and the bump widths scale with the largest section radius rmax.
  const Vec3 N = hole.normal;
  const Vec3 ey = (RandomUnit(g).cross(N)).normalized(), ex = ey.cross(N);
  Eigen::Matrix3d E;
  E << ex, ey, N;
  const double r0 = std::max(0.6 * rho, rho - h);
  const int q = std::max(2, int(std::lround(2 * kPi * r0 / (4 * h))));
  // helix of radius a and pitch p (per turn) around N: radius of curvature
  // (a^2 + (p / 2 pi)^2) / a ~ 1.1 rmax, coils 3.2 rmax apart
  const double rmax = 2 * r0; // with the ellipse and the bumps
  const double a = 0.7 * rmax * Uniform(g, 0.9, 1.1), pitch = 3.2 * rmax;
  const double tilt = std::atan(2 * kPi * a / pitch), azimuth = 2 * kPi * Uniform(g);
  const double hand = Uniform(g) < 0.5 ? -1 : 1;
  const double twistMax = (Uniform(g) < 0.5 ? -1 : 1) * Uniform(g, 1.1, 1.5) * kPi;
  std::array<Vec3, 4> bumps; // (position along the horn, section angle, amplitude)
  for (Vec3& b : bumps)
  {
    b = Vec3(Uniform(g, 0.2, 0.9), 2 * kPi * Uniform(g), Uniform(g, 0.2, 0.35));
  }
  auto radius = [=](double u)
  { return r0 * (1 - 0.45 * u) * (1 + 0.07 * std::sin(7 * u)) * (1 + 0.4 * std::sin(kPi * u)); };
  auto spec = [=](double L)
  {
    const double bend = std::min(1.0, std::max(0.15, 2.5 * rmax * tilt / L)); // in u
    const double turns = hand * 2 * kPi * L * std::cos(tilt) / pitch;         // radians
    const double twist = std::copysign(std::min(std::abs(twistMax), L / rmax), twistMax);
    const double oval = std::min(1.0, std::max(0.12, rmax / L));   // ellipticity ramp, in u
    const double bw = std::max(0.07, 0.6 * rmax / L);              // bump width, in u
    const double tiltL = std::min(tilt, bend * L / (2.25 * rmax)); // bend radius >= 1.5 rmax
    auto tangent = [=](double v)
    {
      const double th = tiltL * SmoothStep(v / bend), ph = azimuth + turns * v;
      return Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
    };
    TubeSpec t;
    t.center = [=](double u) // L * integral of the unit tangent from 0 to u (Simpson)
    {
      const int n = 16;
      Vec3 c = tangent(0) + tangent(u);
      for (int k = 1; k < n; ++k)
      {
        c += (k % 2 ? 4.0 : 2.0) * tangent(u * k / n);
      }
      return Vec3(c * (L * u / (3 * n)));
    };
    t.radii = [=](double u)
    {
      const double e = SmoothStep(u / oval);
      return Vec2(radius(u) * (1 + 0.35 * e), radius(u) * (1 - 0.3 * e));
    };
    t.section = [=](double u, const Vec2& dir)
    {
      double m = 1;
      for (const Vec3& b : bumps)
      {
        const Vec2 c(std::cos(b.y()), std::sin(b.y()));
        m += b.z() * Gaussian((u - b.x()) / bw) * std::exp(-(dir - c).squaredNorm() / 0.16);
      }
      const double e = SmoothStep(u / oval), al = twist * u;
      const Vec2 p = radius(u) * m * Vec2((1 + 0.35 * e) * dir.x(), (1 - 0.3 * e) * dir.y());
      return Vec2(
        std::cos(al) * p.x() - std::sin(al) * p.y(), std::sin(al) * p.x() + std::cos(al) * p.y());
    };
    t.quarter = q;
    t.spacing = h;
    return t;
  };
  const double L0 = (f * area / (1 - f)) / (2 * kPi * 0.7 * r0);
  const Vec3 origin = hole.center + (h + LoopLift(body, hole) + 0.3 * rho) * N;
  E = ClearestFrame(body, E, spec(L0), origin, L0, 2 * rmax);
  const TriMesh m = WeldToFraction(body, hole, spec, origin, E, 0, 0, f, L0);
  return Finish(m, { kPlaneX });
}

ProceduralMesh MakeAsymmetricBodyWithSymmetricPart(int approxFaces,
  double symmetricAreaFraction,
  unsigned seed)
{
  const double f = std::clamp(symmetricAreaFraction, 0.02, 0.6);
  const Lumpy s = LumpyShape(seed);
  const TriMesh body = OctaSphere(OctaResolution(approxFaces * (1 - f)), s, false, 0);
  const double area = MeshArea(body), h = EdgeLength(body);
  const double rb = std::sqrt(area / (4 * kPi));
  auto g = Rng(seed, 404);
  const double rho = std::max(1.5 * h, rb * std::clamp(0.22 + 0.5 * f, 0.22, 0.45));
  // The attachment point and the part's plane. The body near the part must not look symmetric
  // about that plane (else the part's symmetric region runs on into the body and planes a few
  // degrees off gain more of it than they lose): of 12 random surface points with an open view
  // along their normal (no crevice between lumps), the one whose surroundings (within 3 hole
  // radii) have the fewest points mirroring radially within 2% of the body's size onto the
  // surface, for the best of 8 planes containing the normal.
  std::vector<Vec3> sample(1500);
  double lo = 1e300, hi = -1e300;
  for (Vec3& x : sample)
  {
    x = s(RandomUnit(g));
    lo = std::min(lo, x.minCoeff());
    hi = std::max(hi, x.maxCoeff());
  }
  const double tol = 0.02 * std::sqrt(3.0) * (hi - lo);
  auto normalAt = [&](const Vec3& d)
  {
    const Vec3 t1 = d.unitOrthogonal(), t2 = d.cross(t1);
    const Vec3 n = (s((d + 1e-4 * t1).normalized()) - s((d - 1e-4 * t1).normalized()))
                     .cross(s((d + 1e-4 * t2).normalized()) - s((d - 1e-4 * t2).normalized()))
                     .normalized();
    return n.dot(d) > 0 ? n : Vec3(-n);
  };
  // local samples around the direction d, and how many mirror onto the surface about the plane
  // through Q with normal m
  auto localSamples = [&](const Vec3& d, double radius)
  {
    const Vec3 t1 = d.unitOrthogonal(), t2 = d.cross(t1);
    std::vector<Vec3> out;
    for (int i = -10; i <= 10; ++i)
    {
      for (int j = -10; j <= 10; ++j)
      {
        if (i * i + j * j <= 100)
        {
          out.push_back(s((d + radius * (i * t1 + j * t2) / 10).normalized()));
        }
      }
    }
    return out;
  };
  auto mirrored = [&](const std::vector<Vec3>& pts, const Vec3& Q, const Vec3& m)
  {
    int n = 0;
    for (const Vec3& x : pts)
    {
      const Vec3 y = x - 2 * m.dot(x - Q) * m;
      n += std::abs(y.norm() - s(y.normalized()).norm()) < tol;
    }
    return double(n) / double(pts.size());
  };
  Vec3 P = Vec3::Zero(), Pdir = Vec3::UnitX();
  double bestScore = 1e300;
  for (int k = 0; k < 12; ++k)
  {
    const Vec3 d = RandomUnit(g), Q = s(d), out = normalAt(d);
    double elevation = -1;
    for (const Vec3& x : sample)
    {
      const double r = (x - Q).norm();
      elevation = r > 1.5 * rho ? std::max(elevation, (x - Q).dot(out) / r) : elevation;
    }
    const std::vector<Vec3> near = localSamples(d, 3 * rho / Q.norm());
    const Vec3 e1 = out.unitOrthogonal(), e2 = out.cross(e1);
    double sym = 1;
    for (int j = 0; j < 8; ++j)
    {
      const double b = kPi * j / 8;
      sym = std::min(sym, mirrored(near, Q, std::cos(b) * e1 + std::sin(b) * e2));
    }
    const double score = sym + (elevation > 0.0 ? 10 + elevation : 0.0);
    if (score < bestScore)
    {
      bestScore = score;
      P = Q;
      Pdir = d;
    }
  }
  const Hole hole = CutHoleRobust(body, P, rho, h, std::vector<char>(body.t.size(), 1));
  // A "head on a short neck" with one mirror plane, local x = 0: a short neck flaring into a
  // head three times as wide, closed by a half-ellipsoid dome, bent towards local +y. Its
  // sections are flattened and egg-shaped (fuller towards -y) with a high crest on the -y side
  // and a pair of eyes. Fat, so a plane through its axis other than x = 0 misses the crest,
  // and flaring, so no plane across it maps it onto itself (a tube of constant width would
  // look symmetric about both at a tolerance of 2% of the diagonal).
  const Vec3 N = hole.normal;
  const Vec3 ey = (RandomUnit(g).cross(N)).normalized(), ex = ey.cross(N);
  Eigen::Matrix3d E;
  E << ex, ey, N;
  const double r0 = std::max(0.6 * rho, rho - h);
  const int q = std::max(2, int(std::lround(2 * kPi * r0 / (4 * h))));
  // the head's radius: at most that of a half-sphere of the part's whole area (small parts)
  const double head = std::min(2.85 * r0, std::sqrt(f * area / (1 - f) / (2 * kPi)));
  auto radius = [=](double u) { return 0.85 * r0 + (head - 0.85 * r0) * std::pow(u, 1.3); };
  // sections: odd in dir.x along X and even along Y, so exactly symmetric about local x = 0
  auto symmetric = [=](double u, const Vec2& dir)
  {
    const double ax = std::abs(dir.x()), down = std::max(-dir.y(), 0.0);
    const double e2 = (dir.y() - 0.6) * (dir.y() - 0.6);
    const double eyes = 0.25 * Gaussian((u - 0.8) / 0.07) *
      (std::exp(-((ax - 0.8) * (ax - 0.8) + e2) / 0.12) +
        std::exp(-((ax + 0.8) * (ax + 0.8) + e2) / 0.12));
    const double crest = 0.8 * Gaussian((u - 0.6) / 0.3) * Gaussian(ax / 0.35) * down * down;
    const double R = radius(u), m = 1 + eyes;
    return Vec2(R * m * dir.x(), R * (0.6 * m * dir.y() * (1 - 0.4 * dir.y()) - crest));
  };
  auto spec = [=](double L)
  {
    const double bend = std::min(0.6, L / (9.5 * r0)); // radius of curvature >= 1.5 head radii
    TubeSpec t;
    t.center = [=](double u) { return Vec3(0, bend * L * u * u, L * u); };
    t.radii = [=](double u) { return Vec2(radius(u), 0.6 * radius(u)); };
    t.section = symmetric;
    t.quarter = q;
    t.spacing = h;
    t.symmetricDiagonals = true;
    return t;
  };
  const Vec3 origin = hole.center + (h + LoopLift(body, hole) + 0.3 * rho) * N;
  const double L0 = (f * area / (1 - f)) / (2 * kPi * 2 * r0);
  // of the orientations that clear the body, the one about whose plane the body around the
  // part looks least symmetric
  const std::vector<Vec3> near = localSamples(Pdir, 3 * rho / P.norm());
  auto bodySymmetry = [&](const Eigen::Matrix3d& R) { return mirrored(near, origin, R.col(0)); };
  E = ClearestFrame(body, E, spec(L0), origin, L0, 2 * r0, bodySymmetry, h);
  const TriMesh m = WeldToFraction(body, hole, spec, origin, E, 1, 1, f, L0);
  return Finish(m, { KnownPlane{ origin, E.col(0) } });
}
} // namespace testing
} // namespace foldingmeshes
