#include "oracle/rigid_body_oracle.h"
#include "core/error.h"
#include "oracle/heights.h"
#include "oracle/support_search.h"
#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <string_view>

namespace rollcheck::oracle
{
namespace
{
// Products summed with fused multiply-adds in index order: the rounding of
// the OpenBLAS dot/gemv kernels behind the reference's numpy calls.
double fma_dot3(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::fma(a[2], b[2], std::fma(a[1], b[1], a[0] * b[0]));
}

double fma_norm4(const Eigen::Vector4d& q)
{
  return std::sqrt(std::fma(q[3], q[3], std::fma(q[2], q[2], std::fma(q[1], q[1], q[0] * q[0]))));
}

Eigen::Vector3d fma_matvec(const Eigen::Matrix3d& m, const Eigen::Vector3d& v)
{
  return {fma_dot3(m.row(0), v), fma_dot3(m.row(1), v), fma_dot3(m.row(2), v)};
}

// numpy's cross: one product minus another, each rounded.
Eigen::Vector3d cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Quaternions are [w, x, y, z].
Eigen::Matrix3d rotation_of(const Eigen::Vector4d& quaternion)
{
  const double n = fma_norm4(quaternion);
  const double w = quaternion[0] / n, x = quaternion[1] / n, y = quaternion[2] / n, z = quaternion[3] / n;
  Eigen::Matrix3d r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),  //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

Eigen::Vector4d hamilton_product(const Eigen::Vector4d& a, const Eigen::Vector4d& b)
{
  const double w1 = a[0], x1 = a[1], y1 = a[2], z1 = a[3];
  const double w2 = b[0], x2 = b[1], y2 = b[2], z2 = b[3];
  return {w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
          w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2};
}

/// One rigid-body run, advanced a step at a time.
class RollingSimulation
{
public:
  RollingSimulation(const RollingBody& body, const RigidBodySettings& o, const PaperCompat& c,
                    const Eigen::Vector3d& spin)
      : body_(body), o_(o), c_(c), support_(body), omega_(spin)
  {
    // The tensor is for density 1 (mass = volume); the corrected form scales
    // it to the mass gravity acts on.
    inertial_mass_ = c.unit_mass_with_density_one_inertia ? body.mass.volume_m3 : o.mass_kg;
    inertia_ = c.unit_mass_with_density_one_inertia ? body.mass.inertia
                                                    : Eigen::Matrix3d(body.mass.inertia * (o.mass_kg / body.mass.volume_m3));
    inverse_ = inverse_of(inertia_);
  }

  struct State
  {
    Eigen::Matrix3d rotation;
    int support;
    Eigen::Vector3d omega_before, omega_after;
  };

  State step()
  {
    State st;
    st.rotation = rotation_of(q_);
    const Eigen::Matrix3d& r = st.rotation;
    st.support = support_.lowest(r.row(2).transpose());
    const auto sv = static_cast<std::size_t>(st.support);
    const Eigen::Vector3d s = rotate(r, body_.vertices, sv);
    st.omega_before = omega_;

    // Gravity at the point turned about (the origin), lever arm from the
    // support point touching the ground; written as the reference forms it.
    const Eigen::Vector3d lever{0.0 - s[0], 0.0 - s[1], -s[2] - 0.0};
    const Eigen::Vector3d weight{0.0, 0.0, -o_.mass_kg * o_.gravity_m_s2};
    Eigen::Vector3d torque = cross(lever, weight);
    torque -= (o_.damping_n_m_s * omega_).eval();

    Eigen::Vector3d alpha;
    if (c_.body_inertia_in_world_equations && c_.centroidal_inertia_for_support_torque)
    {
      const Eigen::Vector3d gyroscopic = cross(omega_, fma_matvec(inertia_, omega_));
      alpha = fma_matvec(inverse_, (torque - gyroscopic).eval());
    }
    else
    {
      Eigen::Matrix3d inertia = c_.body_inertia_in_world_equations ? inertia_ : r * inertia_ * r.transpose();
      if (!c_.centroidal_inertia_for_support_torque)
      {
        const Eigen::Vector3d arm = r * body_.centre_of_mass - s; // support to centre of mass
        inertia += inertial_mass_ * (arm.squaredNorm() * Eigen::Matrix3d::Identity() - arm * arm.transpose());
      }
      alpha = inverse_of(inertia) * (torque - omega_.cross(inertia * omega_));
    }
    omega_ = omega_ + alpha * o_.time_step_s;
    const double speed = std::sqrt(fma_dot3(omega_, omega_));
    if (speed > o_.max_angular_speed_rad_s)
      omega_ = (omega_ * o_.max_angular_speed_rad_s) / speed;

    const double omega_norm = std::sqrt(fma_dot3(omega_, omega_));
    const double angle = omega_norm * o_.time_step_s;
    Eigen::Vector4d dq{1.0, 0.0, 0.0, 0.0};
    if (!(angle < 1e-12))
    {
      const Eigen::Vector3d axis = omega_ / omega_norm;
      const double half = angle / 2.0, sh = std::sin(half);
      dq = {std::cos(half), axis[0] * sh, axis[1] * sh, axis[2] * sh};
    }
    q_ = hamilton_product(dq, q_);
    q_ = q_ / fma_norm4(q_);
    st.omega_after = omega_;
    return st;
  }

private:
  static Eigen::Matrix3d inverse_of(const Eigen::Matrix3d& m)
  {
    const Eigen::Matrix3d inv = m.partialPivLu().inverse();
    if (!inv.allFinite())
      throw ComputationError("rigid-body oracle: the inertia tensor is singular (a flat or degenerate body)");
    return inv;
  }

