#include "contact/edge_on_elastic_block_exponent.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::contact
{
namespace
{
constexpr double pi = std::numbers::pi;

void check_angle(double theta)
{
  if (!(theta > 0 && theta <= pi))
    throw InputError(fmt::format("interior angle {} rad: must lie in (0, pi]", theta));
}

void check_material(double youngs_modulus_pa, double poisson_ratio, const char* which)
{
  if (!(std::isfinite(youngs_modulus_pa) && youngs_modulus_pa > 0))
    throw InputError(fmt::format("Young's modulus of the {} {} Pa: must be positive and finite", which, youngs_modulus_pa));
  if (!(poisson_ratio >= 0 && poisson_ratio < 0.5))
    throw InputError(fmt::format("Poisson ratio of the {} {}: must lie in [0, 0.5)", which, poisson_ratio));
}

double plane_strain_modulus(double youngs_modulus_pa, double poisson_ratio)
{
  return youngs_modulus_pa / (1 - poisson_ratio * poisson_ratio);
}

/// x - sin x without the cancellation of small x (its series below 0.1).
double x_minus_sin(double x)
{
  if (std::abs(x) >= 0.1)
    return x - std::sin(x);
  const double x2 = x * x;
  return x * x2 / 6 * (1 - x2 / 20 * (1 - x2 / 42 * (1 - x2 / 72 * (1 - x2 / 110))));
}

/// The least lambda in (0, 1) where the body's (weight w_body = E1* / (E1* + E2*)
/// = (1 + alpha) / 2) and the block's (w_block = (1 - alpha) / 2) normal
/// displacements agree; 1 where there is none.
double least_root(double theta, double w_body, double w_block)
{
  const double sin_t = std::sin(theta), sin_2t = std::sin(2 * theta);
  // f(lambda) = w_block S sin(lambda pi) - 2 w_body Q cos(lambda pi) (the header's
  // equation halved), divided by 1 - lambda to remove its trivial root at 1.
  // Q = (lambda sin theta - sin lambda theta)(lambda sin theta + sin lambda theta),
  // the first factor as (x - sin x) differences, exact for a sharp wedge.
  auto g = [&](double l) {
    if (l == 1.0) // the limit: f(1 - e) / e -> 2 (w_block pi sin 2 theta + w_body (theta sin 2 theta - 2 sin^2 theta))
      return 2 * (w_block * pi * sin_2t + w_body * (theta * sin_2t - 2 * sin_t * sin_t));
    const double s = std::sin(2 * l * theta) + l * sin_2t;
    const double q = (x_minus_sin(l * theta) - l * x_minus_sin(theta)) * (l * sin_t + std::sin(l * theta));
    return (w_block * s * std::sin(l * pi) - 2 * w_body * q * std::cos(l * pi)) / (1 - l);
  };
  // f / lambda^2 -> w_block pi (2 theta + sin 2 theta) + 2 w_body (theta^2 - sin^2 theta) > 0
  // as lambda -> 0, so the first sign change from the left brackets the least root.
  constexpr int cells = 1000;
  double lo = 0;
  for (int i = 1; i <= cells; ++i)
  {
    const double hi = double(i) / cells;
    const double g_hi = g(hi);
    if (g_hi == 0)
      return hi;
    if (g_hi < 0)
    {
      double a = lo, b = hi; // g(a) > 0 (or a = 0+), g(b) < 0
      for (int k = 0; k < 200 && b - a > 1e-15; ++k)
      {
        const double mid = 0.5 * (a + b);
        (g(mid) > 0 ? a : b) = mid;
      }
      return 0.5 * (a + b);
    }
    lo = hi;
  }
  return 1.0; // no root in (0, 1): the stresses stay bounded
}
} // namespace

double dundurs_alpha_plane_strain(double youngs_modulus_body_pa, double poisson_ratio_body,
                                  double youngs_modulus_block_pa, double poisson_ratio_block)
{
  check_material(youngs_modulus_body_pa, poisson_ratio_body, "body");
  check_material(youngs_modulus_block_pa, poisson_ratio_block, "block");
  const double body = plane_strain_modulus(youngs_modulus_body_pa, poisson_ratio_body);
  const double block = plane_strain_modulus(youngs_modulus_block_pa, poisson_ratio_block);
  return (body - block) / (body + block);
}

double edge_on_elastic_block_exponent_for_alpha(double interior_angle_rad, double alpha)
{
  check_angle(interior_angle_rad);
  if (!(alpha >= -1 && alpha <= 1))
    throw InputError(fmt::format("Dundurs' alpha {}: must lie in [-1, 1]", alpha));
  return least_root(interior_angle_rad, 0.5 * (1 + alpha), 0.5 * (1 - alpha)) - 1.0;
}

double edge_on_elastic_block_exponent(double interior_angle_rad, double youngs_modulus_body_pa,
                                      double poisson_ratio_body, double youngs_modulus_block_pa,
                                      double poisson_ratio_block)
{
  check_angle(interior_angle_rad);
  check_material(youngs_modulus_body_pa, poisson_ratio_body, "body");
  check_material(youngs_modulus_block_pa, poisson_ratio_block, "block");
  // The weights straight from E*, not via alpha: 1 -/+ alpha loses digits for
  // a nearly rigid partner.
  const double body = plane_strain_modulus(youngs_modulus_body_pa, poisson_ratio_body);
  const double block = plane_strain_modulus(youngs_modulus_block_pa, poisson_ratio_block);
  return least_root(interior_angle_rad, body / (body + block), block / (body + block)) - 1.0;
}
} // namespace rollcheck::contact
