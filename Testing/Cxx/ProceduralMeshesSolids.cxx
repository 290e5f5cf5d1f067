// Basic solid generators: rounded box (three planes), sphere, capped cylinder.
#include "ProceduralMeshesInternal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
using namespace procedural;

// =================================== generators ===================================

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
} // namespace testing
} // namespace foldingmeshes
