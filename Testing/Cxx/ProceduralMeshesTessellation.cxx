// Tessellation: equal-area octahedral grids (one or two resolutions), ring tables, loop params.
#include "ProceduralMeshesInternal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
namespace procedural
{
namespace
{
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
} // namespace

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

int OctaResolution(double faces)
{
  return std::max(2, int(std::lround(std::sqrt(faces / 8))));
}
} // namespace procedural
} // namespace testing
} // namespace foldingmeshes
