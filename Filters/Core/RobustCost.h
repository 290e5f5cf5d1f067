// The Geman-McClure robust cost and its IRLS weight (paper, section 3).
#ifndef foldingmeshes_RobustCost_h
#define foldingmeshes_RobustCost_h

#include <cmath>

namespace foldingmeshes
{
/// rho(d) = d^2 / (sigma^2 + d^2); 1 for an infinite distance.
inline double GemanMcClureCost(double d, double sigma)
{
  if (!std::isfinite(d))
  {
    return 1.0;
  }
  const double d2 = d * d;
  return d2 / (sigma * sigma + d2);
}

/// w(d) = (1/d) d rho / dd = 2 sigma^2 / (sigma^2 + d^2)^2; 0 for an infinite distance.
inline double GemanMcClureWeight(double d, double sigma)
{
  if (!std::isfinite(d))
  {
    return 0.0;
  }
  const double s2 = sigma * sigma;
  const double t = s2 + d * d;
  return 2.0 * s2 / (t * t);
}
}

#endif
