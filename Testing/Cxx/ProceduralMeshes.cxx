#include "ProceduralMeshes.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPoints.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <unordered_map>

namespace foldingmeshes
{
namespace testing
{
namespace
{
using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
using Id = vtkIdType;
using Tri = std::array<Id, 3>;
constexpr double kPi = 3.14159265358979323846;

struct TriMesh
{
  std::vector<Vec3> p;
  std::vector<Tri> t;
  std::vector<char> sym; // per triangle
  Id Add(const Vec3& x)
  {
    p.push_back(x);
    return Id(p.size()) - 1;
  }
  void Face(Id a, Id b, Id c, char s)
  {
    t.push_back({ a, b, c });
    sym.push_back(s);
  }
  void Append(const TriMesh& o)
  {
    const Id off = Id(p.size());
    p.insert(p.end(), o.p.begin(), o.p.end());
    for (const Tri& f : o.t)
    {
      t.push_back({ f[0] + off, f[1] + off, f[2] + off });
    }
    sym.insert(sym.end(), o.sym.begin(), o.sym.end());
  }
  double Area(size_t f) const
  {
    return 0.5 * (p[t[f][1]] - p[t[f][0]]).cross(p[t[f][2]] - p[t[f][0]]).norm();
  }
};

// ---- deterministic random numbers (std distributions are implementation-defined) ----
std::mt19937 Rng(unsigned seed, unsigned salt)
{
  std::seed_seq s{ seed, salt };
  return std::mt19937(s);
}
double Uniform(std::mt19937& g)
{
  return (double(g()) + 0.5) / 4294967296.0;
}
double Uniform(std::mt19937& g, double a, double b)
{
  return a + (b - a) * Uniform(g);
}
double Gauss(std::mt19937& g)
{
  const double u = Uniform(g);
  const double v = Uniform(g);
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * kPi * v);
}
Vec3 RandomUnit(std::mt19937& g)
{
  const double z = Uniform(g, -1, 1);
  const double a = 2 * kPi * Uniform(g);
  const double s = std::sqrt(1 - z * z);
  return { s * std::cos(a), s * std::sin(a), z };
}
Vec3 MirrorX(const Vec3& v)
{
  return { -v.x(), v.y(), v.z() };
}

// ---- analytic closed surfaces: unit directions d -> points ----
double Gaussian(double x)
{
  return std::exp(-x * x);
}
double SmoothStep(double x)
{
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

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

Creature CreatureShape(unsigned seed)
{
  auto g = Rng(seed, 101);
  Creature s;
  s.body = Uniform(g, 0.28, 0.33);
  s.head = Uniform(g, 0.24, 0.29);
  s.yh = Uniform(g, 0.74, 0.82);
  s.tailLift = Uniform(g, 0.25, 0.45);
  s.headLift = Uniform(g, 0.08, 0.16);
  s.crestAmp = Uniform(g, 0.15, 0.21);
  s.yCrest = Uniform(g, -0.35, 0.0);
  const double leg = Uniform(g, 0.48, 0.62);
  s.bumps.push_back({ Uniform(g, -0.6, -0.45), 0.2, 0.75, -0.66, 0.5, leg });       // hind legs
  s.bumps.push_back({ Uniform(g, 0.1, 0.22), 0.17, 0.75, -0.66, 0.45, 0.6 * leg }); // fore legs
  s.bumps.push_back({ s.yh - 0.08, 0.12, 0.5, 0.85, 0.4, Uniform(g, 0.25, 0.32) }); // ears
  s.bumps.push_back({ s.yh + 0.06, 0.07, 0.78, 0.5, 0.3, Uniform(g, 0.15, 0.22) }); // eyes
  for (int k = 0; k < 5; ++k) // irregular flank bumps
  {
    const double psi = Uniform(g, 0.35, 2.6);
    s.bumps.push_back({ Uniform(g, -0.9, 0.6),
      Uniform(g, 0.08, 0.18),
      std::sin(psi),
      std::cos(psi),
      Uniform(g, 0.3, 0.5),
      Uniform(g, 0.15, 0.3) });
  }
  s.bumps.push_back({ Uniform(g, -0.9, -0.7), 0.1, 0.0, 1.0, 0.4, 0.25 }); // a hump on the tail
  s.BuildTable();
  return s;
}

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

Lumpy LumpyShape(unsigned seed)
{
  auto g = Rng(seed, 202);
  Lumpy s;
  s.semi = { Uniform(g, 0.95, 1.1), Uniform(g, 0.85, 1.0), Uniform(g, 0.8, 0.95) };
  s.lin = 0.1 * RandomUnit(g);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = i; j < 3; ++j)
    {
      s.quad(i, j) = s.quad(j, i) = Uniform(g, -0.1, 0.1);
    }
  }
  s.waveAmp = 0.08;
  for (int k = 0; k < 20; ++k)
  {
    const Vec3 v = RandomUnit(g) * Uniform(g, 7.0, 11.0);
    s.waves.push_back(Eigen::Vector4d(v.x(), v.y(), v.z(), 2 * kPi * Uniform(g)));
  }
  for (int k = 0; k < 7; ++k)
  {
    Lumpy::Lobe L;
    L.c = RandomUnit(g);
    L.e1 = RandomUnit(g).cross(L.c).normalized();
    L.e2 = L.c.cross(L.e1);
    const double gamma = Uniform(g, 0.3, 1.2);
    L.e3 = std::cos(gamma) * L.e1 + std::sin(gamma) * L.e2;
    L.a = Uniform(g, 0.3, 0.55);
    L.w1 = Uniform(g, 0.3, 0.45);
    L.w2 = L.w1 * Uniform(g, 0.5, 1.0);
    L.skew = (Uniform(g) < 0.5 ? -1 : 1) * Uniform(g, 0.4, 0.8);
    s.lobes.push_back(L);
  }
  return s;
}

// ---- equal-area octahedral grid of the hemisphere x >= 0 ----
// Lattice point (i, j) of the diamond |i| + |j| <= n onto the unit hemisphere x >= 0; the seam
// |i| + |j| = n lands exactly on x = 0 and the map is exactly odd in i and in j.
Vec3 HemiDir(int i, int j, int n)
{
  const int s = std::abs(i) + std::abs(j);
  if (s == 0)
  {
    return { 1, 0, 0 };
  }
  const double d = double(s) / n;
  const double phi = 0.5 * kPi * std::abs(j) / s;
  const double sn = d * std::sqrt(2 - d * d);
  return { s == n ? 0.0 : 1 - d * d,
    i == 0 ? 0.0 : std::copysign(sn * std::cos(phi), double(i)),
    j == 0 ? 0.0 : std::copysign(sn * std::sin(phi), double(j)) };
}

struct Diamond // vertex ids of the lattice |i| + |j| <= R
{
  int R;
  std::vector<Id> id;
  explicit Diamond(int r)
    : R(r)
    , id(size_t(2 * r + 1) * (2 * r + 1), -1)
  {
  }
  Id& operator()(int i, int j) { return id[size_t(i + R) * (2 * R + 1) + (j + R)]; }
};

// Triangles of the diamond lattice, counter-clockwise in (i, j), invariant under i->-i, j->-j.
template <class Emit>
void DiamondTriangles(int R, Emit emit)
{
  for (int sy : { 1, -1 })
  {
    for (int sz : { 1, -1 })
    {
      auto put = [&](int a0, int b0, int a1, int b1, int a2, int b2)
      {
        if (sy * sz > 0)
        {
          emit(sy * a0, sz * b0, sy * a1, sz * b1, sy * a2, sz * b2);
        }
        else
        {
          emit(sy * a0, sz * b0, sy * a2, sz * b2, sy * a1, sz * b1);
        }
      };
      for (int a = 0; a < R; ++a)
      {
        for (int b = 0; a + b < R; ++b)
        {
          put(a, b, a + 1, b, a, b + 1);
          if (a + b + 2 <= R)
          {
            put(a + 1, b, a + 1, b + 1, a, b + 1);
          }
        }
      }
    }
  }
}

// The ring |i| + |j| = R, counter-clockwise from (R, 0).
std::vector<std::array<int, 2>> DiamondRing(int R)
{
  std::vector<std::array<int, 2>> r;
  for (int t = 0; t < 4 * R; ++t)
  {
    const int q = t / R, s = t % R;
    const std::array<int, 2> v[4] = { { R - s, s }, { -s, R - s }, { s - R, -s }, { s, s - R } };
    r.push_back(v[q]);
  }
  return r;
}

// Zipper strip between an inner loop and an outer loop (same rotational sense, parameters in
// [0, 1) increasing from 0). Triangles use the inner edges backwards and the outer edges forwards:
// counter-clockwise when both loops are counter-clockwise around the inner one. A one-vertex
// inner loop gives a fan.
template <class Emit>
void Zip(const std::vector<Id>& in,
  const std::vector<double>& tin,
  const std::vector<Id>& out,
  const std::vector<double>& tout,
  Emit emit)
{
  const size_t ni = in.size(), no = out.size(), iend = ni == 1 ? 0 : ni;
  size_t i = 0, k = 0;
  while (i < iend || k < no)
  {
    const double nexti = i + 1 < ni ? tin[i + 1] : 1.0;
    const double nexto = k + 1 < no ? tout[k + 1] : 1.0;
    if (i >= iend || (k < no && nexto <= nexti))
    {
      emit(in[i % ni], out[k % no], out[(k + 1) % no]);
      ++k;
    }
    else
    {
      emit(in[i % ni], out[k % no], in[(i + 1) % ni]);
      ++i;
    }
  }
}

std::vector<double> UniformParams(size_t n)
{
  std::vector<double> t(n);
  for (size_t k = 0; k < n; ++k)
  {
    t[k] = double(k) / double(n);
  }
  return t;
}

std::vector<double> ArcParams(const TriMesh& m, const std::vector<Id>& loop)
{
  std::vector<double> t(loop.size(), 0.0);
  double len = 0;
  for (size_t k = 0; k < loop.size(); ++k)
  {
    t[k] = len;
    len += (m.p[loop[(k + 1) % loop.size()]] - m.p[loop[k]]).norm();
  }
  for (double& x : t)
  {
    x /= len;
  }
  return t;
}

// Closed sphere-like mesh on the octahedral grid of resolution n: the half x >= 0 is
// shape(HemiDir); the half x < 0 either mirrors its vertices (exact symmetry) or evaluates `shape`
// at the mirrored directions. Faces [0, F/2) are the half x >= 0, face i + F/2 mirrors face i.
TriMesh OctaSphere(int n, const std::function<Vec3(const Vec3&)>& shape, bool mirror, char sym)
{
  TriMesh m;
  Diamond D(n);
  for (int i = -n; i <= n; ++i)
  {
    for (int j = std::abs(i) - n; j <= n - std::abs(i); ++j)
    {
      D(i, j) = m.Add(shape(HemiDir(i, j, n)));
    }
  }
  DiamondTriangles(n,
    [&](int i0, int j0, int i1, int j1, int i2, int j2)
    { m.Face(D(i0, j0), D(i1, j1), D(i2, j2), sym); });
  std::vector<Id> mir(m.p.size());
  for (int i = -n; i <= n; ++i)
  {
    for (int j = std::abs(i) - n; j <= n - std::abs(i); ++j)
    {
      const Id v = D(i, j);
      const Vec3 q = mirror ? MirrorX(m.p[v]) : shape(MirrorX(HemiDir(i, j, n)));
      mir[v] = std::abs(i) + std::abs(j) == n ? v : m.Add(q);
    }
  }
  const size_t nt = m.t.size();
  for (size_t f = 0; f < nt; ++f)
  {
    const Tri t = m.t[f];
    m.Face(mir[t[1]], mir[t[0]], mir[t[2]], sym);
  }
  return m;
}

// As OctaSphere(n, shape, false) but the half x < 0 uses the finer lattice of resolution m > n
// (vertices |i| + |j| <= m - 1), zipped to the seam of the half x >= 0.
TriMesh OctaSphereTwoResolutions(int n, int m, const std::function<Vec3(const Vec3&)>& shape)
{
  TriMesh M;
  Diamond A(n), B(m - 1);
  for (int i = -n; i <= n; ++i)
  {
    for (int j = std::abs(i) - n; j <= n - std::abs(i); ++j)
    {
      A(i, j) = M.Add(shape(HemiDir(i, j, n)));
    }
  }
  DiamondTriangles(n,
    [&](int i0, int j0, int i1, int j1, int i2, int j2)
    { M.Face(A(i0, j0), A(i1, j1), A(i2, j2), 1); });
  const int r = m - 1;
  for (int i = -r; i <= r; ++i)
  {
    for (int j = std::abs(i) - r; j <= r - std::abs(i); ++j)
    {
      B(i, j) = M.Add(shape(MirrorX(HemiDir(i, j, m))));
    }
  }
  const size_t firstB = M.t.size();
  DiamondTriangles(r,
    [&](int i0, int j0, int i1, int j1, int i2, int j2)
    { M.Face(B(i0, j0), B(i1, j1), B(i2, j2), 1); });
  std::vector<Id> inner, outer;
  for (const auto& ij : DiamondRing(r))
  {
    inner.push_back(B(ij[0], ij[1]));
  }
  for (const auto& ij : DiamondRing(n))
  {
    outer.push_back(A(ij[0], ij[1]));
  }
  Zip(inner,
    UniformParams(inner.size()),
    outer,
    UniformParams(outer.size()),
    [&](Id a, Id b, Id c) { M.Face(a, b, c, 1); });
  for (size_t f = firstB; f < M.t.size(); ++f) // built as a half x >= 0: flip for x < 0
  {
    std::swap(M.t[f][0], M.t[f][1]);
  }
  return M;
}

// The 4q unit vectors at angles 2 pi k / 4q, exactly invariant under x->-x, y->-y and x<->y.
std::vector<Vec2> RingTable(int q)
{
  std::vector<double> c(q + 1);
  for (int k = 0; k <= q; ++k)
  {
    c[k] = k == q ? 0.0 : std::cos(0.5 * kPi * k / q);
  }
  std::vector<Vec2> r(4 * q);
  for (int k = 0; k < q; ++k)
  {
    r[k] = { c[k], c[q - k] };
    r[q + k] = { -c[q - k], c[k] };
    r[2 * q + k] = { -c[k], -c[q - k] };
    r[3 * q + k] = { c[q - k], -c[k] };
  }
  return r;
}

// ---- tubes (horns, necks) in a local frame: centreline from 0, leaving along +z ----
struct TubeSpec
{
  std::function<Vec3(double)> center; // local centreline, t in [0, 1], c(0) = 0, c'(0) along +z
  std::function<Vec2(double)> radii;  // section semi-axes along the section's X and Y axes
  // Optional general section: the offset (along X, Y) of the ring point of unit direction dir
  // (a RingTable entry) at t; replaces (radii.x dir.x, radii.y dir.y). radii(1) still sets the
  // length of the end cap.
  std::function<Vec2(double, const Vec2&)> section;
  int quarter = 2;                 // 4 * quarter vertices per ring
  double spacing = 0.1;            // target edge length
  bool symmetricDiagonals = false; // triangulate mirror-symmetrically about local x = 0
};

// Builds the tube (open at t = 0, closed by a half-ellipsoid cap and a tip vertex) in world
// coordinates o + E * local. The section frame (X, Y) is parallel-transported along the
// centreline from X = local x at t = 0 (so a centreline in the plane x = 0 keeps X = (1, 0, 0)
// exactly, and a section offset odd in x along X and even along Y gives a tube exactly
// symmetric about local x = 0). Returns the mesh; ring0 receives the ids of the first ring,
// whose edges the tube uses as ring0[k+1] -> ring0[k].
TriMesh BuildTube(const TubeSpec& s,
  const Vec3& o,
  const Eigen::Matrix3d& E,
  char sym,
  std::vector<Id>& ring0)
{
  double len = 0;
  for (int k = 0; k < 64; ++k)
  {
    len += (s.center((k + 1) / 64.0) - s.center(k / 64.0)).norm();
  }
  const int rings = std::max(2, int(std::ceil(len / s.spacing)));
  struct Section
  {
    Vec3 c, X, Y;
    double t, scale;
  };
  std::vector<Section> sec;
  Vec3 X = Vec3::UnitX(), T = Vec3::UnitZ();
  auto transport = [&](double t)
  {
    const double dt = 1e-5, t0 = std::max(0.0, t - dt), t1 = std::min(1.0, t + dt);
    T = (s.center(t1) - s.center(t0)).normalized();
    X = (X - X.dot(T) * T).normalized();
  };
  for (int j = 0; j <= rings; ++j)
  {
    const double t = double(j) / rings;
    transport(t);
    sec.push_back({ s.center(t), X, T.cross(X), t, 1.0 });
  }
  const Vec3 c1 = s.center(1.0), T1 = T, X1 = X;
  const double capLen = s.radii(1.0).minCoeff();
  const int capRings = std::max(1, int(std::lround(0.5 * kPi * capLen / s.spacing)) - 1);
  for (int i = 1; i <= capRings; ++i)
  {
    const double th = 0.5 * kPi * i / (capRings + 1);
    sec.push_back({ c1 + capLen * std::sin(th) * T1, X1, T1.cross(X1), 1.0, std::cos(th) });
  }
  const std::vector<Vec2> table = RingTable(s.quarter);
  const size_t M = table.size();
  TriMesh m;
  std::vector<std::vector<Id>> ring(sec.size());
  for (size_t j = 0; j < sec.size(); ++j)
  {
    const Section& S = sec[j];
    const Vec2 r = s.radii(S.t);
    for (size_t k = 0; k < M; ++k)
    {
      const Vec2 off =
        s.section ? s.section(S.t, table[k]) : Vec2(r.x() * table[k].x(), r.y() * table[k].y());
      const Vec3 local = S.c + (S.scale * off.x()) * S.X + (S.scale * off.y()) * S.Y;
      ring[j].push_back(m.Add(o + E * local));
    }
  }
  const Id tip = m.Add(o + E * (c1 + capLen * T1));
  for (size_t j = 0; j + 1 < sec.size(); ++j)
  {
    const auto& R = ring[j];
    const auto& Q = ring[j + 1];
    for (size_t k = 0; k < M; ++k)
    {
      const size_t k1 = (k + 1) % M;
      if (!s.symmetricDiagonals || table[k].x() + table[k1].x() > 0)
      {
        m.Face(R[k1], R[k], Q[k], sym);
        m.Face(R[k1], Q[k], Q[k1], sym);
      }
      else
      {
        m.Face(R[k1], R[k], Q[k1], sym);
        m.Face(R[k], Q[k], Q[k1], sym);
      }
    }
  }
  for (size_t k = 0; k < M; ++k)
  {
    m.Face(ring.back()[(k + 1) % M], ring.back()[k], tip, sym);
  }
  ring0 = ring[0];
  return m;
}

// ---- cutting a disc-shaped hole and welding a tube into it ----
struct Hole
{
  std::vector<char> removed; // per face
  std::vector<Id> loop;      // boundary, in the direction of the kept faces' edges
  Vec3 normal, center;       // mean normal of the removed faces, centroid of the loop
};

uint64_t EdgeKey(Id a, Id b)
{
  return (uint64_t(a) << 32) | uint64_t(b);
}

// Removes the faces around P (connected to the face nearest P, centroid within rho, allowed),
// fills notches, and checks that the boundary is one simple loop.
bool CutHole(const TriMesh& m,
  const Vec3& P,
  double rho,
  double h,
  const std::vector<char>& allowed,
  Hole& hole)
{
  const size_t nf = m.t.size();
  std::vector<Vec3> cen(nf);
  std::unordered_map<uint64_t, size_t> half; // directed edge -> face, for faces near P
  std::vector<size_t> cand;
  for (size_t f = 0; f < nf; ++f)
  {
    cen[f] = (m.p[m.t[f][0]] + m.p[m.t[f][1]] + m.p[m.t[f][2]]) / 3;
    if ((cen[f] - P).norm() < rho + 3 * h)
    {
      cand.push_back(f);
      for (int e = 0; e < 3; ++e)
      {
        half[EdgeKey(m.t[f][e], m.t[f][(e + 1) % 3])] = f;
      }
    }
  }
  auto twin = [&](size_t f, int e) -> long
  {
    auto it = half.find(EdgeKey(m.t[f][(e + 1) % 3], m.t[f][e]));
    return it == half.end() ? -1 : long(it->second);
  };
  long seed = -1;
  for (size_t f : cand)
  {
    if (allowed[f] && (seed < 0 || (cen[f] - P).norm() < (cen[seed] - P).norm()))
    {
      seed = long(f);
    }
  }
  if (seed < 0)
  {
    return false;
  }
  std::vector<char>& rem = hole.removed;
  rem.assign(nf, 0);
  rem[seed] = 1;
  std::vector<size_t> stack{ size_t(seed) };
  while (!stack.empty())
  {
    const size_t f = stack.back();
    stack.pop_back();
    for (int e = 0; e < 3; ++e)
    {
      const long g = twin(f, e);
      if (g >= 0 && !rem[g] && allowed[g] && (cen[g] - P).norm() < rho)
      {
        rem[g] = 1;
        stack.push_back(size_t(g));
      }
    }
  }
  // fill notches: kept faces with 2+ edges on the hole, or (smoother loops) with an edge on the
  // hole and the third vertex on it too
  for (bool changed = true; changed;)
  {
    changed = false;
    std::unordered_map<Id, char> onHole;
    for (size_t f : cand)
    {
      for (int e = 0; rem[f] && e < 3; ++e)
      {
        onHole[m.t[f][e]] = 1;
      }
    }
    for (size_t f : cand)
    {
      int n = 0, v = 0;
      for (int e = 0; e < 3; ++e)
      {
        const long g = twin(f, e);
        n += g >= 0 && rem[g];
        v += onHole.count(m.t[f][e]) > 0;
      }
      if (!rem[f] && allowed[f] && (n >= 2 || (n == 1 && v == 3)))
      {
        rem[f] = changed = true;
      }
    }
  }
  std::unordered_map<Id, Id> next;
  for (size_t f : cand)
  {
    for (int e = 0; e < 3; ++e)
    {
      const long g = twin(f, e);
      if (!rem[f] && g >= 0 && rem[g] && !next.emplace(m.t[f][e], m.t[f][(e + 1) % 3]).second)
      {
        return false; // pinch
      }
    }
  }
  if (next.size() < 3)
  {
    return false;
  }
  hole.loop.clear();
  Id v = next.begin()->first;
  do
  {
    hole.loop.push_back(v);
    auto it = next.find(v);
    if (it == next.end() || hole.loop.size() > next.size())
    {
      return false;
    }
    v = it->second;
  } while (v != hole.loop.front());
  if (hole.loop.size() != next.size())
  {
    return false; // several loops
  }
  hole.normal.setZero();
  hole.center.setZero();
  for (size_t f = 0; f < nf; ++f)
  {
    if (rem[f])
    {
      hole.normal += (m.p[m.t[f][1]] - m.p[m.t[f][0]]).cross(m.p[m.t[f][2]] - m.p[m.t[f][0]]);
    }
  }
  hole.normal.normalize();
  for (Id u : hole.loop)
  {
    hole.center += m.p[u];
  }
  hole.center /= double(hole.loop.size());
  {
    // the normal of the loop's least-squares plane (oriented as the removed faces): the loop
    // then winds around it as evenly as it can
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (Id u : hole.loop)
    {
      C += (m.p[u] - hole.center) * (m.p[u] - hole.center).transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
    const Vec3 fit = es.eigenvectors().col(0);
    hole.normal = fit.dot(hole.normal) < 0 ? Vec3(-fit) : fit;
  }
  return true;
}

// Tries radii around rho until the hole is a clean disc.
Hole CutHoleRobust(const TriMesh& m,
  const Vec3& P,
  double rho,
  double h,
  const std::vector<char>& allowed)
{
  Hole hole;
  for (int k = 0; k < 24; ++k)
  {
    const double f = 1 + 0.04 * ((k + 1) / 2) * (k % 2 ? -1 : 1);
    if (CutHole(m, P, rho * f, h, allowed, hole))
    {
      return hole;
    }
  }
  throw std::runtime_error("ProceduralMeshes: could not cut a disc-shaped hole");
}

double LoopSense(const TriMesh& m, const std::vector<Id>& loop, const Vec3& c, const Vec3& n)
{
  double s = 0;
  for (size_t k = 0; k < loop.size(); ++k)
  {
    s += (m.p[loop[k]] - c).cross(m.p[loop[(k + 1) % loop.size()]] - c).dot(n);
  }
  return s;
}

// body minus the hole + tube + collar (marked 0) joining the hole loop to the tube's first ring;
// unused vertices removed.
TriMesh Weld(const TriMesh& body, const Hole& hole, TriMesh tube, std::vector<Id> ring0)
{
  TriMesh out;
  out.p = body.p;
  for (size_t f = 0; f < body.t.size(); ++f)
  {
    if (!hole.removed[f])
    {
      out.t.push_back(body.t[f]);
      out.sym.push_back(body.sym[f]);
    }
  }
  const Id off = Id(out.p.size());
  for (Id& v : ring0)
  {
    v += off;
  }
  out.Append(tube);
  const Vec3 n = hole.normal, c = hole.center;
  if ((LoopSense(out, hole.loop, c, n) > 0) != (LoopSense(out, ring0, c, n) > 0))
  {
    std::reverse(ring0.begin() + 1, ring0.end()); // same sense as the loop: flip the tube
    for (size_t f = out.t.size() - tube.t.size(); f < out.t.size(); ++f)
    {
      std::swap(out.t[f][0], out.t[f][1]);
    }
  }
  auto flat = [&](Id v)
  {
    const Vec3 d = out.p[v] - c;
    return Vec3(d - d.dot(n) * n).normalized();
  };
  std::vector<Id> loop = hole.loop;
  size_t start = 0;
  for (size_t k = 1; k < loop.size(); ++k)
  {
    if (flat(loop[k]).dot(flat(ring0[0])) > flat(loop[start]).dot(flat(ring0[0])))
    {
      start = k;
    }
  }
  std::rotate(loop.begin(), loop.begin() + long(start), loop.end());
  // Pair the two loops by the angle around the normal when both wind monotonically around it
  // (no crossing collar triangles on a wiggly hole), else by arc length.
  const Vec3 e0 = flat(ring0[0]), e1 = n.cross(e0);
  auto angles = [&](const std::vector<Id>& l, std::vector<double>& t)
  {
    t.assign(l.size(), 0.0);
    const double sense = LoopSense(out, l, c, n) > 0 ? 1 : -1;
    double prev = 0;
    for (size_t k = 0; k < l.size(); ++k)
    {
      const Vec3 d = flat(l[k]);
      double a = sense * std::atan2(d.dot(e1), d.dot(e0));
      while (a < prev - kPi)
      {
        a += 2 * kPi;
      }
      while (a > prev + kPi)
      {
        a -= 2 * kPi;
      }
      prev = a;
      t[k] = k > 0 ? std::max(t[k - 1], a) : a; // monotone envelope of the winding angle
    }
    const double a0 = t[0];
    for (double& x : t)
    {
      x = (x - a0) / (2 * kPi);
    }
    const Vec3 d0 = flat(l[0]), dn = flat(l.back()); // the loop winds once around c
    const double last = sense * std::atan2(d0.cross(dn).dot(n), d0.dot(dn));
    return t.size() > 2 && t.back() < 1 && std::abs(prev - a0 - (2 * kPi + last)) < 1e-6;
  };
  std::vector<double> tl, tr;
  if (!(angles(loop, tl) && angles(ring0, tr)))
  {
    tl = ArcParams(out, loop);
    tr = ArcParams(out, ring0);
  }
  Zip(loop, tl, ring0, tr, [&](Id a, Id b, Id d) { out.Face(a, b, d, 0); });
  std::vector<Id> map(out.p.size(), -1);
  TriMesh packed;
  for (size_t f = 0; f < out.t.size(); ++f)
  {
    Tri t = out.t[f];
    for (Id& v : t)
    {
      if (map[v] < 0)
      {
        map[v] = packed.Add(out.p[v]);
      }
      v = map[v];
    }
    packed.Face(t[0], t[1], t[2], out.sym[f]);
  }
  return packed;
}

double MeshArea(const TriMesh& m, int onlySym = -1)
{
  double a = 0;
  for (size_t f = 0; f < m.t.size(); ++f)
  {
    a += onlySym < 0 || m.sym[f] == onlySym ? m.Area(f) : 0.0;
  }
  return a;
}

double EdgeLength(const TriMesh& m)
{
  return std::sqrt(4 * MeshArea(m) / (std::sqrt(3.0) * double(m.t.size())));
}

int OctaResolution(double faces)
{
  return std::max(2, int(std::lround(std::sqrt(faces / 8))));
}

// Height of the hole loop above its centre along the hole normal: tubes start above it, so the
// collar does not dip into a bumpy body.
double LoopLift(const TriMesh& m, const Hole& hole)
{
  double lift = 0;
  for (Id v : hole.loop)
  {
    lift = std::max(lift, (m.p[v] - hole.center).dot(hole.normal));
  }
  return lift;
}

// Of 8 turns about the hole normal of the frame E, the one whose tube spec (length L) keeps
// farthest from the body's vertices beyond arc length `skip` from its start at o; with `cost`,
// the one of least cost among those keeping at least `minGap` away (if any).
Eigen::Matrix3d ClearestFrame(const TriMesh& body,
  const Eigen::Matrix3d& E,
  const TubeSpec& s,
  const Vec3& o,
  double L,
  double skip,
  const std::function<double(const Eigen::Matrix3d&)>& cost = {},
  double minGap = 0)
{
  const size_t stride = std::max<size_t>(1, body.p.size() / 3000);
  const std::vector<Vec2> dirs = RingTable(4);
  const double u0 = std::min(0.9, skip / L);
  Eigen::Matrix3d best = E, cheapest = E;
  double bestGap = -1e300, bestCost = 1e300;
  for (int k = 0; k < 8; ++k)
  {
    const double b = 2 * kPi * k / 8;
    Eigen::Matrix3d R = E;
    R.col(0) = std::cos(b) * E.col(0) + std::sin(b) * E.col(1);
    R.col(1) = E.col(2).cross(R.col(0));
    double gap = 1e300;
    for (int j = 0; j <= 32; ++j)
    {
      const double u = u0 + (1 - u0) * j / 32;
      const Vec3 c = o + R * s.center(u);
      const Vec2 r = s.radii(u);
      double rs = r.maxCoeff();
      for (const Vec2& d : dirs)
      {
        rs = std::max(rs, s.section ? s.section(u, d).norm() : 0.0);
      }
      for (size_t i = 0; i < body.p.size(); i += stride)
      {
        gap = std::min(gap, (body.p[i] - c).norm() - rs);
      }
    }
    if (gap > bestGap)
    {
      bestGap = gap;
      best = R;
    }
    const double c = cost && gap >= minGap ? cost(R) : 1e300;
    if (c < bestCost)
    {
      bestCost = c;
      cheapest = R;
    }
  }
  return bestCost < 1e300 ? cheapest : best;
}

// Welds tubes of growing length until the area fraction of faces with sym == which reaches target.
TriMesh WeldToFraction(const TriMesh& body,
  const Hole& hole,
  const std::function<TubeSpec(double)>& spec,
  const Vec3& o,
  const Eigen::Matrix3d& E,
  char tubeSym,
  int which,
  double target,
  double L0)
{
  auto make = [&](double L)
  {
    std::vector<Id> ring0;
    TriMesh tube = BuildTube(spec(L), o, E, tubeSym, ring0);
    return Weld(body, hole, tube, ring0);
  };
  auto frac = [&](const TriMesh& m) { return MeshArea(m, which) / MeshArea(m); };
  const double Lmin = spec(1).spacing;
  double La = std::max(Lmin, L0), Lb = 1.3 * La;
  TriMesh a = make(La), b = make(Lb);
  double fa = frac(a) - target, fb = frac(b) - target;
  for (int it = 0; it < 6 && std::abs(fb) > 0.005 && fb != fa; ++it)
  {
    const double Lc = std::clamp(Lb - fb * (Lb - La) / (fb - fa), Lmin, 60.0);
    La = Lb;
    fa = fb;
    a = std::move(b);
    Lb = Lc;
    b = make(Lb);
    fb = frac(b) - target;
  }
  return std::abs(fb) <= std::abs(fa) ? b : a;
}

// ---- VTK conversion and access ----
vtkSmartPointer<vtkPolyData> ToPolyData(const TriMesh& m)
{
  auto coords = vtkSmartPointer<vtkDoubleArray>::New();
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(vtkIdType(m.p.size()));
  double* c = coords->GetPointer(0);
  for (size_t i = 0; i < m.p.size(); ++i)
  {
    std::copy(m.p[i].data(), m.p[i].data() + 3, c + 3 * i);
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coords);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto conn = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(vtkIdType(m.t.size() + 1));
  conn->SetNumberOfValues(vtkIdType(3 * m.t.size()));
  for (size_t f = 0; f <= m.t.size(); ++f)
  {
    offsets->SetValue(vtkIdType(f), vtkIdType(3 * f));
  }
  for (size_t f = 0; f < m.t.size(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      conn->SetValue(vtkIdType(3 * f + k), m.t[f][k]);
    }
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets.Get(), conn.Get());
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(cells);
  return pd;
}

ProceduralMesh Finish(const TriMesh& m, std::vector<KnownPlane> planes)
{
  ProceduralMesh r;
  r.mesh = ToPolyData(m);
  r.planes = std::move(planes);
  r.symmetricFace = m.sym;
  return r;
}

const KnownPlane kPlaneX{ Vec3::Zero(), Vec3::UnitX() };
const KnownPlane kPlaneY{ Vec3::Zero(), Vec3::UnitY() };
const KnownPlane kPlaneZ{ Vec3::Zero(), Vec3::UnitZ() };

std::vector<Vec3> GetPoints(vtkPolyData* pd)
{
  std::vector<Vec3> p(size_t(pd->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    pd->GetPoint(i, p[size_t(i)].data());
  }
  return p;
}

void SetPoints(vtkPolyData* pd, const std::vector<Vec3>& p)
{
  vtkPoints* pts = pd->GetPoints();
  for (size_t i = 0; i < p.size(); ++i)
  {
    pts->SetPoint(vtkIdType(i), p[i].data());
  }
  pts->Modified();
  pd->Modified();
}

template <class Fn> // fn(cellId, a, b, c) for every triangle of every polygon (fan)
void ForEachTriangle(vtkPolyData* pd, Fn fn)
{
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    const int type = pd->GetCellType(c);
    if (type != VTK_TRIANGLE && type != VTK_POLYGON && type != VTK_QUAD)
    {
      continue;
    }
    pd->GetCellPoints(c, n, ids);
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      fn(c, ids[0], ids[k], ids[k + 1]);
    }
  }
}
} // namespace

