#include "oracle/rolling_dynamics.h"
#include "core/error.h"
#include "geometry/mass_properties.h"
#include <Eigen/Geometry>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <numbers>

namespace rollcheck::oracle
{
namespace
{
constexpr double pi = std::numbers::pi;
const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();

void require_positive(double value, const char* what)
{
  if (!std::isfinite(value) || value <= 0)
    throw InputError(fmt::format("rolling: {} must be positive and finite, got {}", what, value));
}

void validate(const RollingParameters& p)
{
  require_positive(p.gravity_m_s2, "gravity (m/s^2)");
  require_positive(p.duration_s, "duration (s)");
  require_positive(p.sample_interval_s, "sample interval (s)");
  require_positive(p.relative_tolerance, "relative tolerance");
  require_positive(p.energy_tolerance, "energy tolerance");
  if (!std::isfinite(p.rolling_resistance_n_m_s) || p.rolling_resistance_n_m_s < 0)
    throw InputError(fmt::format("rolling: rolling resistance (N m s) must be finite and non-negative, got {}",
                                 p.rolling_resistance_n_m_s));
  if (p.duration_s / p.sample_interval_s > 1e8)
    throw InputError("rolling: more than 1e8 samples (duration / sample interval)");
}

void validate(const MassModel& mass)
{
  require_positive(mass.mass_kg, "mass (kg)");
  if (!mass.centre_of_mass_m.allFinite() || !mass.inertia_kg_m2.allFinite())
    throw InputError("rolling: centre of mass or inertia is not finite");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(mass.inertia_kg_m2);
  if (eig.eigenvalues().minCoeff() <= 0)
    throw InputError("rolling: inertia tensor is not positive definite");
}

// ---------------------------------------------------------------------------
// Dormand-Prince 5(4), autonomous, with a projection after each accepted step.
class Dopri5
{
public:
  using Rhs = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
  using Project = std::function<void(Eigen::VectorXd&)>;

  Dopri5(Rhs rhs, Project project, Eigen::VectorXd floor, double rtol, double initial_step)
      : rhs_(std::move(rhs)), project_(std::move(project)), floor_(std::move(floor)), rtol_(rtol), h_(initial_step)
  {
  }

  /// Advances y by `duration` (s), landing exactly on its end.
  void advance(Eigen::VectorXd& y, double duration)
  {
    static constexpr double a21 = 1.0 / 5, a31 = 3.0 / 40, a32 = 9.0 / 40, a41 = 44.0 / 45, a42 = -56.0 / 15,
                            a43 = 32.0 / 9, a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                            a54 = -212.0 / 729, a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                            a64 = 49.0 / 176, a65 = -5103.0 / 18656, b1 = 35.0 / 384, b3 = 500.0 / 1113,
                            b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84, e1 = 71.0 / 57600,
                            e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                            e7 = -1.0 / 40;
    double t = 0;
    while (t < duration)
    {
      const bool last = h_ >= duration - t;
      const double h = last ? duration - t : h_;
      const Eigen::VectorXd k1 = rhs_(y);
      const Eigen::VectorXd k2 = rhs_(y + h * a21 * k1);
      const Eigen::VectorXd k3 = rhs_(y + h * (a31 * k1 + a32 * k2));
      const Eigen::VectorXd k4 = rhs_(y + h * (a41 * k1 + a42 * k2 + a43 * k3));
      const Eigen::VectorXd k5 = rhs_(y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4));
      const Eigen::VectorXd k6 = rhs_(y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5));
      Eigen::VectorXd next = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
      const Eigen::VectorXd k7 = rhs_(next);
      const Eigen::VectorXd error = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
      double norm = 0;
      for (Eigen::Index i = 0; i < y.size(); ++i)
      {
        const double scale = rtol_ * std::max({floor_[i], std::abs(y[i]), std::abs(next[i])});
        norm += (error[i] / scale) * (error[i] / scale);
      }
      norm = std::sqrt(norm / static_cast<double>(y.size()));
      if (!std::isfinite(norm))
        throw ComputationError("rolling: the integration produced a non-finite state");
      const double factor = std::clamp(0.9 * std::pow(std::max(norm, 1e-10), -0.2), 0.2, 5.0);
      if (norm <= 1)
      {
        ++accepted_;
        t = last ? duration : t + h;
        project_(next);
        y = std::move(next);
        if (!last || factor < 1)
          h_ = h * factor;
      }
      else
      {
        ++rejected_;
        h_ = h * factor;
      }
      if (h_ < 1e-14 * duration)
        throw ComputationError(fmt::format("rolling: step size underflow ({:.3g} s)", h_));
    }
  }

  long accepted() const { return accepted_; }
  long rejected() const { return rejected_; }

private:
  Rhs rhs_;
  Project project_;
  Eigen::VectorXd floor_;
  double rtol_;
  double h_;
  long accepted_ = 0;
  long rejected_ = 0;
};

