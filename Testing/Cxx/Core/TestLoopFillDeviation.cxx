// ProvedLoopDeviation (Filters/Core/LoopFillDeviation.h), the proof behind the narrow-crack test
// of the unfolder's hole and seam-gap fills:
// - a flat triangle filling its own loop reaches exactly its inradius from the loop, in its
//   interior; its centroid and edge midpoints (the samples the test used before) are nearer, so
//   at a limit between the two the samples passed and the proof must fail;
// - with the limit above the inradius the bound is proved, at least the inradius (sound) and
//   within the limit;
// - a long thin crack filled by two slivers is within half its width;
// - the bound is never below the distance measured at any point of a dense grid over the fill
//   (random bent loops), and is infinite when the piece budget cannot settle it.
#include "CoreTestUtilities.h"
#include "LoopFillDeviation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

using namespace foldingmeshes;

namespace
{
double SegmentDistance(const Vec3& x, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (x - (a + t * ab)).norm();
}

double LoopDistance(const Vec3& x, const std::vector<Vec3>& p, const std::vector<int>& loop)
{
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < loop.size(); ++i)
    d = std::min(d, SegmentDistance(x, p[loop[i]], p[loop[(i + 1) % loop.size()]]));
  return d;
}

/// The largest distance to the loop over a barycentric grid of every fill triangle.
double SampledDeviation(const std::vector<Vec3>& p,
  const std::vector<Triangle>& fill,
  const std::vector<int>& loop,
  int n)
{
  double worst = 0.0;
  for (const Triangle& t : fill)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
      {
        const double a = double(i) / n, b = double(j) / n;
        const Vec3 x = p[t[0]] + a * (p[t[1]] - p[t[0]]) + b * (p[t[2]] - p[t[0]]);
        worst = std::max(worst, LoopDistance(x, p, loop));
      }
  return worst;
}

void TestTriangleInradius()
{
  const std::vector<Vec3> p{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.3, 0) };
  const std::vector<int> loop{ 0, 1, 2 };
  const std::vector<Triangle> fill{ { 0, 1, 2 } };
  const double side = std::sqrt(0.25 + 0.09);
  const double inradius = 0.15 / ((1.0 + 2.0 * side) / 2.0); // area / semi-perimeter
  const Vec3 centroid = (p[0] + p[1] + p[2]) / 3.0;
  const double sampled = LoopDistance(centroid, p, loop); // midpoints: 0
  std::printf("triangle: inradius %.4f, centroid %.4f\n", inradius, sampled);
  EXPECT(sampled < 0.11 && inradius > 0.11, "the triangle does not separate samples from proof");
  const double below = ProvedLoopDeviation(p, fill, loop, 0.11);
  EXPECT(std::isinf(below), "a fill reaching " << inradius << " proved within 0.11: " << below);
  const double above = ProvedLoopDeviation(p, fill, loop, 0.14);
  EXPECT(above >= inradius - 1e-12 && above <= 0.14,
    "bound " << above << " not in [inradius " << inradius << ", 0.14]");
}

void TestThinCrack()
{
  // A crack 1 long and 0.02 wide, filled by two slivers: within 0.01 of its long sides.
  const std::vector<Vec3> p{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0.02, 0), Vec3(0, 0.02, 0) };
  const std::vector<int> loop{ 0, 1, 2, 3 };
  const std::vector<Triangle> fill{ { 0, 1, 2 }, { 0, 2, 3 } };
  const double bound = ProvedLoopDeviation(p, fill, loop, 0.0105);
  std::printf("crack: bound %.5f (half width 0.01)\n", bound);
  EXPECT(bound >= 0.01 - 1e-12 && bound <= 0.0105, "crack bound " << bound);
  EXPECT(std::isinf(ProvedLoopDeviation(p, fill, loop, 0.009)), "crack proved within 0.009");
}

void TestSoundOnBentLoops()
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  int proved = 0;
  for (int trial = 0; trial < 40; ++trial)
  {
    // A bent hexagon filled as a fan from its first vertex.
    std::vector<Vec3> p;
    for (int k = 0; k < 6; ++k)
    {
      const double a = 2.0 * M_PI * k / 6.0;
      p.emplace_back(
        std::cos(a) + 0.2 * jitter(random), std::sin(a) + 0.2 * jitter(random), jitter(random));
    }
    const std::vector<int> loop{ 0, 1, 2, 3, 4, 5 };
    std::vector<Triangle> fill;
    for (int k = 1; k + 1 < 6; ++k)
      fill.push_back({ 0, k, k + 1 });
    const double sampled = SampledDeviation(p, fill, loop, 60);
    const double bound = ProvedLoopDeviation(p, fill, loop, 1.1 * sampled + 1e-3);
    if (std::isfinite(bound))
      ++proved;
    EXPECT(bound >= sampled - 1e-12,
      "trial " << trial << ": bound " << bound << " below a measured distance " << sampled);
    EXPECT(std::isinf(ProvedLoopDeviation(p, fill, loop, 0.9 * sampled)),
      "trial " << trial << ": proved below a measured distance");
  }
  std::printf("bent loops: %d of 40 proved within 1.1 x the sampled deviation\n", proved);
  EXPECT(proved >= 30, "only " << proved << " of 40 bent loops proved within 1.1 x");
  // A piece budget too small to settle anything: not proved.
  const std::vector<Vec3> p{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.3, 0) };
  EXPECT(std::isinf(ProvedLoopDeviation(p, { { 0, 1, 2 } }, { 0, 1, 2 }, 0.14, 3)),
    "three pieces proved the triangle");
}
}

int main()
{
  TestTriangleInradius();
  TestThinCrack();
  TestSoundOnBentLoops();
  return coretest::Finish("TestLoopFillDeviation");
}