// =================================== generators ===================================

ProceduralMesh MakeBilateralBlob(int approxFaces, unsigned seed)
{
  const Creature s = CreatureShape(seed);
  return Finish(OctaSphere(OctaResolution(approxFaces), s, true, 1), { kPlaneX });
}

ProceduralMesh MakeBilateralBlobDifferentTessellation(int approxFaces, unsigned seed)
{
  const Creature s = CreatureShape(seed);
  // faces ~ 4 n^2 + 4 (1.3 n)^2
  const int n = std::max(2, int(std::lround(std::sqrt(approxFaces / 10.76))));
  const int m = std::max(n + 1, int(std::lround(1.3 * n)));
  return Finish(OctaSphereTwoResolutions(n, m, s), { kPlaneX });
}

ProceduralMesh MakeThreePlaneShape(int approxFaces)
{
  const Vec3 a(1.0, 0.7, 0.4); // half extents
  const double rho = 0.2;
  const double sc = std::sqrt(approxFaces / (16 * (a.x() * a.y() + a.y() * a.z() + a.z() * a.x())));
  int N[3];
  for (int k = 0; k < 3; ++k)
  {
    N[k] = 2 * std::max(1, int(std::lround(sc * a[k])));
  }
  TriMesh m;
  std::unordered_map<int64_t, Id> ids;
  auto vertex = [&](const std::array<int, 3>& L)
  {
    const int64_t key = (int64_t(L[0]) * (N[1] + 1) + L[1]) * (N[2] + 1) + L[2];
    auto ins = ids.emplace(key, Id(m.p.size()));
    if (ins.second)
    {
      Vec3 q, c;
      for (int k = 0; k < 3; ++k)
      {
        q[k] = a[k] * double(2 * L[k] - N[k]) / N[k]; // exactly odd in L -> N - L
        c[k] = std::clamp(q[k], -(a[k] - rho), a[k] - rho);
      }
      m.Add(c + rho * (q - c).normalized());
    }
    return ins.first->second;
  };
  for (int ax = 0; ax < 3; ++ax)
  {
    const int b = (ax + 1) % 3, c = (ax + 2) % 3; // e_b x e_c = e_ax
    for (int side = 0; side < 2; ++side)
    {
      for (int i = 0; i < N[b]; ++i)
      {
        for (int j = 0; j < N[c]; ++j)
        {
          Id v[2][2];
          for (int di = 0; di < 2; ++di)
          {
            for (int dj = 0; dj < 2; ++dj)
            {
              std::array<int, 3> L;
              L[ax] = side * N[ax];
              L[b] = i + di;
              L[c] = j + dj;
              v[di][dj] = vertex(L);
            }
          }
          // diagonal pattern mirrored about the face's mid lines: symmetric triangle set
          const bool diag = (2 * i + 1 > N[b]) == (2 * j + 1 > N[c]);
          Tri t1 = { v[0][0], v[1][0], diag ? v[1][1] : v[0][1] };
          Tri t2 = diag ? Tri{ v[0][0], v[1][1], v[0][1] } : Tri{ v[1][0], v[1][1], v[0][1] };
          for (Tri* t : { &t1, &t2 })
          {
            if (!side)
            {
              std::swap((*t)[1], (*t)[2]);
            }
            m.Face((*t)[0], (*t)[1], (*t)[2], 1);
          }
        }
      }
    }
  }
  return Finish(m, { kPlaneX, kPlaneY, kPlaneZ });
}

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

