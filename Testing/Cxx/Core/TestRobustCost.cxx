// Geman-McClure cost rho(d) = d^2 / (sigma^2 + d^2) and IRLS weight w(d) = (1/d) d rho/dd:
// - w against a central finite difference of rho (several sigmas, d from 1e-3 to 1e3 sigma);
// - limits: rho(0) = 0, w(0) = 2 / sigma^2 (the limit of rho'(d)/d, checked against small d),
//   rho(inf) = 1, w(inf) = 0, and rho -> 1, w -> 0 for large finite d;
// - rho even in d, strictly increasing on d >= 0 and in [0, 1); w positive, strictly decreasing.
#include "CoreTestUtilities.h"
#include "RobustCost.h"

#include <cmath>
#include <limits>

using foldingmeshes::GemanMcClureCost;
using foldingmeshes::GemanMcClureWeight;

int main()
{
  const double inf = std::numeric_limits<double>::infinity();
  for (double sigma : { 1e-3, 0.37, 1.0, 25.0, 1e4 })
  {
    // Finite differences: w = rho'(d) / d.
    double worst = 0.0;
    for (double t = 1e-3; t <= 1e3; t *= 1.1)
    {
      const double d = t * sigma, h = 1e-5 * d;
      const double derivative =
        (GemanMcClureCost(d + h, sigma) - GemanMcClureCost(d - h, sigma)) / (2 * h);
      const double fd = derivative / d;
      const double w = GemanMcClureWeight(d, sigma);
      // Relative to the weight scale at 0, 2/sigma^2 (rho' is tiny far out).
      worst = std::max(worst, std::abs(w - fd) * sigma * sigma / 2.0);
    }
    EXPECT(worst < 1e-6,
      "sigma " << sigma << ": weight differs from finite-difference rho'/d by " << worst
               << " (relative to 2/sigma^2)");

    // d = 0 and its neighbourhood.
    EXPECT(GemanMcClureCost(0.0, sigma) == 0.0, "rho(0) = " << GemanMcClureCost(0.0, sigma));
    const double w0 = GemanMcClureWeight(0.0, sigma);
    EXPECT(
      std::abs(w0 * sigma * sigma / 2.0 - 1.0) < 1e-14, "w(0) = " << w0 << ", expected 2/sigma^2");
    const double small = 1e-4 * sigma;
    const double fdSmall =
      (GemanMcClureCost(2 * small, sigma) - GemanMcClureCost(0.0, sigma)) / (2 * small) / small;
    EXPECT(std::abs(fdSmall * sigma * sigma / 2.0 - 1.0) < 1e-6,
      "w(0) is not the limit of rho'(d)/d: finite difference gives " << fdSmall << ", w(0) " << w0);

    // d = infinity and large finite d.
    EXPECT(GemanMcClureCost(inf, sigma) == 1.0, "rho(inf) = " << GemanMcClureCost(inf, sigma));
    EXPECT(GemanMcClureWeight(inf, sigma) == 0.0, "w(inf) = " << GemanMcClureWeight(inf, sigma));
    const double big = 1e6 * sigma;
    EXPECT(
      std::abs(GemanMcClureCost(big, sigma) - 1.0) < 1e-11 && GemanMcClureCost(big, sigma) <= 1.0,
      "rho(1e6 sigma) = " << GemanMcClureCost(big, sigma) << ", not close to its limit 1");
    EXPECT(GemanMcClureWeight(big, sigma) * sigma * sigma < 1e-23,
      "w(1e6 sigma) = " << GemanMcClureWeight(big, sigma) << ", not close to its limit 0");

    // Evenness, range and monotonicity.
    double lastRho = -1.0, lastW = inf;
    bool monotone = true, inRange = true, even = true;
    for (double t = 0.0; t <= 1e4; t = t < 1e-3 ? t + 1e-4 : t * 1.05)
    {
      const double d = t * sigma;
      const double rho = GemanMcClureCost(d, sigma), w = GemanMcClureWeight(d, sigma);
      monotone = monotone && rho > lastRho && w < lastW;
      inRange = inRange && rho >= 0.0 && rho < 1.0 && w > 0.0;
      even = even && rho == GemanMcClureCost(-d, sigma) && w == GemanMcClureWeight(-d, sigma);
      lastRho = rho;
      lastW = w;
    }
    EXPECT(
      monotone, "sigma " << sigma << ": rho not strictly increasing or w not strictly decreasing");
    EXPECT(inRange, "sigma " << sigma << ": rho outside [0,1) or w not positive");
    EXPECT(even, "sigma " << sigma << ": rho or w not even in d");

    // rho = 1/2 at d = sigma; at d = 2 sigma (the support threshold) rho = 4/5.
    EXPECT(std::abs(GemanMcClureCost(sigma, sigma) - 0.5) < 1e-15, "rho(sigma) != 1/2");
    EXPECT(std::abs(GemanMcClureCost(2 * sigma, sigma) - 0.8) < 1e-15, "rho(2 sigma) != 4/5");
  }
  return coretest::Finish("TestRobustCost");
}
