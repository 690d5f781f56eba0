#pragma once
// Force control by displacement control: the top face's approach delta is
// adjusted until the computed force F_h(delta) meets the target F to a
// relative tolerance. The force grows like a power of the approach (Hertz:
// F ~ delta^(3/2) for a point, close to delta^1 for a line), so the update is
// a secant on log F against log delta:
//   delta_{k+1} = delta_k (F / F_k)^(1 / n_k),
// n_0 the Hertz exponent, then n_k = ln(F_k / F_{k-1}) / ln(delta_k / delta_{k-1}).
// Each solve starts from the previous solution with the new approach
// prescribed on the top face (see PenaltyContact::set_approach).
#include "fem/penalty_contact.h"
#include <functional>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
struct LoadControlReport
{
  double approach_m = 0;
  double force = 0;         ///< computed, N or N/m (reaction at the top face)
  double first_force = 0;   ///< at the first solve's approach: how far the start missed
  int load_steps = 0;       ///< Newton solves
  NewtonReport newton;      ///< summed over the solves
};

/// The classical estimate of the approach of a cylinder's centre (radius R,
/// Hertz half-width b) under a line load q: delta = q / (pi E*) L with
/// L = 2 ln(4 R / b) - 1, whose local exponent d ln q / d ln delta is
/// L / (L - 1). It starts the load control of the line contacts.
struct LineApproach
{
  double approach_m;
  double exponent;
};
LineApproach line_contact_approach(double load_n_per_m, double radius_m, double half_width_m,
                                   double effective_modulus_pa);

/// `first_approach_m` and `first_shift_m` start the first solve (see
/// PenaltyContact::start_translated); `exponent` is n_0. Each load step is
/// logged at `progress` (info for a long solve's progress on rank 0). The
/// force is the reaction at the top face, or what `measured_force` returns
/// (a part of the body's load, e.g. the line load at a section).
/// `on_step` is called after each solve with its force (a field time series).
LoadControlReport reach_force(PenaltyContact& problem, double target_force, double first_approach_m,
                              double first_shift_m, double exponent, double rtol,
                              spdlog::level::level_enum progress = spdlog::level::debug,
                              const std::function<double()>& measured_force = {},
                              const std::function<void(double)>& on_step = {});

/// The same from the problem's current state and approach (e.g. a finer
/// level started from the coarser level's solution,
/// PenaltyContact::start_interpolated).
LoadControlReport continue_to_force(PenaltyContact& problem, double target_force, double exponent, double rtol,
                                    spdlog::level::level_enum progress = spdlog::level::debug,
                                    const std::function<double()>& measured_force = {},
                                    const std::function<void(double)>& on_step = {});
} // namespace rollcheck::fem
