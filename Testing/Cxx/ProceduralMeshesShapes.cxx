// Seeded factories of the analytic shapes: CreatureShape and LumpyShape.
#include "ProceduralMeshesShapes.h"

namespace foldingmeshes
{
namespace testing
{
namespace procedural
{
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
} // namespace procedural
} // namespace testing
} // namespace foldingmeshes
