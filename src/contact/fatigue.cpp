#include "contact/fatigue.h"
#include <cmath>
#include <limits>

namespace rollcheck::contact
{
double cycles_to_failure(double sigma, const FatigueParameters& p)
{
  if (!(sigma > 0) || sigma < p.endurance_limit_pa)
    return std::numeric_limits<double>::infinity();
  return std::pow(sigma / p.strength_coefficient_pa, 1.0 / p.basquin_exponent);
}

double miner_damage_per_cycle(double sigma, const FatigueParameters& p)
{
  const double n = cycles_to_failure(sigma, p);
  return std::isinf(n) ? 0.0 : 1.0 / n;
}
} // namespace rollcheck::contact
