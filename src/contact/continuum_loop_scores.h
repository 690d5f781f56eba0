#pragma once
// Resolution-free distribution scores of one loop of a rolling line contact,
// accumulated on the body's exact surface: the ruling coordinates of a
// developable body, no mesh.
//
// Over one loop of the contact curve each surface point P is swept once by
// the contact ruling, at turning angle sigma and fraction s of a ruling of
// length L, where the radius of normal curvature across the ruling is
// R(s) = (1 - s) R_0 + s R_1 and the surface element is dA = L R dsigma ds
// = L R |sigma'| dt ds. A per-point quantity x(P) is scored by its
// normalised variance (the squared coefficient of variation)
//     V = A integral x^2 dA / (integral x dA)^2 - 1
// over the whole surface (A its area: the preprint's template normalisation,
// which charges a body for surface that never touches) and over the touched
// surface only (A -> the area where x > 0), and by max x / mean x over the
// touched surface. V = 0 for uniform x; x uniform on a fraction phi of the
// surface and 0 elsewhere gives V = 1/phi - 1. For a cylinder of radius r
// and length L rolling on its side, every x below is uniform on the side:
// V_whole = A_caps / A_side = r / L, V_touched = 0, max/mean = 1.
//
// The quantities (line load q(s) from the load rule, E* the effective modulus):
//  - contact time density rho: the time P spends in contact per loop,
//    Hertz width: rho = 2 b / (|sigma'| R), b = sqrt(4 q R / (pi E*))
//    (K. L. Johnson, "Contact Mechanics", CUP 1985, eq. 4.43); geometric
//    width: rho = 1 / (|sigma'| R). Its V_whole is oracle/uniformity_score.h's
//    U_inf (computed here with the second moment in closed form,
//    integral rho^2 dA = integral 16 N / (pi E* |sigma'|) dt for Hertz).
//  - peak pressure p0 = sqrt(q E* / (pi R)) (Johnson eq. 4.45), taken per pass;
//    near a loaded end of the ruling it is held at its value `end_margin` of
//    the ruling inside that end (the rim's own stress is a separate, singular
//    problem: study/rims). It does not depend on how fast the body rolls.
//    With a pressure factor g, p0 g(lambda), lambda = q / (E* R) at the held
//    point: the plane-strain FEM's correction to line Hertz, which depends on
//    lambda alone (fem/scenes/slice_scaling.h); the accumulated pressure and
//    the damage follow it.
//  - accumulated pressure, the pressure-time integral of a pass: Hertz width
//    integral p dt = (pi / 4) p0 2 b / (|sigma'| R) with p0, b held as above;
//    geometric width p0 / (|sigma'| R) (the preprint's per-face sum of
//    sampled pressures, in the limit of fine faces and samples).
//  - Basquin damage of a pass (p0 / 2)^(-1 / b_B), b_B Basquin's exponent
//    (contact/fatigue.h) without the endurance limit, so that loads below the
//    limit still rank by damage; V is scale-free, so the strength does not
//    enter.
//
// Load rules (static through the centre of mass, the motion's own dynamic
// load, uniform) and the held ends: contact/ruling_load.h.
// Time laws: the free rolling of the trajectory, or a uniform rate (sigma'
// constant, the loop in the same time): the limit of a fast roll.
//
// Quadrature: the trapezoid rule between the trajectory's samples, and
// two-point Gauss-Legendre on `pieces` equal pieces along each ruling.
#include "contact/contact_parameters.h"
#include "contact/ruling_load.h"
#include "core/named_values.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_dynamics.h"
#include <Eigen/Core>
#include <array>
#include <limits>
#include <functional>
#include <string>