ProceduralMesh MakeAsymmetricBlob(int approxFaces, unsigned seed)
{
  const Lumpy s = LumpyShape(seed);
  return Finish(OctaSphere(OctaResolution(approxFaces), s, false, 0), {});
}

ProceduralMesh MakeSphere(int approxFaces)
{
  ProceduralMesh r =
    Finish(OctaSphere(
             OctaResolution(approxFaces), [](const Vec3& d) { return d; }, true, 1),
      { kPlaneX, kPlaneY, kPlaneZ });
  r.family = SymmetryFamily::AnyPlaneThroughCenter;
  return r;
}

ProceduralMesh MakeCylinder(int approxFaces)
{
  const double R = 0.6, H = 2.0;
  const int J =
    std::max(2, int(std::lround(std::sqrt(approxFaces / (8 * (1 + 2 * H / (kPi * R)))))));
  const int Nz = 2 * std::max(1, int(std::lround(H / (2 * (0.5 * kPi * R / J)))));
  const std::vector<Vec2> rim = RingTable(J);
  const size_t M = rim.size();
  TriMesh m;
  std::vector<std::vector<Id>> side(size_t(Nz + 1));
  for (int l = 0; l <= Nz; ++l)
  {
    const double z = 0.5 * H * double(2 * l - Nz) / Nz;
    for (const Vec2& c : rim)
    {
      side[l].push_back(m.Add(Vec3(R * c.x(), R * c.y(), z)));
    }
  }
  for (int l = 0; l < Nz; ++l)
  {
    for (size_t k = 0; k < M; ++k)
    {
      const size_t k1 = (k + 1) % M;
      m.Face(side[l][k], side[l][k1], side[l + 1][k1], 1);
      m.Face(side[l][k], side[l + 1][k1], side[l + 1][k], 1);
    }
  }
  for (int top = 0; top < 2; ++top)
  {
    const double z = top ? 0.5 * H : -0.5 * H;
    const size_t first = m.t.size();
    std::vector<Id> inner{ m.Add(Vec3(0, 0, z)) };
    for (int j = 1; j <= J; ++j)
    {
      std::vector<Id> outer;
      if (j == J)
      {
        outer = side[top ? Nz : 0];
      }
      else
      {
        for (const Vec2& c : RingTable(j))
        {
          outer.push_back(m.Add(Vec3(R * j / J * c.x(), R * j / J * c.y(), z)));
        }
      }
      Zip(inner,
        UniformParams(inner.size()),
        outer,
        UniformParams(outer.size()),
        [&](Id a, Id b, Id c) { m.Face(a, b, c, 1); });
      inner = outer;
    }
    for (size_t f = first; !top && f < m.t.size(); ++f)
    {
      std::swap(m.t[f][0], m.t[f][1]);
    }
  }
  const double h = std::sqrt(0.5);
  ProceduralMesh r = Finish(m,
    { kPlaneX,
      kPlaneY,
      KnownPlane{ Vec3::Zero(), Vec3(h, -h, 0) },
      KnownPlane{ Vec3::Zero(), Vec3(h, h, 0) },
      kPlaneZ });
  r.family = SymmetryFamily::AnyPlaneContainingAxis;
  return r;
}