  const RollingBody& body_;
  const RigidBodySettings& o_;
  const PaperCompat& c_;
  SupportSearch support_;
  Eigen::Vector4d q_{1.0, 0.0, 0.0, 0.0};
  Eigen::Vector3d omega_;
  double inertial_mass_;
  Eigen::Matrix3d inertia_, inverse_;
};

/// InputError "rigid-body oracle: <what> must be <rule>, got <value> <unit>" unless `ok`.
void require(bool ok, std::string_view what, std::string_view rule, double value, std::string_view unit)
{
  if (!ok)
    throw InputError(fmt::format("rigid-body oracle: {} must be {}, got {} {}", what, rule, value, unit));
}

void require_positive(double value, std::string_view what, std::string_view unit)
{
  require(std::isfinite(value) && value > 0, what, "positive", value, unit);
}

void require_non_negative(double value, std::string_view what, std::string_view unit)
{
  require(std::isfinite(value) && value >= 0, what, "finite and >= 0", value, unit);
}
} // namespace

const std::vector<Eigen::Vector3d>& reference_initial_spins()
{
  static const std::vector<Eigen::Vector3d> spins = {
      {0.3, 1.5, 0.2}, {-0.5, 1.0, 0.8}, {0.7, -1.2, 0.4}, {0.1, 0.8, -1.0}, {-0.3, -0.6, 1.5}};
  return spins;
}

void validate(const RigidBodySettings& o)
{
  require_positive(o.time_step_s, "time step", "s");
  if (!(std::isfinite(o.duration_s) && o.duration_s > 0) || steps_per_run(o) < 1)
    throw InputError(fmt::format("rigid-body oracle: duration {} s gives no step of {} s", o.duration_s,
                                 o.time_step_s));
  if (o.sample_every < 1)
    throw InputError(fmt::format("rigid-body oracle: sample interval must be at least 1 step, got {}",
                                 o.sample_every));
  require_non_negative(o.contact_threshold_m, "contact threshold", "m");
  require_non_negative(o.damping_n_m_s, "damping", "N m s");
  require_positive(o.mass_kg, "mass", "kg");
  require_non_negative(o.gravity_m_s2, "gravity", "m/s^2");
  require_positive(o.max_angular_speed_rad_s, "angular speed cap", "rad/s");
  if (o.initial_spins.empty())
    throw InputError("rigid-body oracle: needs at least one run (initial spin)");
  for (const Eigen::Vector3d& w : o.initial_spins)
    if (!w.allFinite())
      throw InputError("rigid-body oracle: initial spins must be finite");
}

long steps_per_run(const RigidBodySettings& o)
{
  const double steps = o.duration_s / o.time_step_s;
  return std::isfinite(steps) && steps < 1e12 ? static_cast<long>(steps) : 0;
}

Trajectory rigid_body_oracle(const RollingBody& body, const RigidBodySettings& options, const PaperCompat& compat)
{
  validate(options);
  const long n_steps = steps_per_run(options);
  Trajectory out;
  out.has_angular_velocity = true;
  out.contact_threshold_m = options.contact_threshold_m;
  out.samples.reserve(options.initial_spins.size() * static_cast<std::size_t>(n_steps / options.sample_every + 1));
  for (std::size_t run = 0; run < options.initial_spins.size(); ++run)
  {
    RollingSimulation sim(body, options, compat, options.initial_spins[run]);
    int lowest_face = -1;
    for (long t = 0; t < n_steps; ++t)
    {
      const RollingSimulation::State st = sim.step();
      if (t % options.sample_every != 0)
        continue;
      const double ground = ground_contacts(body, st.rotation.row(2).transpose(), st.support,
                                            compat.ground_at_lowest_centroid, options.contact_threshold_m,
                                            out.contact_faces, lowest_face);
      out.contact_offsets.push_back(static_cast<int>(out.contact_faces.size()));
      out.samples.push_back({st.rotation, compat.post_step_angular_velocity ? st.omega_after : st.omega_before,
                             st.support, ground, static_cast<int>(run)});
    }
    out.integration_steps += n_steps;
  }
  return out;
}

std::vector<Eigen::Matrix3d> rigid_body_rotations(const RollingBody& body, const Eigen::Vector3d& initial_spin,
                                                  long n_steps, const RigidBodySettings& options,
                                                  const PaperCompat& compat)
{
  validate(options);
  RollingSimulation sim(body, options, compat, initial_spin);
  std::vector<Eigen::Matrix3d> rotations;
  rotations.reserve(static_cast<std::size_t>(std::max(n_steps, 0L)));
  for (long t = 0; t < n_steps; ++t)
    rotations.push_back(sim.step().rotation);
  return rotations;
}
} // namespace rollcheck::oracle
