#include "oracle/rolling_study.h"
#include "core/error.h"
#include "geometry/mass_properties.h"
#include "oracle/contact_density.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/uniformity_score.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>
#include <string_view>

namespace rollcheck::oracle
{
namespace
{
void validate(const RollingStudyParameters& p)
{
  auto require_non_negative = [](double value, std::string_view what) {
    if (!std::isfinite(value) || value < 0)
      throw InputError(fmt::format("rolling study: {} must be finite and non-negative, got {}", what, value));
  };
  require_non_negative(p.rolling_energy, "barrier energy excess");
  require_non_negative(p.rolling_rate_rad_s, "rolling rate (rad/s)");
  require_non_negative(p.duration_s, "duration (s)");
  if (p.loops < 1)
    throw InputError(fmt::format("rolling study: loops must be at least 1, got {}", p.loops));
  if (p.face_subdivisions < 1)
    throw InputError(fmt::format("rolling study: face subdivisions must be at least 1, got {}", p.face_subdivisions));
  if (p.mass_points < 16)
    throw InputError(fmt::format("rolling study: mass points must be at least 16, got {}", p.mass_points));
  if (p.samples_per_loop < 0)
    throw InputError(fmt::format("rolling study: samples per loop must be non-negative, got {}", p.samples_per_loop));
  if (p.rolling_resistance_n_m_s > 0 && p.duration_s == 0)
    throw InputError("rolling study: with rolling resistance the loop period is unknown; give a duration (s)");
}

} // namespace

void require_line_contact(const geometry::BodySpec& spec)
{
  if (!spec.mesh_file.empty())
    throw InputError(fmt::format("mesh_file '{}' (--mesh): the exact body is needed (the circles whose hull it is), give --body "
                                 "oloid, paper-oloid, roller or cylinder",
                                 spec.mesh_file));
  if (spec.body == "roller" && spec.genome.n_circles != 2)
    throw InputError(fmt::format("roller of {} circles: the hull of two circles is needed (--circles 2)",
                                 spec.genome.n_circles));
  if (spec.body != "oloid" && spec.body != "paper-oloid" && spec.body != "roller" && spec.body != "cylinder")
    throw InputError(fmt::format("body '{}' is not the hull of two circles (oloid, paper-oloid, roller, cylinder), "
                                 "whose contact is a ruling; a sphere's point contact is `rollcheck hertz`",
                                 spec.body));
}

std::vector<Circle> line_contact_circles(const geometry::BodySpec& spec)
{
  require_line_contact(spec);
  const geometry::RollerGenome oloid{90.0, 1.0, 1.0, 2};
  if (spec.body == "oloid")
    return roller_circles(oloid, geometry::RollerFamily::centre_line, spec.radius_m);
  if (spec.body == "paper-oloid")
    return roller_circles(oloid, geometry::RollerFamily::paper, spec.radius_m);
  if (spec.body == "roller")
    return roller_circles(spec.genome, spec.family, spec.radius_m);
  return cylinder_rims(spec.radius_m, spec.height_m);
}

namespace
{

RollingParameters dynamics_parameters(const RollingStudyParameters& p, double duration_s)
{
  RollingParameters d;
  d.gravity_m_s2 = p.gravity_m_s2;
  d.rolling_resistance_n_m_s = p.rolling_resistance_n_m_s;
  d.duration_s = duration_s;
  d.sample_interval_s = p.sample_interval_s;
  d.relative_tolerance = p.relative_tolerance;
  return d;
}

/// The scored window: up to `loops` complete loops of the contact curve.
void set_window(RealRolling& run, int loops)
{
  const auto& samples = run.trajectory.samples;
  const double loop_angle = run.trajectory.loop_turning_angle_rad;
  auto time_at = [&](double sigma) { // first crossing, linearly interpolated
    for (std::size_t k = 0; k + 1 < samples.size(); ++k)
      if (samples[k + 1].turning_angle_rad >= sigma && samples[k].turning_angle_rad < sigma)
        return samples[k].time_s + (samples[k + 1].time_s - samples[k].time_s) *
                                       (sigma - samples[k].turning_angle_rad) /
                                       (samples[k + 1].turning_angle_rad - samples[k].turning_angle_rad);
    return std::numeric_limits<double>::quiet_NaN();
  };
  const double end_of_loops = time_at(loops * loop_angle);
  run.first_loop_end_s = time_at(loop_angle);
  run.scored_end_s = std::isfinite(end_of_loops) ? end_of_loops : samples.back().time_s;
  run.loops_completed = std::isfinite(end_of_loops) ? loops : samples.back().turning_angle_rad / loop_angle;
}

RealRolling sphere_rolling(const geometry::BodySpec& spec, const RollingStudyParameters& p)
{
  const Ellipsoid sphere{Eigen::Vector3d::Constant(spec.radius_m)};
  RealRolling run;
  run.initial_rate_rad_s = p.rolling_rate_rad_s > 0 ? p.rolling_rate_rad_s : std::sqrt(p.gravity_m_s2 / spec.radius_m);
  run.loop_period_s = 2 * std::numbers::pi / run.initial_rate_rad_s; // one turn closes the track
  const double duration = p.duration_s > 0 ? p.duration_s : p.loops * run.loop_period_s;
  run.trajectory = roll_on_point(sphere, mass_model_of_ellipsoid(sphere, p.mass_kg),
                                 {Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, run.initial_rate_rad_s, 0)},
                                 dynamics_parameters(p, duration));
  run.scored_end_s = run.trajectory.samples.back().time_s;
  run.first_loop_end_s = std::numeric_limits<double>::quiet_NaN();
  run.loops_completed = run.scored_end_s / run.loop_period_s;
  run.surface_area_m2 = 4 * std::numbers::pi * spec.radius_m * spec.radius_m;
  return run;
}
} // namespace