ProceduralMesh MakeMultiPartSymmetric(int approxFaces)
{
  const Creature body = CreatureShape(7);
  const Lumpy ear = LumpyShape(11);
  TriMesh m = OctaSphere(OctaResolution(0.6 * approxFaces), body, true, 1);
  // on the upper side of the head, pushed outwards by 0.1 along the section direction
  const double ty = body.SpineT(body.yh - 0.05), psi = 0.9, st = std::sqrt(1 - ty * ty);
  const Vec3 c = body(Vec3(st * std::sin(psi), ty, st * std::cos(psi))) +
    0.1 * Vec3(std::sin(psi), 0, std::cos(psi));
  TriMesh right = OctaSphere(
    OctaResolution(0.2 * approxFaces),
    [&](const Vec3& u) { return Vec3(c + 0.25 * ear(u)); },
    false,
    1);
  double minX = 1e300; // the ears stay clear of each other (and of the plane x = 0)
  for (const Vec3& p : right.p)
  {
    minX = std::min(minX, p.x());
  }
  for (Vec3& p : right.p)
  {
    p.x() += std::max(0.0, 0.08 - minX);
  }
  TriMesh left = right;
  for (Vec3& p : left.p)
  {
    p = MirrorX(p);
  }
  for (Tri& t : left.t)
  {
    std::swap(t[0], t[1]);
  }
  m.Append(right);
  m.Append(left);
  return Finish(m, { kPlaneX });
}

