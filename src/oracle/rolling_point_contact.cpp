// Rolling dynamics at a point (rolling_dynamics.h, "Point contact"): the
// ellipsoid, the sphere among them, rolling without slipping on the plane by
// Routh's equations, with the orientation as a unit quaternion.
#include "core/error.h"
#include "oracle/rolling_dynamics.h"
#include "oracle/rolling_dynamics_internal.h"
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <utility>

namespace rollcheck::oracle
{
namespace
{
const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
} // namespace

RollingTrajectory roll_on_point(const Ellipsoid& body, const MassModel& mass, const PointContactStart& start,
                                const RollingParameters& p)
{
  detail::validate(p);
  detail::validate(mass);
  for (int i = 0; i < 3; ++i)
    detail::require_positive(body.semi_axes_m[i], "ellipsoid semi-axis (m)");
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
  detail::Dopri5 integrator(rhs, project, floor, p.relative_tolerance, p.sample_interval_s / 4);

  RollingTrajectory trajectory;
  trajectory.mode = ContactMode::point;
  detail::run_sampled(integrator, y, p, trajectory, sample);
  return trajectory;
}
} // namespace rollcheck::oracle
