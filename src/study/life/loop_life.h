#pragma once
// Wing of the study layer (study/life): the stress-volume life integrals of
// a body over one loop of its rolling (stress_volume.h).
//
// Over one loop each surface point P at fraction s of the contact ruling
// (length L, radius of normal curvature R(s) across it) is passed once, so
// its stress history is one pass of line contact with the half-width b and
// peak p0 of the ruling's line load q(s) there (Johnson eqs. 4.43, 4.45):
//     b = sqrt(4 q R / (pi E*)),  p0 = sqrt(q E* / (pi R)),
// and the element dA = L R dsigma ds. The line load follows the robustness
// study's load rules (contact/ruling_load.h: static through the centre of
// mass, the motion's own dynamic load, uniform) and its end
// margin: within `end_margin` of a loaded end of the ruling q and R are held
// at their values there (the rim's own singular stress is not this model's:
// study/rims; with a rounded edge, for_each_loaded_end adds them). Quadrature: the trapezoid rule in sigma between the
// trajectory's samples, two-point Gauss-Legendre on `pieces` equal pieces of
// the loaded part of each ruling. A pass's life does not depend on how fast
// it rolls, so the rolling energy enters only through the dynamic load.
#include "contact/ruling_load.h"
#include "oracle/rolling_study.h"
#include "study/life/rounded_end_ratios.h"
#include "study/life/stress_volume.h"
#include <array>
#include <functional>

namespace rollcheck::study::life
{
struct LoopLifeSettings
{
  contact::LoadRule load_rule = contact::LoadRule::dynamic;
  double end_margin = 0.05;
  double normal_load_n = 100;
  double effective_modulus_pa = 200e9 / (2 * (1 - 0.3 * 0.3)); ///< steel on steel
  int pieces = 32;
};

/// One loaded surface element: its area, and the Hertz peak and half-width of its pass.
struct LoadedElement
{
  double area_m2;
  double peak_pressure_pa;
  double half_width_m;
};

/// Calls `visit` for every quadrature element of the loop [0, end] of `run`.
void for_each_loaded_element(const oracle::RealRolling& run, const LoopLifeSettings& settings,
                             const std::function<void(const LoadedElement&)>& visit);

/// A rounded rim at every loaded end of the loop's rulings (edge radius
/// r_e), each end's pass taken as a line contact of its own: at the end's
/// line load q (not held at the margin) on R = max(R_end, r_e) (the rounded
/// surface), half-width b = sqrt(4 q R / (pi E*)), and peak rho(R_end / r_e)
/// times line Hertz's p0 there (rounded_end_ratios.h), over a patch of
/// `zone_over_half_width` b along the ruling and R dsigma across. Assumed,
/// not modelled: the end's subsurface field is line contact's at its own
/// peak and b (the rim study's end pressure is a peak over about one b
/// along the ruling, docs/results/rim-ends.md), and rho does not depend on
/// the rim's interior angle (the table's is 87.5 deg; the oloid's end table
/// moves 15-25 % across 66.7-160 deg, docs/results/rims.md).
struct RoundedEnds
{
  double edge_radius_m = 0;
  const RoundedEndRatios* ratios = nullptr;
  double zone_over_half_width = 1;
};

/// One loaded end's element: as LoadedElement, and whether its R_end / r_e
/// lies inside the table (else rho is held at the table's last node: an
/// underestimate).
struct LoadedEnd
{
  LoadedElement element;
  bool inside_table;
};

/// Calls `visit` for every loaded end of every ruling of the loop [0, end] of `run`.
void for_each_loaded_end(const oracle::RealRolling& run, const LoopLifeSettings& settings, const RoundedEnds& ends,
                         const std::function<void(const LoadedEnd&)>& visit);

/// The two criteria that enter the life integrals, in this order.
inline constexpr std::array<contact::FatigueCriterion, 2> life_criteria{contact::FatigueCriterion::orthogonal_shear,
                                                                       contact::FatigueCriterion::largest_shear};

struct LoopIntegrals
{
  std::array<double, 2> lundberg_palmgren{};   ///< I with tau_u = 0, per life_criteria
  std::array<double, 2> ioannides_harris{};    ///< I with the fatigue limit
  double max_peak_pressure_pa = 0;
  double max_dang_van_pa = 0;                  ///< the largest Dang Van stress of any pass
  /// With rounded ends: their own integrals (the interior's above leave them
  /// out), their count and how many lie outside the end table.
  std::array<double, 2> end_lundberg_palmgren{}, end_ioannides_harris{};
  long ends = 0, ends_outside_table = 0;
};

/// The integrals of one loop; `ratio[i]` is the FEM's measured stress over the
/// closed form's for life_criteria[i]; `depth[i]` the criteria's tables,
/// `dang_van` the Dang Van table; `ends`, if given, the rounded rim ends.
LoopIntegrals loop_integrals(const oracle::RealRolling& run, const LoopLifeSettings& settings,
                             const LifeConstants& constants, const std::array<const DepthIntegrals*, 2>& depth,
                             const std::array<double, 2>& ratio, const DepthIntegrals& dang_van,
                             const RoundedEnds* ends = nullptr);

/// Lundberg-Palmgren's integral of one criterion (ratio 1) by direct
/// quadrature over absolute depth: `depths` points uniform in ln(z) over
/// [z_lo, z_hi] (m), the same for every load, so that the load-life exponent
/// measured from it is a measurement of the integral, not of its scaling.
double lundberg_palmgren_by_depth(const oracle::RealRolling& run, const LoopLifeSettings& settings,
                                  const LifeConstants& constants, const DepthIntegrals& depth, double z_lo_m,
                                  double z_hi_m, int depths);
} // namespace rollcheck::study::life