// ================================= transformations =================================

Eigen::Isometry3d RandomRigidMotion(unsigned seed)
{
  auto g = Rng(seed, 505);
  const double u1 = Uniform(g), u2 = Uniform(g), u3 = Uniform(g); // Shoemake: uniform rotation
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const Eigen::Quaterniond q(b * std::cos(2 * kPi * u3),
    a * std::sin(2 * kPi * u2),
    a * std::cos(2 * kPi * u2),
    b * std::sin(2 * kPi * u3));
  Vec3 t;
  for (int k = 0; k < 3; ++k)
  {
    t[k] = Uniform(g, -5, 5);
  }
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = t;
  return T;
}

void ApplyRigidMotion(ProceduralMesh& m, const Eigen::Isometry3d& T)
{
  std::vector<Vec3> p = GetPoints(m.mesh);
  for (Vec3& x : p)
  {
    x = T * x;
  }
  SetPoints(m.mesh, p);
  for (KnownPlane& k : m.planes)
  {
    k.origin = T * k.origin;
    k.normal = (T.linear() * k.normal).normalized();
  }
  m.center = T * m.center;
  m.axis = (T.linear() * m.axis).normalized();
}

void ScaleUniformly(ProceduralMesh& m, double s)
{
  std::vector<Vec3> p = GetPoints(m.mesh);
  for (Vec3& x : p)
  {
    x *= s;
  }
  SetPoints(m.mesh, p);
  for (KnownPlane& k : m.planes)
  {
    k.origin *= s;
  }
  m.center *= s;
}

