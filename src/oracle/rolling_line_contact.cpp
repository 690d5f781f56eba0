// Rolling dynamics on a ruling (rolling_dynamics.h, "Line contact"): the
// two-circle body, its contact curve h_1(u) = h_2(u) and rulings, the loop of
// the curve and the resting ruling, and the rolling motion about the ruling
// with its end loads and centre of pressure.
#include "core/error.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/rolling_dynamics_internal.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::oracle
{
namespace
{
using detail::require_positive;
constexpr double pi = std::numbers::pi;
const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();

double body_size(const TwoCircleBody& body)
{
  return std::max(body.first.radius_m, body.second.radius_m) +
         (body.second.centre_m - body.first.centre_m).norm();
}

/// h_2(u) - h_1(u) and its gradient s_2 - s_1.
double curve_function(const TwoCircleBody& body, const Eigen::Vector3d& u)
{
  return circle_support(body.second, u) - circle_support(body.first, u);
}

/// The ruling at u as it is (no projection), u unit.
Ruling raw_ruling(const TwoCircleBody& body, const Eigen::Vector3d& u)
{
  Ruling r;
  r.direction = u;
  r.start_m = circle_support_point(body.first, u);
  r.end_m = circle_support_point(body.second, u);
  const Eigen::Vector3d span = r.end_m - r.start_m;
  r.length_m = span.norm();
  if (!(r.length_m > 1e-12 * body_size(body)))
    throw ComputationError("rolling: the two circles meet at the contact, the ruling has no length");
  r.axis = span / r.length_m;
  r.tangent = u.cross(r.axis).normalized();
  r.start_rate_m = circle_support_hessian(body.first, u) * r.tangent;
  r.end_rate_m = circle_support_hessian(body.second, u) * r.tangent;
  r.start_radius_m = r.start_rate_m.dot(r.tangent);
  r.end_radius_m = r.end_rate_m.dot(r.tangent);
  return r;
}

void project_onto_curve(const TwoCircleBody& body, Eigen::Vector3d& u)
{
  const double size = body_size(body);
  u.normalize();
  for (int iteration = 0; iteration < 30; ++iteration)
  {
    const double f = curve_function(body, u);
    if (std::abs(f) <= 1e-15 * size)
      return;
    const Eigen::Vector3d gradient =
        circle_support_point(body.second, u) - circle_support_point(body.first, u);
    const Eigen::Vector3d tangential = gradient - u * gradient.dot(u);
    if (!(tangential.squaredNorm() > 0))
      break;
    u = (u - f * tangential / tangential.squaredNorm()).normalized();
  }
  if (std::abs(curve_function(body, u)) > 1e-9 * size)
    throw ComputationError("rolling: the direction cannot be projected onto the contact curve h1 = h2");
}

/// du/dsigma = T(u), one classical Runge-Kutta step of turning angle h, then projection.
Eigen::Vector3d curve_step(const TwoCircleBody& body, const Eigen::Vector3d& u, double h)
{
  auto tangent = [&](const Eigen::Vector3d& v) { return raw_ruling(body, v.normalized()).tangent; };
  const Eigen::Vector3d k1 = tangent(u);
  const Eigen::Vector3d k2 = tangent(u + h / 2 * k1);
  const Eigen::Vector3d k3 = tangent(u + h / 2 * k2);
  const Eigen::Vector3d k4 = tangent(u + h * k3);
  Eigen::Vector3d next = u + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  project_onto_curve(body, next);
  return next;
}

/// Turning angle of the closed loop through u0 (steps of about `h`).
double loop_length(const TwoCircleBody& body, const Eigen::Vector3d& u0, double h)
{
  const Eigen::Vector3d t0 = raw_ruling(body, u0).tangent;
  Eigen::Vector3d u = u0;
  double travelled = 0, previous_distance = 0;
  const long max_steps = static_cast<long>(std::ceil(20 * pi / h)) + 10;
  for (long step = 0; step < max_steps; ++step)
  {
    const Eigen::Vector3d next = curve_step(body, u, h);
    const double distance = (next - u0).dot(t0);
    if (travelled > 4 * h && previous_distance < 0 && distance >= 0 && (next - u0).norm() < 10 * h)
      return travelled + h * (-previous_distance) / (distance - previous_distance);
    previous_distance = distance;
    travelled += h;
    u = next;
  }
  throw ComputationError("rolling: the contact curve does not close within 10 turns");
}

struct LineState
{
  // u (3), rate, sigma, heading, x, y, dissipated work
  static constexpr int size = 9;
};

Eigen::Matrix3d line_rotation(const Ruling& r, double heading)
{
  Eigen::Matrix3d to_frame; // rows: b, -T, -u (ruling to e_x, body up to e_z)
  to_frame.row(0) = r.axis.transpose();
  to_frame.row(1) = -r.tangent.transpose();
  to_frame.row(2) = -r.direction.transpose();
  return Eigen::AngleAxisd(heading, up).toRotationMatrix() * to_frame;
}

struct LineTerms
{
  Ruling ruling;
  Eigen::Vector3d axis_rate; ///< db/dsigma
  double inertia;            ///< J
  double inertia_rate;       ///< dJ/dsigma
  double potential;          ///< V
  double potential_rate;     ///< dV/dsigma
};

LineTerms line_terms(const TwoCircleBody& body, const MassModel& mass, double gravity, const Eigen::Vector3d& u)
{
  LineTerms t;
  t.ruling = raw_ruling(body, u);
  const Ruling& r = t.ruling;
  const Eigen::Vector3d span_rate = r.end_rate_m - r.start_rate_m;
  t.axis_rate = (span_rate - r.axis * r.axis.dot(span_rate)) / r.length_m;
  const Eigen::Vector3d arm = r.start_m - mass.centre_of_mass_m;
  const Eigen::Vector3d arm_x_axis = arm.cross(r.axis);
  t.inertia = ruling_inertia(r, mass);
  t.inertia_rate = 2 * t.axis_rate.dot(mass.inertia_kg_m2 * r.axis) +
                   2 * mass.mass_kg * arm_x_axis.dot(r.start_rate_m.cross(r.axis) + arm.cross(t.axis_rate));
  t.potential = mass.mass_kg * gravity * centre_of_mass_height(r, mass);
  t.potential_rate = mass.mass_kg * gravity * arm.dot(r.tangent);
  return t;
}

RollingSample line_sample(const TwoCircleBody& body, const MassModel& mass, const RollingParameters& p,
                          const Eigen::VectorXd& y, double time)
{
  const LineTerms t = line_terms(body, mass, p.gravity_m_s2, y.head<3>().normalized());
  const Ruling& r = t.ruling;
  const double rate = y[3];
  const double acceleration =
      -(0.5 * t.inertia_rate * rate * rate + t.potential_rate + p.rolling_resistance_n_m_s * rate) / t.inertia;
  RollingSample s;
  s.time_s = time;
  s.rotation = line_rotation(r, y[5]);
  const Eigen::Vector3d axis = s.rotation * r.axis;
  const Eigen::Vector3d arm = s.rotation * (r.start_m - mass.centre_of_mass_m);
  s.angular_velocity_rad_s = rate * axis;
  s.centre_of_mass_m = Eigen::Vector3d(y[6], y[7], -arm.z());
  s.contact_start_m = r.start_m;
  s.contact_end_m = r.end_m;
  s.start_radius_m = r.start_radius_m;
  s.end_radius_m = r.end_radius_m;
  s.turning_angle_rad = y[4];
  s.rolling_rate_rad_s = rate;
  s.kinetic_energy_j = 0.5 * t.inertia * rate * rate;
  s.potential_energy_j = t.potential;
  s.dissipated_energy_j = y[8];

  // Contact force and its moment, from the motion (Newton-Euler).
  const Eigen::Vector3d& omega = s.angular_velocity_rad_s;
  const Eigen::Vector3d omega_rate = acceleration * axis + rate * rate * (s.rotation * t.axis_rate);
  const Eigen::Vector3d arm_rate = omega.cross(arm) + rate * (s.rotation * r.start_rate_m);
  const Eigen::Vector3d acceleration_cm = arm_rate.cross(omega) + arm.cross(omega_rate);
  const Eigen::Vector3d force = mass.mass_kg * (acceleration_cm + p.gravity_m_s2 * up);
  const Eigen::Matrix3d inertia_world = s.rotation * mass.inertia_kg_m2 * s.rotation.transpose();
  const Eigen::Vector3d moment_cm = inertia_world * omega_rate + omega.cross(inertia_world * omega);
  const Eigen::Vector3d moment_start = moment_cm - arm.cross(force);
  const double end_load = -moment_start.dot(up.cross(axis)) / r.length_m;
  s.normal_force_n = force.z();
  s.centre_of_pressure = end_load / force.z();
  s.friction_ratio = force.head<2>().norm() / force.z();
  return s;
}
} // namespace

TwoCircleBody two_circle_body(std::span<const Circle> circles)
{
  if (circles.size() != 2)
    throw InputError(fmt::format("rolling on a ruling needs exactly two circles, got {}", circles.size()));
  for (const Circle& c : circles)
  {
    require_positive(c.radius_m, "circle radius (m)");
    if (!c.centre_m.allFinite() || std::abs(c.normal.norm() - 1) > 1e-9)
      throw InputError("rolling: circle centre not finite or normal not unit");
  }
  if ((circles[1].centre_m - circles[0].centre_m).norm() <= 1e-9 * circles[0].radius_m)
    throw InputError("rolling: the two circles are concentric; their hull has no line contact to roll on");
  return {circles[0], circles[1]};
}

double ruling_inertia(const Ruling& ruling, const MassModel& mass)
{
  const Eigen::Vector3d arm = ruling.start_m - mass.centre_of_mass_m;
  return ruling.axis.dot(mass.inertia_kg_m2 * ruling.axis) + mass.mass_kg * arm.cross(ruling.axis).squaredNorm();
}

double centre_of_mass_height(const Ruling& ruling, const MassModel& mass)
{
  return (ruling.start_m - mass.centre_of_mass_m).dot(ruling.direction);
}

Ruling ruling_at(const TwoCircleBody& body, const Eigen::Vector3d& direction)
{
  if (!direction.allFinite() || !(direction.norm() > 0))
    throw InputError("ruling: the direction must be finite and non-zero");
  Eigen::Vector3d u = direction;
  project_onto_curve(body, u);
  return raw_ruling(body, u);
}

Eigen::Vector3d contact_curve_point(const TwoCircleBody& body, const Eigen::Vector3d& hint)
{
  if (!hint.allFinite() || !(hint.norm() > 0))
    throw InputError("contact curve: the hint direction must be finite and non-zero");
  const Eigen::Vector3d u0 = hint.normalized();
  const double f0 = curve_function(body, u0);
  const double size = body_size(body);
  if (std::abs(f0) <= 1e-15 * size)
    return u0;
  // Candidates of opposite sign: a Fibonacci sphere of directions.
  constexpr int candidates = 4096;
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  double best_cos = -2;
  for (int k = 0; k < candidates; ++k)
  {
    const double z = 1 - (2.0 * k + 1) / candidates;
    const double rho = std::sqrt(1 - z * z), phi = k * pi * (3 - std::sqrt(5.0));
    const Eigen::Vector3d v(rho * std::cos(phi), rho * std::sin(phi), z);
    if (curve_function(body, v) * f0 < 0 && v.dot(u0) > best_cos)
    {
      best = v;
      best_cos = v.dot(u0);
    }
  }
  if (best_cos < -1)
    throw ComputationError("contact curve: one circle never reaches the support, the hull has no ruling");
  // Bisection on the great-circle arc from u0 to best.
  Eigen::Vector3d a = u0, b = best;
  for (int iteration = 0; iteration < 80; ++iteration)
  {
    const Eigen::Vector3d mid = (a + b).normalized();
    (curve_function(body, mid) * f0 > 0 ? a : b) = mid;
  }
  Eigen::Vector3d u = (a + b).normalized();
  project_onto_curve(body, u);
  return u;
}

ContactLoop trace_contact_loop(const TwoCircleBody& body, const Eigen::Vector3d& start, int points)
{
  if (points < 8)
    throw InputError(fmt::format("contact loop: at least 8 points, got {}", points));
  Eigen::Vector3d u = start;
  project_onto_curve(body, u);
  ContactLoop loop;
  loop.turning_angle_rad = loop_length(body, u, 2 * pi / points);
  const double h = loop.turning_angle_rad / points;
  loop.directions.reserve(static_cast<std::size_t>(points));
  for (int k = 0; k < points; ++k)
  {
    loop.directions.push_back(u);
    u = curve_step(body, u, h);
  }
  return loop;
}

Eigen::Vector3d resting_direction(const TwoCircleBody& body, const MassModel& mass, const Eigen::Vector3d& start)
{
  const ContactLoop loop = trace_contact_loop(body, start, 720);
  auto height = [&](const Eigen::Vector3d& u) { return centre_of_mass_height(raw_ruling(body, u), mass); };
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < loop.directions.size(); ++k)
    if (height(loop.directions[k]) < height(loop.directions[lowest]))
      lowest = k;
  const double h = loop.turning_angle_rad / static_cast<double>(loop.directions.size());
  const std::size_t before = (lowest + loop.directions.size() - 1) % loop.directions.size();
  const Eigen::Vector3d origin = loop.directions[before];
  auto at = [&](double sigma) { // u at turning angle sigma past `origin`, sigma in [0, 2h]
    Eigen::Vector3d u = origin;
    for (int k = 0; k < 4; ++k)
      u = curve_step(body, u, sigma / 4);
    return u;
  };
  const double golden = (std::sqrt(5.0) - 1) / 2;
  double lo = 0, hi = 2 * h;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  double f1 = height(at(x1)), f2 = height(at(x2));
  for (int iteration = 0; iteration < 60; ++iteration)
  {
    if (f1 < f2)
    {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - golden * (hi - lo), f1 = height(at(x1));
    }
    else
    {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + golden * (hi - lo), f2 = height(at(x2));
    }
  }
  return at((lo + hi) / 2);
}

