#include "contact/contact_parameters.h"
#include "core/error.h"
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::contact
{
void validate(const ContactParameters& p)
{
  auto require = [](bool ok, const char* what, double value, const char* unit) {
    if (!ok)
      throw InputError(fmt::format("contact parameters: {} is out of range: {} {}", what, value, unit));
  };
  auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  auto non_negative = [](double x) { return std::isfinite(x) && x >= 0; };
  require(positive(p.hertz.youngs_modulus_pa), "Young's modulus", p.hertz.youngs_modulus_pa, "Pa");
  require(std::isfinite(p.hertz.poisson_ratio) && p.hertz.poisson_ratio > -1 && p.hertz.poisson_ratio < 0.5,
          "Poisson ratio (-1 < nu < 0.5)", p.hertz.poisson_ratio, "");
  require(positive(p.hertz.normal_load_n), "normal load", p.hertz.normal_load_n, "N");
  require(positive(p.hertz.flat_radius_m), "flat-face radius", p.hertz.flat_radius_m, "m");
  require(non_negative(p.hertz.curvature_floor_per_m), "curvature floor", p.hertz.curvature_floor_per_m, "1/m");
  require(positive(p.fatigue.load_n), "fatigue load", p.fatigue.load_n, "N");
  require(positive(p.fatigue.strength_coefficient_pa), "fatigue strength coefficient",
          p.fatigue.strength_coefficient_pa, "Pa");
  require(std::isfinite(p.fatigue.basquin_exponent) && p.fatigue.basquin_exponent < 0, "Basquin exponent (< 0)",
          p.fatigue.basquin_exponent, "");
  require(non_negative(p.fatigue.endurance_limit_pa), "endurance limit", p.fatigue.endurance_limit_pa, "Pa");
  require(non_negative(p.thermal.friction_coefficient), "friction coefficient", p.thermal.friction_coefficient, "");
  require(non_negative(p.wear.archard_coefficient), "Archard coefficient", p.wear.archard_coefficient, "");
  require(positive(p.wear.hardness_pa), "hardness", p.wear.hardness_pa, "Pa");
  require(non_negative(p.wear.contact_time_s), "contact time per sample", p.wear.contact_time_s, "s");
}
} // namespace rollcheck::contact