void AddGaussianNoise(ProceduralMesh& m, double sigmaFraction, unsigned seed, bool alongNormals)
{
  const double sigma = sigmaFraction * BoundsDiagonal(m.mesh);
  std::vector<Vec3> p = GetPoints(m.mesh), n(p.size(), Vec3::Zero());
  ForEachTriangle(m.mesh,
    [&](vtkIdType, vtkIdType a, vtkIdType b, vtkIdType c)
    {
      const Vec3 w = (p[b] - p[a]).cross(p[c] - p[a]);
      n[a] += w;
      n[b] += w;
      n[c] += w;
    });
  auto g = Rng(seed, 606);
  for (size_t i = 0; i < p.size(); ++i)
  {
    if (alongNormals)
    {
      const double k = n[i].norm();
      const double e = sigma * Gauss(g);
      p[i] += k > 0 ? Vec3(e / k * n[i]) : Vec3::Zero();
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        p[i][c] += sigma * Gauss(g);
      }
    }
  }
  SetPoints(m.mesh, p);
}

// ===================================== measures =====================================

double BoundsDiagonal(vtkPolyData* mesh)
{
  double b[6];
  mesh->GetBounds(b);
  return Vec3(b[1] - b[0], b[3] - b[2], b[5] - b[4]).norm();
}