geometry::SurfaceMesh mass_mesh(const geometry::BodySpec& spec, int mass_points)
{
  geometry::BodySpec fine = spec;
  fine.points = fine.sections = mass_points;
  return geometry::make_body(fine);
}

Eigen::Vector3d rolling_centre_of_mass(const geometry::BodySpec& spec)
{
  return mass_model_of_mesh(mass_mesh(spec, RollingStudyParameters{}.mass_points), 1.0).centre_of_mass_m;
}

RollingMass rolling_mass(const geometry::BodySpec& spec, const RollingStudyParameters& p)
{
  const geometry::SurfaceMesh fine = mass_mesh(spec, p.mass_points);
  return {mass_model_of_mesh(fine, p.mass_kg), geometry::mass_properties(fine).area_m2};
}

RealRolling real_rolling(const geometry::BodySpec& spec, const RollingStudyParameters& p)
{
  validate(p);
  if (spec.body == "sphere")
    return sphere_rolling(spec, p);
  return real_rolling(spec, p, rolling_mass(spec, p));
}

RealRolling real_rolling(const geometry::BodySpec& spec, const RollingStudyParameters& p, const RollingMass& body_mass)
{
  validate(p);
  const TwoCircleBody body = two_circle_body(line_contact_circles(spec));
  const MassModel& mass = body_mass.mass;
  RealRolling run;
  run.surface_area_m2 = body_mass.surface_area_m2;
  run.circles = line_contact_circles(spec);
  run.mass = mass;

  // The stable ruling, the potential along the loop, and the initial rate.
  const Eigen::Vector3d rest = resting_direction(body, mass, contact_curve_point(body, -Eigen::Vector3d::UnitZ()));
  const ContactLoop loop = trace_contact_loop(body, rest, 2000);
  std::vector<double> inertia, height;
  for (const Eigen::Vector3d& u : loop.directions)
  {
    const Ruling r = ruling_at(body, u);
    inertia.push_back(ruling_inertia(r, mass));
    height.push_back(centre_of_mass_height(r, mass));
  }
  const double lowest = *std::min_element(height.begin(), height.end());
  const double highest = *std::max_element(height.begin(), height.end());
  const double mg = p.mass_kg * p.gravity_m_s2;
  const double size = std::max(body.first.radius_m, body.second.radius_m);
  if (p.rolling_rate_rad_s > 0)
    run.initial_rate_rad_s = p.rolling_rate_rad_s;
  else if (highest - lowest > 1e-9 * size)
    run.initial_rate_rad_s = std::sqrt(2 * (1 + p.rolling_energy) * mg * (highest - lowest) / inertia.front());
  else
    run.initial_rate_rad_s = std::sqrt(p.gravity_m_s2 / size);

  // Undamped loop period, the integral of dsigma / sigma'(sigma) with
  // sigma' = sqrt(2 (E - V) / J) (trapezoid rule, periodic).
  const double energy = 0.5 * inertia.front() * run.initial_rate_rad_s * run.initial_rate_rad_s + mg * height.front();
  const double step = loop.turning_angle_rad / static_cast<double>(loop.directions.size());
  for (std::size_t k = 0; k < loop.directions.size() && std::isfinite(run.loop_period_s); ++k)
  {
    const double kinetic = energy - mg * height[k];
    run.loop_period_s = kinetic > 0 ? run.loop_period_s + step / std::sqrt(2 * kinetic / inertia[k])
                                    : std::numeric_limits<double>::infinity();
  }
  if (!std::isfinite(run.loop_period_s))
  {
    run.loop_period_s = 0;
    if (p.duration_s == 0)
      throw InputError(fmt::format("rolling study: at {:.4g} rad/s the {} cannot roll over its potential barrier; "
                                   "raise the rate or give a duration (s)",
                                   run.initial_rate_rad_s, spec.body));
  }
  const double duration = p.duration_s > 0 ? p.duration_s : 1.02 * p.loops * run.loop_period_s;
  RollingParameters dynamics = dynamics_parameters(p, duration);
  if (p.samples_per_loop > 0 && run.loop_period_s > 0)
    dynamics.sample_interval_s = run.loop_period_s / static_cast<double>(p.samples_per_loop);
  run.trajectory = roll_on_ruling(body, mass, {rest, run.initial_rate_rad_s, 0}, dynamics);
  set_window(run, p.loops);
  return run;
}

