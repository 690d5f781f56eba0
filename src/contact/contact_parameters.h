#pragma once
// Material, load and model parameters of the contact physics. Defaults are the
// preprint's values (section "Hertz Contact Pressure Validation" and
// "Fatigue, Thermal, and Wear Distribution") and the reference code's.
namespace rollcheck::contact
{
struct HertzParameters
{
  double youngs_modulus_pa = 200e9;  ///< E, mild steel (the preprint's)
  double poisson_ratio = 0.3;        ///< nu (the preprint's)
  double normal_load_n = 100.0;      ///< F, the reference load (the preprint's)
  /// A face whose effective radius exceeds this is flat and carries no Hertz
  /// pressure (the reference code's 1e5 m).
  double flat_radius_m = 1e5;
  /// A principal curvature below this counts as zero (the reference code's 1e-3 1/m).
  double curvature_floor_per_m = 1e-3;
};

struct FatigueParameters
{
  double load_n = 5000.0;                 ///< F for fatigue; pressures scale as (F / F_ref)^(1/3) (the preprint's)
  double strength_coefficient_pa = 700e6; ///< sigma_f' (the preprint's)
  double basquin_exponent = -0.085;       ///< b (the preprint's)
  double endurance_limit_pa = 250e6;      ///< sigma_e: no damage below it (the preprint's)
};

struct ThermalParameters
{
  double friction_coefficient = 0.15;     ///< mu, lubricated steel on steel (the preprint's)
};

struct WearParameters
{
  double archard_coefficient = 1e-4;      ///< k, dimensionless (the preprint's)
  double hardness_pa = 2.0e9;             ///< H (the preprint's)
  /// Contact time per sample (the reference code's typed-in 0.05 s, equal to
  /// its dt x sample interval 0.002 s x 25).
  double contact_time_s = 0.05;
};

struct ContactParameters
{
  HertzParameters hertz;
  FatigueParameters fatigue;
  ThermalParameters thermal;
  WearParameters wear;
};

/// InputError naming the parameter if one is non-finite or out of range.
void validate(const ContactParameters& parameters);
} // namespace rollcheck::contact