std::vector<double> FaceAreas(vtkPolyData* mesh)
{
  std::vector<double> a(size_t(mesh->GetNumberOfCells()), 0.0);
  const std::vector<Vec3> p = GetPoints(mesh);
  ForEachTriangle(mesh,
    [&](vtkIdType c, vtkIdType i, vtkIdType j, vtkIdType k)
    { a[size_t(c)] += 0.5 * (p[j] - p[i]).cross(p[k] - p[i]).norm(); });
  return a;
}

Eigen::Vector3d AreaCentroid(vtkPolyData* mesh)
{
  const std::vector<Vec3> p = GetPoints(mesh);
  Vec3 s = Vec3::Zero();
  double w = 0;
  ForEachTriangle(mesh,
    [&](vtkIdType, vtkIdType i, vtkIdType j, vtkIdType k)
    {
      const double a = 0.5 * (p[j] - p[i]).cross(p[k] - p[i]).norm();
      s += a * (p[i] + p[j] + p[k]) / 3;
      w += a;
    });
  return w > 0 ? Vec3(s / w) : Vec3::Zero();
}

double MaskAreaFraction(vtkPolyData* mesh, const std::vector<char>& mask)
{
  const std::vector<double> a = FaceAreas(mesh);
  if (mask.size() != a.size())
  {
    throw std::invalid_argument("MaskAreaFraction: mask size differs from the cell count");
  }
  double in = 0, all = 0;
  for (size_t f = 0; f < a.size(); ++f)
  {
    in += mask[f] ? a[f] : 0.0;
    all += a[f];
  }
  return all > 0 ? in / all : 0.0;
}