RollingTrajectory roll_on_ruling(const TwoCircleBody& body, const MassModel& mass, const LineContactStart& start,
                                 const RollingParameters& p)
{
  detail::validate(p);
  detail::validate(mass);
  if (!std::isfinite(start.rolling_rate_rad_s) || !std::isfinite(start.heading_rad))
    throw InputError("rolling: initial rolling rate and heading must be finite");
  Eigen::Vector3d u0 = start.direction;
  if (!u0.allFinite() || !(u0.norm() > 0))
    throw InputError("rolling: the initial contact direction must be finite and non-zero");
  project_onto_curve(body, u0);

  RollingTrajectory trajectory;
  trajectory.mode = ContactMode::line;
  trajectory.loop_turning_angle_rad = loop_length(body, u0, 2 * pi / 2000);

  const double size = body_size(body);
  const double natural_rate = std::sqrt(p.gravity_m_s2 / size);
  Eigen::VectorXd y(LineState::size);
  y << u0, start.rolling_rate_rad_s, 0, start.heading_rad, 0, 0, 0;
  const double c = p.rolling_resistance_n_m_s;
  auto rhs = [&](const Eigen::VectorXd& state) {
    const Eigen::Vector3d u = state.head<3>().normalized();
    const LineTerms t = line_terms(body, mass, p.gravity_m_s2, u);
    const double rate = state[3];
    const double acceleration =
        -(0.5 * t.inertia_rate * rate * rate + t.potential_rate + c * rate) / t.inertia;
    const Eigen::Matrix3d rotation = line_rotation(t.ruling, state[5]);
    const Eigen::Vector3d velocity =
        rate * (rotation * (t.ruling.start_m - mass.centre_of_mass_m).cross(t.ruling.axis));
    Eigen::VectorXd d(LineState::size);
    d << rate * t.ruling.tangent, acceleration, rate, -rate * t.axis_rate.dot(t.ruling.tangent), velocity.x(),
        velocity.y(), c * rate * rate;
    return d;
  };
  auto project = [&](Eigen::VectorXd& state) {
    Eigen::Vector3d u = state.head<3>();
    project_onto_curve(body, u);
    state.head<3>() = u;
  };
  const double energy_scale = mass.mass_kg * p.gravity_m_s2 * size;
  Eigen::VectorXd floor(LineState::size);
  floor << 1, 1, 1, std::max(std::abs(start.rolling_rate_rad_s), natural_rate), 1, 1, size, size, energy_scale;
  detail::Dopri5 integrator(rhs, project, floor, p.relative_tolerance, p.sample_interval_s / 4);

  detail::run_sampled(integrator, y, p, trajectory, [&](const Eigen::VectorXd& state, double time) {
    return line_sample(body, mass, p, state, time);
  });
  return trajectory;
}
} // namespace rollcheck::oracle