RollingStudyResult score_real_rolling(const RealRolling& run, const geometry::SurfaceMesh& body_mesh,
                                      const RollingStudyParameters& p)
{
  validate(p);
  const geometry::SurfaceMesh mesh = subdivide_faces(body_mesh, p.face_subdivisions);
  const ContactDensity density = contact_density(mesh, run.trajectory, p.contact_width, run.scored_end_s);
  const UniformityScore score = uniformity_score(density.measure, density.face_areas_m2);
  RollingStudyResult result;
  const bool line = run.trajectory.mode == ContactMode::line;
  result.contact = line ? "line" : "point";
  result.faces = static_cast<long>(mesh.faces.rows());
  result.uniformity = score.normalised_variance;
  result.coverage = score.coverage;
  result.max_over_mean = score.max_over_mean;
  result.continuum_uniformity =
      line && std::isfinite(run.first_loop_end_s)
          ? continuum_uniformity(run.trajectory, 0, run.first_loop_end_s, run.surface_area_m2, p.contact_width)
          : std::numeric_limits<double>::quiet_NaN();
  result.initial_rate_rad_s = run.initial_rate_rad_s;
  result.loop_period_s = run.loop_period_s;
  result.loops_completed = run.loops_completed;
  result.scored_time_s = run.scored_end_s;
  result.contact_held = run.trajectory.contact_held;
  result.max_energy_error = run.trajectory.max_energy_error;
  result.centre_of_pressure_min = std::numeric_limits<double>::infinity();
  result.centre_of_pressure_max = -std::numeric_limits<double>::infinity();
  for (const RollingSample& s : run.trajectory.samples)
    if (s.time_s <= run.scored_end_s)
    {
      result.centre_of_pressure_min = std::min(result.centre_of_pressure_min, s.centre_of_pressure);
      result.centre_of_pressure_max = std::max(result.centre_of_pressure_max, s.centre_of_pressure);
      result.friction_ratio_max = std::max(result.friction_ratio_max, s.friction_ratio);
    }
  return result;
}

RollingStudyResult rolling_study(const geometry::BodySpec& spec, const RollingStudyParameters& p)
{
  return score_real_rolling(real_rolling(spec, p), geometry::make_body(spec), p);
}
} // namespace rollcheck::oracle