double PlaneAngleDegrees(const Eigen::Vector3d& n1, const Eigen::Vector3d& n2)
{
  return std::atan2(n1.cross(n2).norm(), std::abs(n1.dot(n2))) * 180 / kPi;
}

double PlaneOffsetError(const KnownPlane& truth,
  const Eigen::Vector3d& origin,
  const Eigen::Vector3d& normal,
  const Eigen::Vector3d& at,
  double diagonal)
{
  const Vec3 nt = truth.normal.normalized();
  const Vec3 q = at - nt.dot(at - truth.origin) * nt;
  return std::abs(normal.normalized().dot(q - origin)) / diagonal;
}

PlaneMatch BestPlaneMatch(const ProceduralMesh& m,
  const Eigen::Vector3d& origin,
  const Eigen::Vector3d& normal)
{
  const Vec3 at = AreaCentroid(m.mesh);
  const double diag = BoundsDiagonal(m.mesh);
  std::vector<PlaneMatch> c;
  for (size_t i = 0; i < m.planes.size(); ++i)
  {
    c.push_back({ int(i),
      PlaneAngleDegrees(normal, m.planes[i].normal),
      PlaneOffsetError(m.planes[i], origin, normal, at, diag) });
  }
  Vec3 n = normal.normalized();
  if (m.family == SymmetryFamily::AnyPlaneContainingAxis)
  {
    const Vec3 a = m.axis.normalized();
    n -= n.dot(a) * a;
    n = n.norm() > 1e-12 ? Vec3(n.normalized()) : a.unitOrthogonal();
  }
  if (m.family != SymmetryFamily::None)
  {
    const KnownPlane k{ m.center, n };
    c.push_back(
      { -1, PlaneAngleDegrees(normal, n), PlaneOffsetError(k, origin, normal, at, diag) });
  }
  PlaneMatch best;
  for (const PlaneMatch& x : c)
  {
    best.angleDegrees = std::min(best.angleDegrees, x.angleDegrees);
  }
  const double minAngle = best.angleDegrees;
  for (const PlaneMatch& x : c)
  {
    if (x.angleDegrees <= minAngle + 1e-6 && x.offsetError < best.offsetError)
    {
      best = x;
    }
  }
  return best;
}

double RegionIoU(vtkPolyData* mesh, const std::vector<char>& found, const std::vector<char>& truth)
{
  const std::vector<double> a = FaceAreas(mesh);
  if (found.size() != a.size() || truth.size() != a.size())
  {
    throw std::invalid_argument("RegionIoU: mask sizes differ from the cell count");
  }
  double inter = 0, uni = 0;
  for (size_t f = 0; f < a.size(); ++f)
  {
    inter += found[f] && truth[f] ? a[f] : 0.0;
    uni += found[f] || truth[f] ? a[f] : 0.0;
  }
  return uni > 0 ? inter / uni : 1.0;
}

} // namespace testing
} // namespace foldingmeshes
