// The sections' share of the load (study/whole_body/section_share.h).
#include "study/whole_body/section_share.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/petsc_session.h"
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::study::whole_body
{
namespace
{
/// A section's load against its approach through its last two solves,
/// q = Q (delta / D)^n.
struct PowerLaw
{
  double approach_m = 0, load_n_per_m = 0, exponent = 1.1;
  double load(double delta) const { return load_n_per_m * std::pow(delta / approach_m, exponent); }
};

/// delta_0 and t that balance F and the moment about x_G on the model
/// (Newton on the 2 x 2 system, started from `start`).
Eigen::Vector2d balance(const std::vector<PowerLaw>& laws, const std::vector<double>& x, double x_G, double weight,
                        double force_n, Eigen::Vector2d start)
{
  Eigen::Vector2d v = start;
  for (int iteration = 0; iteration < 50; ++iteration)
  {
    Eigen::Vector2d residual(-force_n, 0);
    Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();
    for (std::size_t k = 0; k < laws.size(); ++k)
    {
      const double arm = x[k] - x_G, delta = v[0] + v[1] * arm;
      if (!(delta > 0))
        throw ComputationError(fmt::format("section load rule: the tilt {:.4g} rad lifts the section at {:.6g} m "
                                           "off the plane (approach {:.4g} m at x_G)",
                                           v[1], x[k], v[0]));
      const double q = laws[k].load(delta), dq = laws[k].exponent * q / delta;
      residual += weight * Eigen::Vector2d(q, q * arm);
      jacobian += weight * dq * Eigen::Matrix2d{{1, arm}, {arm, arm * arm}};
    }
    const Eigen::Vector2d step = jacobian.fullPivLu().solve(-residual);
    // Halved while it would lift a section: the loads are positive powers.
    double scale = 1;
    auto lifts = [&](double s) {
      for (const double xk : x)
        if (!(v[0] + s * step[0] + (v[1] + s * step[1]) * (xk - x_G) > 0))
          return true;
      return false;
    };
    while (lifts(scale) && scale > 1e-6)
      scale *= 0.5;
    v += scale * step;
    if (std::abs(step[0]) <= 1e-12 * v[0] && std::abs(residual[0]) <= 1e-12 * force_n)
      break;
  }
  return v;
}
} // namespace

double SectionShare::load_at(double x_m) const
{
  const std::vector<double>& xs = stations_m;
  const std::vector<double>& qs = load_n_per_m;
  if (xs.size() < 2)
    return qs.empty() ? 0.0 : qs.front();
  std::size_t i = std::upper_bound(xs.begin(), xs.end(), x_m) - xs.begin();
  i = std::clamp<std::size_t>(i, 1, xs.size() - 1);
  const double f = (x_m - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return qs[i - 1] + f * (qs[i] - qs[i - 1]);
}

SectionShare section_share(MPI_Comm comm, const fem::MappedBodyPose& pose, double force_n,
                                  double centre_of_mass_along_m, double first_approach_m,
                                  const fem::WholeBodySizes& sizes, const fem::SectionSettings& section,
                                  const SectionShareSettings& settings)
{
  const double L = pose.length_m, x_G = centre_of_mass_along_m;
  if (!(settings.stations >= 4) || !(settings.tolerance > 0) || !(settings.max_passes >= 2))
    throw InputError(fmt::format("section load rule: need at least 4 stations ({}), a positive tolerance ({}) and at "
                                 "least 2 passes ({})",
                                 settings.stations, settings.tolerance, settings.max_passes));
  if (!(force_n > 0) || !(x_G > 0 && x_G < L) || !(first_approach_m > 0))
    throw InputError(fmt::format("section load rule: need F > 0 ({} N), x_G on the ruling ({} m of {} m) and a "
                                 "first approach > 0 ({} m)",
                                 force_n, x_G, L, first_approach_m));
  fem::ensure_petsc();
  const auto start = std::chrono::steady_clock::now();
  const bool log = fem::world_rank() == 0;
  const std::size_t n = static_cast<std::size_t>(settings.stations);
  const double weight = L / static_cast<double>(n);
  SectionShare rule;
  for (std::size_t k = 0; k < n; ++k)
    rule.stations_m.push_back((static_cast<double>(k) + 0.5) * weight);
  std::vector<PowerLaw> laws(n);
  std::vector<double> approaches(n, first_approach_m);
  Eigen::Vector2d balanced(first_approach_m, 0);
  bool converged = false;
  for (int pass = 1; pass <= settings.max_passes; ++pass)
  {
    const std::vector<fem::SectionFem> solved
        = fem::solve_sections(comm, pose, rule.stations_m, approaches, sizes, section);
    rule.passes = pass;
    rule.section_dofs = solved.front().dofs;
    rule.last_change = 0;
    for (std::size_t k = 0; k < n; ++k)
    {
      const double q = solved[k].load_n_per_m;
      if (!(q > 0))
        throw ComputationError(fmt::format("section load rule: the section at {:.6g} m carries no load at approach "
                                           "{:.6g} m",
                                           rule.stations_m[k], approaches[k]));
      if (pass > 1)
      {
        rule.last_change = std::max(rule.last_change, std::abs(q / laws[k].load(approaches[k]) - 1));
        if (approaches[k] != laws[k].approach_m)
          laws[k].exponent = std::log(q / laws[k].load_n_per_m) / std::log(approaches[k] / laws[k].approach_m);
      }
      laws[k].approach_m = approaches[k];
      laws[k].load_n_per_m = q;
    }
    rule.load_n_per_m.clear();
    rule.peak_pressure_pa.clear();
    for (const fem::SectionFem& f : solved)
    {
      rule.load_n_per_m.push_back(f.load_n_per_m);
      rule.peak_pressure_pa.push_back(f.peak_pressure_pa);
    }
    rule.approach_m = approaches;
    if (log)
      spdlog::info("section load rule pass {}: approach {:.6e} m at x_G, tilt {:.4e} rad, loads {:.1f} .. {:.1f} N/m, "
                   "largest change against the model {:.2e}",
                   pass, balanced[0], balanced[1], *std::min_element(rule.load_n_per_m.begin(), rule.load_n_per_m.end()),
                   *std::max_element(rule.load_n_per_m.begin(), rule.load_n_per_m.end()), rule.last_change);
    if (pass > 1 && rule.last_change <= settings.tolerance)
    {
      converged = true;
      break;
    }
    balanced = balance(laws, rule.stations_m, x_G, weight, force_n, balanced);
    for (std::size_t k = 0; k < n; ++k)
      approaches[k] = balanced[0] + balanced[1] * (rule.stations_m[k] - x_G);
  }
  if (!converged)
    throw ComputationError(fmt::format("section load rule: the sections' loads still differ by {:.2e} from the "
                                       "model's after {} passes (tolerance {:.1e})",
                                       rule.last_change, rule.passes, settings.tolerance));
  // The balance the last solves' approaches came from.
  rule.approach_at_centre_of_mass_m = balanced[0];
  rule.tilt_rad = balanced[1];
  double moment = 0;
  for (std::size_t k = 0; k < n; ++k)
  {
    rule.force_n += weight * rule.load_n_per_m[k];
    moment += weight * rule.load_n_per_m[k] * rule.stations_m[k];
  }
  rule.centre_of_pressure_m = moment / rule.force_n;
  rule.wall_s = fem::wall_seconds_since(comm, start);
  return rule;
}

nlohmann::json to_json(const SectionShare& rule)
{
  nlohmann::json stations = nlohmann::json::array();
  for (std::size_t k = 0; k < rule.stations_m.size(); ++k)
    stations.push_back({{"position_m", rule.stations_m[k]},
                        {"approach_m", rule.approach_m[k]},
                        {"load_n_per_m", rule.load_n_per_m[k]},
                        {"peak_pressure_pa", rule.peak_pressure_pa[k]}});
  return {{"stations", stations},
          {"approach_at_centre_of_mass_m", rule.approach_at_centre_of_mass_m},
          {"tilt_rad", rule.tilt_rad},
          {"force_n", rule.force_n},
          {"centre_of_pressure_m", rule.centre_of_pressure_m},
          {"passes", rule.passes},
          {"last_change", rule.last_change},
          {"section_dofs", rule.section_dofs},
          {"wall_s", rule.wall_s}};
}
} // namespace rollcheck::study::whole_body
