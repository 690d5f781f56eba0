#include "contact/hertz.h"
#include "core/error.h"
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::contact
{
namespace
{
void require_positive(double value, const char* name)
{
  if (!std::isfinite(value) || value <= 0)
    throw InputError(fmt::format("Hertz contact: {} must be positive and finite, got {}", name, value));
}

void require_poisson(double nu)
{
  if (!std::isfinite(nu) || nu <= -1.0 || nu >= 0.5)
    throw InputError(fmt::format("Hertz contact: Poisson ratio must lie in (-1, 0.5), got {}", nu));
}

struct DepthMaximum
{
  double value;
  double depth;
};

/// Maximum of f(zeta) for zeta = z / c in (0, 5]: a dense scan, then golden
/// section on the bracketing interval (the axis stresses are unimodal there).
template <typename F>
DepthMaximum maximise_over_depth(F f)
{
  constexpr int n = 2000;
  constexpr double zmax = 5.0;
  int best = 1;
  for (int i = 2; i <= n; ++i)
    if (f(zmax * i / n) > f(zmax * best / n))
      best = i;
  double lo = zmax * (best - 1) / n, hi = zmax * std::min(best + 1, n) / n;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 100; ++it)
  {
    const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    (f(x1) < f(x2) ? lo : hi) = (f(x1) < f(x2) ? x1 : x2);
  }
  const double z = (lo + hi) / 2;
  return {f(z), z};
}

/// compute(nu), kept for the last nu this thread asked for. The subsurface
/// maxima per unit p0 and contact size depend on nu alone, and a scan of
/// 4,400 points costs far more than the rest of the contact: the half-space
/// solvers ask for one nu at every column of a grid at every iteration
/// (contact/line_hertz_beyond.cpp). One cache per call site (the lambda's type).
template <typename Compute>
auto kept_for_poisson_ratio(double nu, Compute compute)
{
  using Maxima = decltype(compute(nu));
  thread_local double kept_nu = std::nan(""); // equal to no ratio: the first call computes
  thread_local Maxima maxima{};
  if (nu != kept_nu)
  {
    maxima = compute(nu);
    kept_nu = nu;
  }
  return maxima;
}
} // namespace

double effective_modulus_rigid_plane(double E, double nu)
{
  require_positive(E, "Young's modulus (Pa)");
  require_poisson(nu);
  return E / (1 - nu * nu);
}

double effective_modulus_identical_bodies(double E, double nu)
{
  return effective_modulus_rigid_plane(E, nu) / 2;
}

double effective_modulus(double E, double nu, bool elastic_plane)
{
  return elastic_plane ? effective_modulus_identical_bodies(E, nu) : effective_modulus_rigid_plane(E, nu);
}

PointHertz point_contact(double force_n, double radius_m, double effective_modulus_pa, double nu)
{
  require_positive(force_n, "force (N)");
  require_positive(radius_m, "radius (m)");
  require_positive(effective_modulus_pa, "effective modulus (Pa)");
  require_poisson(nu);
  const double a = std::cbrt(3 * force_n * radius_m / (4 * effective_modulus_pa));
  const double p0 = 3 * force_n / (2 * std::numbers::pi * a * a);
  const DepthMaximum shear = kept_for_poisson_ratio(nu, [](double nu) {
    // Axis stresses per unit p0 at depth zeta = z / a (Johnson eq. 3.45).
    auto sigma_z = [](double zeta) { return -1 / (1 + zeta * zeta); };
    auto sigma_r = [nu](double zeta) {
      return -(1 + nu) * (1 - zeta * std::atan(1 / zeta)) + 1 / (2 * (1 + zeta * zeta));
    };
    // On the axis sigma_r = sigma_theta, so von Mises = |sigma_z - sigma_r| = 2 tau_max.
    return maximise_over_depth([&](double zeta) { return std::abs(sigma_z(zeta) - sigma_r(zeta)) / 2; });
  });
  return {a,
          p0,
          2 * p0 / 3,
          a * a / radius_m,
          shear.value * p0,
          shear.depth * a,
          2 * shear.value * p0,
          shear.depth * a};
}

LineHertz line_contact(double force_per_length, double radius_m, double effective_modulus_pa, double nu)
{
  require_positive(force_per_length, "force per unit length (N/m)");
  require_positive(radius_m, "radius (m)");
  require_positive(effective_modulus_pa, "effective modulus (Pa)");
  require_poisson(nu);
  const double b = std::sqrt(4 * force_per_length * radius_m / (std::numbers::pi * effective_modulus_pa));
  const double p0 = 2 * force_per_length / (std::numbers::pi * b);
  const auto [shear, mises] = kept_for_poisson_ratio(nu, [](double nu) {
    // Axis stresses per unit p0 at zeta = z / b (Johnson eq. 4.49), plane strain.
    auto sigma_x = [](double zeta) { return -((1 + 2 * zeta * zeta) / std::sqrt(1 + zeta * zeta) - 2 * zeta); };
    auto sigma_z = [](double zeta) { return -1 / std::sqrt(1 + zeta * zeta); };
    return std::array<DepthMaximum, 2>{
        maximise_over_depth([&](double zeta) { return std::abs(sigma_x(zeta) - sigma_z(zeta)) / 2; }),
        maximise_over_depth([&](double zeta) {
          const double sx = sigma_x(zeta), sz = sigma_z(zeta), sy = nu * (sx + sz);
          return std::sqrt(((sx - sy) * (sx - sy) + (sy - sz) * (sy - sz) + (sz - sx) * (sz - sx)) / 2);
        })};
  });
  return {b, p0, std::numbers::pi * p0 / 4, shear.value * p0, shear.depth * b, mises.value * p0, mises.depth * b};
}

double pressure_profile(double p0, double c, double s)
{
  const double x = s / c;
  return std::abs(x) < 1 ? p0 * std::sqrt(1 - x * x) : 0.0;
}
} // namespace rollcheck::contact
