// Analytic closed surfaces of the generators: the bilateral creature and the lumpy blob.
#ifndef foldingmeshes_testing_ProceduralMeshesShapes_h
#define foldingmeshes_testing_ProceduralMeshesShapes_h

#include "ProceduralMeshesInternal.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
namespace procedural
{
// Bilateral "creature", mirror plane x = 0: a long body along y with a big head and a narrowing
// snout towards +y and a thin tail curling up towards -y, a flat belly (-z), a dorsal sail (+z),
// four stubby legs, ears, eyes and random bumps, all in mirror pairs. A sphere direction d is
// read as an axial coordinate t = d.y and a unit section direction w = (d.x, d.z) / |(d.x, d.z)|;
// t maps monotonically to the spine position Y in [y0, y1] (a table that spreads the samples
// by area^0.7, so the thin tail keeps enough of them) and the point is
//   ( R(Y) a(w) m(Y, w) w.x,  Y,  zc(Y) + R(Y) (b(w) m(Y, w) w.z + crest(Y, w)) )
// with the profile R (zero at both tips), the section shape a, b (flat belly, wider below), the
// bumps m (pairs at (+-sx, sz): they depend on |w.x| only) and the sail. Every factor is even in
// w.x and the sign of x comes from w.x alone: the map commutes exactly with x -> -x and sends
// d.x = 0 exactly to x = 0.
struct Creature
{
  struct PairBump
  {
    double y, wy, sx, sz, wa, amp; // axial centre and width, section direction, width, amplitude
  };
  double y0 = -1.3, y1 = 1.15;
  // R(Y) = g(Y) sqrt((Y - y0)(y1 - Y)), g = tail + body G((Y - yb) / wb) + head G((Y - yh) / wh)
  double tail = 0.12, body = 0.30, yb = -0.15, wb = 0.45, head = 0.26, yh = 0.78, wh = 0.22;
  double tailLift = 0.35, yTail = -0.55, headLift = 0.12;
  double crestAmp = 0.18, yCrest = -0.2, wCrest = 0.5, crestWidth = 0.25;
  std::vector<PairBump> bumps;
  std::vector<double> tableT; // t at the uniform spine samples y0 + (y1 - y0) k / K
  static constexpr int K = 2048;

