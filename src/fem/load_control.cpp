#include "fem/load_control.h"
#include "core/error.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
LineApproach line_contact_approach(double load_n_per_m, double radius_m, double half_width_m,
                                   double effective_modulus_pa)
{
  const double log_term = 2 * std::log(4 * radius_m / half_width_m) - 1;
  return {load_n_per_m / (std::numbers::pi * effective_modulus_pa) * log_term, log_term / (log_term - 1)};
}

LoadControlReport reach_force(PenaltyContact& problem, double target, double first_approach_m,
                              double first_shift_m, double exponent, double rtol, spdlog::level::level_enum progress,
                              const std::function<double()>& measured_force,
                              const std::function<void(double)>& on_step)
{
  problem.start_translated(first_shift_m, first_approach_m);
  return continue_to_force(problem, target, exponent, rtol, progress, measured_force, on_step);
}

LoadControlReport continue_to_force(PenaltyContact& problem, double target, double exponent, double rtol,
                                    spdlog::level::level_enum progress, const std::function<double()>& measured_force,
                                    const std::function<void(double)>& on_step)
{
  constexpr int max_steps = 20;
  LoadControlReport report;
  double previous_approach = 0, previous_force = 0;
  for (int step = 1; step <= max_steps; ++step)
  {
    const NewtonReport newton = problem.solve();
    report.newton.newton_iterations += newton.newton_iterations;
    report.newton.krylov_iterations += newton.krylov_iterations;
    report.newton.preconditioner_setups += newton.preconditioner_setups;
    report.newton.line_search_halvings += newton.line_search_halvings;
    report.newton.final_relative_increment = newton.final_relative_increment;
    report.newton.assembly_s += newton.assembly_s;
    report.newton.solve_s += newton.solve_s;
    report.load_steps = step;
    report.approach_m = problem.approach_m();
    report.force = measured_force ? measured_force() : problem.reaction_force_n();
    if (step == 1)
      report.first_force = report.force;
    spdlog::log(progress, "load step {}: approach {:.9e} m, force {:.6g} of {:.6g}, {} Newton iterations", step,
                report.approach_m, report.force, target, newton.newton_iterations);
    if (!(report.force > 0))
      throw ComputationError(fmt::format("load control: no contact force at approach {:.6e} m", report.approach_m));
    if (on_step)
      on_step(report.force);
    if (std::abs(report.force - target) <= rtol * target)
      return report;
    if (step > 1 && report.approach_m != previous_approach && report.force != previous_force)
      exponent = std::clamp(std::log(report.force / previous_force) / std::log(report.approach_m / previous_approach),
                            0.5, 3.0);
    previous_approach = report.approach_m;
    previous_force = report.force;
    problem.set_approach(report.approach_m * std::pow(target / report.force, 1.0 / exponent));
  }
  throw ComputationError(fmt::format("load control did not reach {:.6g} to {:.1e} in {} solves (last {:.9g})", target,
                                     rtol, max_steps, report.force));
}
} // namespace rollcheck::fem