/// Integrates over the run, one sample per interval; checks the energy balance
/// at each sample and stops after the first sample whose contact does not hold
/// (normal force not positive, or centre of pressure off the ruling).
template <class SampleAt>
void run_sampled(Dopri5& integrator, Eigen::VectorXd& y, const RollingParameters& p, RollingTrajectory& trajectory,
                 const SampleAt& sample_at)
{
  const long n_intervals = static_cast<long>(std::ceil(p.duration_s / p.sample_interval_s - 1e-9));
  trajectory.samples.reserve(static_cast<std::size_t>(n_intervals) + 1);
  double initial_energy = 0;
  for (long k = 0; k <= n_intervals; ++k)
  {
    const double time = std::min(static_cast<double>(k) * p.sample_interval_s, p.duration_s);
    if (k > 0)
      integrator.advance(y, time - trajectory.samples.back().time_s);
    RollingSample s = sample_at(y, time);
    const double energy = s.kinetic_energy_j + s.potential_energy_j;
    if (k == 0)
      initial_energy = energy;
    const double error = std::abs(energy + s.dissipated_energy_j - initial_energy) / initial_energy;
    trajectory.max_energy_error = std::max(trajectory.max_energy_error, error);
    if (error > p.energy_tolerance)
      throw ComputationError(fmt::format("rolling: energy balance error {:.3g} at t = {:.4g} s exceeds the bound "
                                         "{:.3g}; tighten the relative tolerance",
                                         error, time, p.energy_tolerance));
    const bool held = s.normal_force_n > 0 &&
                      (trajectory.mode == ContactMode::point || (s.centre_of_pressure >= 0 && s.centre_of_pressure <= 1));
    trajectory.samples.push_back(s);
    if (!held)
    {
      trajectory.contact_held = false;
      break;
    }
  }
  trajectory.accepted_steps = integrator.accepted();
  trajectory.rejected_steps = integrator.rejected();
}

// ---------------------------------------------------------------------------
// Line contact.
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

// ---------------------------------------------------------------------------
MassModel mass_model_of_mesh(const geometry::SurfaceMesh& mesh, double mass_kg)
{
  require_positive(mass_kg, "mass (kg)");
  const geometry::MassProperties mp = geometry::mass_properties(mesh);
  if (!(mp.volume_m3 > 0))
    throw InputError("rolling: the mesh encloses no volume");
  return {mass_kg, mp.centre_of_mass, mp.inertia * (mass_kg / mp.volume_m3)};
}

MassModel mass_model_of_ellipsoid(const Ellipsoid& body, double mass_kg)
{
  require_positive(mass_kg, "mass (kg)");
  const Eigen::Vector3d a = body.semi_axes_m;
  for (int i = 0; i < 3; ++i)
    require_positive(a[i], "ellipsoid semi-axis (m)");
  const Eigen::Vector3d sq = a.cwiseProduct(a);
  MassModel m;
  m.mass_kg = mass_kg;
  m.inertia_kg_m2 = (mass_kg / 5 * Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y())).asDiagonal();
  return m;
}

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
  validate(p);
  validate(mass);
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
  Dopri5 integrator(rhs, project, floor, p.relative_tolerance, p.sample_interval_s / 4);

  run_sampled(integrator, y, p, trajectory, [&](const Eigen::VectorXd& state, double time) {
    return line_sample(body, mass, p, state, time);
  });
  return trajectory;
}