namespace rollcheck::contact
{
enum class TimeLaw
{
  free_rolling,
  uniform_rate
};
/// The time laws' names ("free", "uniform_rate").
const NamedValues<TimeLaw>& time_law_names();

struct ContinuumLoopSettings
{
  LoadRule load_rule = LoadRule::dynamic;
  TimeLaw time_law = TimeLaw::free_rolling;
  oracle::ContactWidthModel width = oracle::ContactWidthModel::hertz;
  double end_margin = 0.05;   ///< fraction of the ruling held at each loaded end (peak and accumulated pressure, damage)
  double normal_load_n = 100; ///< F (the preprint's)
  double effective_modulus_pa = 200e9 / (2 * (1 - 0.3 * 0.3)); ///< steel on steel
  double basquin_exponent = FatigueParameters{}.basquin_exponent;
  int pieces = 64;            ///< Gauss pieces along each ruling
  /// Only the accumulated pressure (what FEM-SDS reads): the other scores are
  /// left zero, and the damage's power and the widths are not computed.
  bool accumulated_pressure_only = false;
  /// g(lambda), lambda = q / (E* R), multiplying every peak pressure; empty: 1 (line Hertz).
  std::function<double(double)> pressure_factor = {};
  /// g(lambda) and a second factor g'(lambda) from one call: g as
  /// pressure_factor, g' scored beside it for the accumulated pressure alone
  /// (ContinuumMoments::second_factor, ContinuumLoopScores::
  /// accumulated_pressure_second_factor), as a pass with pressure_factor g'
  /// would score it, to the bit. One pass for a FEM table and the same
  /// table at half its nodes, whose look-ups share their logarithm. At most
  /// one of pressure_factor and pressure_factors is set.
  std::function<std::array<double, 2>(double)> pressure_factors = {};
};

/// The scores of one per-point quantity x.
struct ContinuumScore
{
  double whole = 0;        ///< V over the whole surface (below 1e-9: 0, uniform)
  double touched = 0;      ///< V over the touched surface (below 1e-9: 0, uniform)
  double peak_to_mean = 0; ///< max x / mean x over the touched surface
  double touched_area_m2 = 0;
};

struct ContinuumLoopScores
{
  ContinuumScore contact_time;
  ContinuumScore peak_pressure;
  ContinuumScore accumulated_pressure;
  ContinuumScore damage;
  double swept_area_m2 = 0;    ///< integral L R dsigma ds over the loop
  double surface_area_m2 = 0;  ///< A
  double peak_pressure_max_pa = 0;
  /// Least and largest lambda = q / (E* R) at which a peak pressure was taken
  /// (the range a pressure factor must cover).
  double load_ratio_min = 0, load_ratio_max = 0;
  /// The accumulated pressure under pressure_factors' second factor (zero without it).
  ContinuumScore accumulated_pressure_second_factor;
};

/// The accumulated pressure's integrals under a second pressure factor (its
/// touched area is area[2], the first factor's).
struct SecondFactorMoments
{
  double first = 0, second = 0, max = 0;
};

/// What the scores are made of: the integrals over the loop of each
/// quantity x over the surface the rulings sweep (integral 1[x > 0] dA,
/// x dA, x^2 dA, and max x; the swept area; the load ratios' range).
/// Those of disjoint parts of a window add up (+=: sums, and the largest and
/// least), so that the parts can be integrated apart (on MPI ranks).
struct ContinuumMoments
{
  static constexpr int quantities = 4; ///< contact time, peak pressure, accumulated pressure, damage
  std::array<double, quantities> area{}, first{}, second{}, max{};
  double swept = 0;
  double load_ratio_min = std::numeric_limits<double>::infinity(), load_ratio_max = 0;
  SecondFactorMoments second_factor; ///< with ContinuumLoopSettings::pressure_factors
  ContinuumMoments& operator+=(const ContinuumMoments& other);
};

/// The part-th of `parts` contiguous runs of a window's sample intervals
/// (as near equal in count as they divide); {0, 1} is the whole window.
struct WindowPart
{
  int part = 0;
  int parts = 1;
};

/// The moments of `part` of the loop [begin_s, end_s] of a line-contact
/// trajectory (the parts of a window add up to its whole). InputError for
/// point contact, an empty window, a part that does not exist or bad settings.
ContinuumMoments continuum_loop_moments(const oracle::RollingTrajectory& trajectory, double begin_s, double end_s,
                                        const RollingBodyMass& body, const ContinuumLoopSettings& settings,
                                        WindowPart part = {});
/// The scores of a whole window's moments on a body of area `surface_area_m2`
/// (ComputationError if nothing is touched).
ContinuumLoopScores continuum_loop_scores(const ContinuumMoments& moments, double surface_area_m2,
                                          const ContinuumLoopSettings& settings);

/// The scores of the loop [begin_s, end_s] of a line-contact trajectory on a
/// body of area `surface_area_m2`. InputError for point contact, an empty
/// window or bad settings; ComputationError if nothing is touched.
ContinuumLoopScores continuum_loop_scores(const oracle::RollingTrajectory& trajectory, double begin_s, double end_s,
                                          double surface_area_m2, const RollingBodyMass& body,
                                          const ContinuumLoopSettings& settings);
} // namespace rollcheck::contact