  double Profile(double Y) const
  {
    const double trunk = Gaussian((Y - yb) / wb) * (1 - 0.3 * std::tanh((Y - yb) / 0.3)); // pear
    const double g = tail + body * trunk + head * Gaussian((Y - yh) / wh);
    return g * std::sqrt(std::max(0.0, (Y - y0) * (y1 - Y)));
  }
  double SpineZ(double Y) const
  {
    const double s = std::max(0.0, (yTail - Y) / (yTail - y0));
    return tailLift * s * s + headLift * SmoothStep((Y - 0.35) / 0.4);
  }
  void BuildTable()
  {
    std::vector<double> W(K + 1, 0.0);
    const double dy = (y1 - y0) / K;
    double prevR = Profile(y0);
    for (int k = 0; k < K; ++k)
    {
      const double R = Profile(y0 + dy * (k + 1));
      const double len = std::sqrt(dy * dy + (R - prevR) * (R - prevR));
      W[k + 1] = W[k] + std::pow(0.5 * (R + prevR) * len / dy, 0.7) * dy;
      prevR = R;
    }
    tableT.resize(K + 1);
    for (int k = 0; k <= K; ++k)
    {
      tableT[k] = k == K ? 1.0 : -1 + 2 * W[k] / W[K];
    }
  }
  double SpineY(double t) const
  {
    const auto it = std::upper_bound(tableT.begin(), tableT.end(), t);
    const int k = std::clamp(int(it - tableT.begin()) - 1, 0, K - 1);
    const double f = std::clamp((t - tableT[k]) / (tableT[k + 1] - tableT[k]), 0.0, 1.0);
    return std::min(y1, y0 + (y1 - y0) * (k + f) / K);
  }
  double SpineT(double Y) const // inverse of SpineY
  {
    const double x = std::clamp((Y - y0) / (y1 - y0), 0.0, 1.0) * K;
    const int k = std::min(int(x), K - 1);
    return tableT[k] + (x - k) * (tableT[k + 1] - tableT[k]);
  }
  Vec3 operator()(const Vec3& d) const
  {
    const double Y = SpineY(std::clamp(d.y(), -1.0, 1.0));
    const double rho = std::sqrt(d.x() * d.x() + d.z() * d.z());
    if (rho == 0)
    {
      return { 0.0, Y, SpineZ(Y) };
    }
    const double wx = d.x() / rho, wz = d.z() / rho, ax = std::abs(wx);
    double m = 1;
    for (const PairBump& b : bumps)
    {
      const double dz2 = (wz - b.sz) * (wz - b.sz);
      double s = std::exp(-((ax - b.sx) * (ax - b.sx) + dz2) / (b.wa * b.wa));
      if (b.sx > 0)
      {
        s += std::exp(-((ax + b.sx) * (ax + b.sx) + dz2) / (b.wa * b.wa));
      }
      m += b.amp * Gaussian((Y - b.y) / b.wy) * s;
    }
    // wide and flat hips, narrower and taller shoulders, wider below, flat belly, domed back
    const double ta = 0.2 * std::tanh((Y - yb) / 0.35);
    const double a = 1.25 * (1 - ta) - 0.12 * wz;
    const double bz = (0.75 + 0.3 * std::tanh(2.5 * wz)) * (1 + ta);
    const double up = std::max(wz, 0.0);
    const double crest = crestAmp * Gaussian((Y - yCrest) / wCrest) *
      (1 + 0.8 * std::tanh((Y - yCrest) / wCrest)) * Gaussian(ax / crestWidth) * up * up;
    const double R = Profile(Y);
    return { R * a * m * wx, Y, SpineZ(Y) + R * (bz * m * wz + crest) };
  }
};

Creature CreatureShape(unsigned seed);

// Lumpy blob without any symmetry, as a radial function: an ellipsoid with random linear and
// quadratic terms, 7 big lopsided lobes (25-55% of the radius; anisotropic footprints skewed
// along an oblique direction, so not even a lobe has a mirror plane of its own) and a rough
// skin of 20 random waves (wavelength ~0.7 radius, 8% amplitude each): smooth shapes have
// large near-symmetric patches at a tolerance of 2% of the diagonal, this one has none.
struct Lumpy
{
  struct Lobe
  {
    Vec3 c, e1, e2, e3; // centre direction, footprint axes, skew direction (tangent at c)
    double a, w1, w2, skew;
  };
  Vec3 semi{ 1, 1, 1 };
  Vec3 lin = Vec3::Zero();
  Eigen::Matrix3d quad = Eigen::Matrix3d::Zero();
  std::vector<Lobe> lobes;
  std::vector<Eigen::Vector4d> waves; // direction * frequency, phase: amplitude waveAmp
  double waveAmp = 0;
  Vec3 operator()(const Vec3& d) const
  {
    double r = 1 + lin.dot(d) + d.dot(quad * d);
    for (const Eigen::Vector4d& w : waves)
    {
      r += waveAmp * std::cos(w.head<3>().dot(d) + w[3]);
    }
    for (const Lobe& L : lobes)
    {
      const Vec3 u = d - L.c;
      const double x = u.dot(L.e1) / L.w1, y = u.dot(L.e2) / L.w2, z = u.dot(L.c) / L.w1;
      r += L.a * std::exp(-(x * x + y * y + z * z)) * (1 + L.skew * std::tanh(u.dot(L.e3) / L.w1));
    }
    r = 0.25 + 0.25 * std::log1p(std::exp(4 * (r - 0.25))); // smoothly kept above 0.25
    return r * semi.cwiseProduct(d);
  }
};

Lumpy LumpyShape(unsigned seed);
} // namespace procedural
} // namespace testing
} // namespace foldingmeshes

#endif