// ---------------------------------------------------------------------------
RollingTrajectory roll_on_point(const Ellipsoid& body, const MassModel& mass, const PointContactStart& start,
                                const RollingParameters& p)
{
  validate(p);
  validate(mass);
  for (int i = 0; i < 3; ++i)
    require_positive(body.semi_axes_m[i], "ellipsoid semi-axis (m)");
  if (!start.rotation.allFinite() ||
      (start.rotation.transpose() * start.rotation - Eigen::Matrix3d::Identity()).norm() > 1e-9 ||
      start.rotation.determinant() < 0)
    throw InputError("rolling: the initial rotation is not a rotation matrix");
  if (!start.angular_velocity_rad_s.allFinite())
    throw InputError("rolling: the initial angular velocity is not finite");

  const Eigen::Matrix3d shape = body.semi_axes_m.cwiseProduct(body.semi_axes_m).asDiagonal();
  const double m = mass.mass_kg, g = p.gravity_m_s2, c = p.rolling_resistance_n_m_s;
  const double size = body.semi_axes_m.maxCoeff();

  struct Terms
  {
    Eigen::Matrix3d rotation;
    Eigen::Vector3d contact; ///< body frame
    Eigen::Vector3d arm;     ///< world, centre of mass to contact
    Eigen::Matrix3d curvature_radii_world;
    Eigen::Matrix3d inertia_world;
    Eigen::Matrix3d inertia_contact;
  };
  auto terms = [&](const Eigen::Vector4d& q_coeffs) {
    Terms t;
    const Eigen::Quaterniond q(q_coeffs[0], q_coeffs[1], q_coeffs[2], q_coeffs[3]);
    t.rotation = q.normalized().toRotationMatrix();
    const Eigen::Vector3d u = -t.rotation.row(2).transpose();
    const double h = std::sqrt(u.dot(shape * u));
    t.contact = shape * u / h;
    const Eigen::Matrix3d hessian = (shape - t.contact * t.contact.transpose()) / h;
    t.arm = t.rotation * (t.contact - mass.centre_of_mass_m);
    t.curvature_radii_world = t.rotation * hessian * t.rotation.transpose();
    t.inertia_world = t.rotation * mass.inertia_kg_m2 * t.rotation.transpose();
    t.inertia_contact =
        t.inertia_world + m * (t.arm.squaredNorm() * Eigen::Matrix3d::Identity() - t.arm * t.arm.transpose());
    return t;
  };
  auto angular_acceleration = [&](const Terms& t, const Eigen::Vector3d& omega) {
    const Eigen::Vector3d arm_rate = omega.cross(t.arm) - t.curvature_radii_world * up.cross(omega);
    const Eigen::Vector3d torque = -omega.cross(t.inertia_world * omega) + m * t.arm.cross(arm_rate.cross(omega)) +
                                   m * g * t.arm.cross(up) - c * omega;
    return std::pair<Eigen::Vector3d, Eigen::Vector3d>{t.inertia_contact.lu().solve(torque), arm_rate};
  };
  auto rhs = [&](const Eigen::VectorXd& state) {
    const Eigen::Vector4d qc = state.head<4>();
    const Eigen::Vector3d omega = state.segment<3>(4);
    const Terms t = terms(qc);
    const auto [omega_rate, arm_rate] = angular_acceleration(t, omega);
    (void)arm_rate;
    // dq/dt = (1/2) (0, omega) q, q = (w, x, y, z).
    const Eigen::Quaterniond q(qc[0], qc[1], qc[2], qc[3]);
    const Eigen::Quaterniond dq = Eigen::Quaterniond(0, omega.x(), omega.y(), omega.z()) * q;
    const Eigen::Vector3d velocity = t.arm.cross(omega);
    Eigen::VectorXd d(10);
    d << 0.5 * dq.w(), 0.5 * dq.x(), 0.5 * dq.y(), 0.5 * dq.z(), omega_rate, velocity.x(), velocity.y(),
        c * omega.squaredNorm();
    return d;
  };
  auto project = [](Eigen::VectorXd& state) { state.head<4>().normalize(); };

  auto sample = [&](const Eigen::VectorXd& state, double time) {
    const Terms t = terms(state.head<4>());
    const Eigen::Vector3d omega = state.segment<3>(4);
    const auto [omega_rate, arm_rate] = angular_acceleration(t, omega);
    RollingSample s;
    s.time_s = time;
    s.rotation = t.rotation;
    s.angular_velocity_rad_s = omega;
    s.centre_of_mass_m = Eigen::Vector3d(state[7], state[8], -t.arm.z());
    s.contact_start_m = s.contact_end_m = t.contact;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> radii(t.curvature_radii_world);
    s.start_radius_m = s.end_radius_m = std::sqrt(radii.eigenvalues()[1] * radii.eigenvalues()[2]);
    s.rolling_rate_rad_s = omega.norm();
    s.kinetic_energy_j = 0.5 * omega.dot(t.inertia_contact * omega);
    s.potential_energy_j = m * g * (-t.arm.z());
    s.dissipated_energy_j = state[9];
    const Eigen::Vector3d force = m * (arm_rate.cross(omega) + t.arm.cross(omega_rate) + g * up);
    s.normal_force_n = force.z();
    s.friction_ratio = force.head<2>().norm() / force.z();
    return s;
  };

  const Eigen::Quaterniond q0(start.rotation);
  Eigen::VectorXd y(10);
  y << q0.w(), q0.x(), q0.y(), q0.z(), start.angular_velocity_rad_s, 0, 0, 0;
  const double natural_rate = std::sqrt(g / size);
  Eigen::VectorXd floor(10);
  floor << 1, 1, 1, 1, Eigen::Vector3d::Constant(std::max(start.angular_velocity_rad_s.norm(), natural_rate)), size,
      size, m * g * size;
  Dopri5 integrator(rhs, project, floor, p.relative_tolerance, p.sample_interval_s / 4);

  RollingTrajectory trajectory;
  trajectory.mode = ContactMode::point;
  run_sampled(integrator, y, p, trajectory, sample);
  return trajectory;
}
} // namespace rollcheck::oracle
