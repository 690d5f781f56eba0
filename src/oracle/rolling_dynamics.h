#pragma once
// Rolling without slipping of a rigid convex body on the horizontal plane
// z = 0 under gravity, with optional viscous rolling resistance.
//
// Notation: R rotates body to world; c is the centre of mass (body frame);
// the body touches the plane where its outward normal is u = R^T(-e_z) (body
// frame); a = R (s(u) - c) points (world frame) from the centre of mass to the
// contact point s(u) (support_set.h); I_w = R I R^T is the world inertia about
// the centre of mass; m the mass, g gravity, C the rolling-resistance
// coefficient (torque -C omega, N m s).
//
// Point contact (a smooth, strictly convex body: here the ellipsoid, the sphere
// as a special case). No slip means v = a x omega for the centre of mass.
// Newton (m dv/dt = F - m g e_z) and Euler about the centre of mass
// (d(I_w omega)/dt = a x F - C omega) with the contact force F eliminated give
// the classical rolling equations (E. J. Routh, "Advanced Dynamics of a System
// of Rigid Bodies", 1905, ch. V; A. V. Borisov, I. S. Mamaev, "Rolling of a
// rigid body on a plane and sphere. Hierarchy of dynamics", Regul. Chaotic
// Dyn. 7 (2002) 177-200, eq. 2.4):
//   [I_w + m (|a|^2 I - a a^T)] d(omega)/dt
//       = -omega x I_w omega + m a x (da/dt x omega) + m g a x e_z - C omega,
//   da/dt = omega x a - H_w (e_z x omega),
// where H_w = R H R^T and H is the Hessian of the support function (the
// radii-of-curvature operator), so -H_w (e_z x omega) is how fast the contact
// point travels over the body. Orientation: dq/dt = (1/2) (0, omega) q.
//
// Line contact (a developable body resting on a ruling: the two-circle rollers,
// the oloid among them, and the cylinder as the hull of its two rims). Both ends
// of the contact ruling are at rest, so omega lies along the ruling: the body
// rolls about its contact ruling, and the support direction u moves on the
// curve where both circles are lowest, h_1(u) = h_2(u). Parametrised by its
// turning angle sigma (arc length of u on the unit sphere),
//   du/dsigma = T = u x b,   b = (s_2 - s_1)/|s_2 - s_1|   (the ruling),
//   omega = (d sigma/dt) R b,
// one degree of freedom is left. Its kinetic energy is (1/2) J sigma'^2 with
// J = b.I b + m |(s_1 - c) x b|^2 the moment of inertia about the ruling, its
// potential V = m g (s_1 - c).u, and energy balance gives
//   J sigma'' + (1/2) (dJ/dsigma) sigma'^2 + dV/dsigma = -C sigma',
//   dV/dsigma = m g (s_1 - c).T,   ds_i/dsigma = H_i T   (H_i: circle Hessians),
// all evaluated in closed form. The heading turns with the ruling,
// d(psi)/dsigma = -(db/dsigma).T, and the centre of mass moves with
// v = a x omega. The body is assumed to stay on its ruling: the normal force
// must keep both ends loaded. From the contact force F = m (dv/dt + g e_z) and
// its moment about the first end, the end loads N_1, N_2 and the centre of
// pressure N_2 / (N_1 + N_2) along the ruling are reported at every sample;
// when the centre of pressure leaves [0, 1] the body would tip onto one rim
// (rolling on a circle's edge, then an impact when the other circle lands),
// which is not modelled: the run stops there and says so.
//
// Integration: Dormand-Prince 5(4) with step control (E. Hairer, S. Norsett,
// G. Wanner, "Solving ODEs I", 2nd ed., 1993, sec. II.4-5) on the state
// including the dissipated work W = integral of C |omega|^2 dt; after each step
// the unit quaternion is normalised (point contact) or u is projected back onto
// h_1 = h_2 by Newton steps (line contact). The energy balance
// |E(t) + W(t) - E(0)| / E(0) is evaluated at every sample and must stay below
// `energy_tolerance`, else ComputationError: this is the bound on the energy
// error the local error control (relative_tolerance per step) is checked against.
//
// The integrator and the mass models are in rolling_dynamics.cpp, the line
// contact in rolling_line_contact.cpp, the point contact in rolling_point_contact.cpp.
#include "geometry/surface_mesh.h"
#include "oracle/support_set.h"
#include <Eigen/Core>
#include <vector>

namespace rollcheck::oracle
{
/// Mass, centre of mass and inertia about it, in the body frame.
struct MassModel
{
  double mass_kg = 1.0;
  Eigen::Vector3d centre_of_mass_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Identity();
};

/// Uniform solid bounded by a closed convex mesh, scaled to `mass_kg`.
MassModel mass_model_of_mesh(const geometry::SurfaceMesh& mesh, double mass_kg);

/// Ellipsoid centred at the body origin with semi-axes along the body axes.
struct Ellipsoid
{
  Eigen::Vector3d semi_axes_m = Eigen::Vector3d::Ones();
};
MassModel mass_model_of_ellipsoid(const Ellipsoid& body, double mass_kg);

/// Convex hull of two circles (body frame).
struct TwoCircleBody
{
  Circle first;
  Circle second;
};
TwoCircleBody two_circle_body(std::span<const Circle> circles);

struct RollingParameters
{
  double gravity_m_s2 = 9.81;               ///< the preprint's g
  double rolling_resistance_n_m_s = 0.0;    ///< C; 0 = undamped (the preprint's gamma is 0.02)
  double duration_s = 10.0;                 ///< the preprint's run length
  double sample_interval_s = 1e-3;          ///< output spacing; strips of the contact density
  double relative_tolerance = 1e-11;        ///< local error per step (Dormand-Prince)
  double energy_tolerance = 1e-7;           ///< bound on |E + W - E0| / E0, checked at every sample
};

enum class ContactMode
{
  point,
  line
};

struct RollingSample
{
  double time_s = 0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); ///< body to world
  Eigen::Vector3d angular_velocity_rad_s = Eigen::Vector3d::Zero(); ///< world frame
  Eigen::Vector3d centre_of_mass_m = Eigen::Vector3d::Zero();       ///< world frame; z is its height
  /// Contact set in the body frame: the ruling from the first to the second
  /// circle (line contact) or the contact point twice (point contact).
  Eigen::Vector3d contact_start_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d contact_end_m = Eigen::Vector3d::Zero();
  /// Line contact: radius of normal curvature across the ruling at its two ends
  /// (m); it varies linearly in between (exact for a developable surface).
  /// Point contact: both are sqrt(R_1 R_2), the principal radii's geometric mean.
  double start_radius_m = 0;
  double end_radius_m = 0;
  double turning_angle_rad = 0; ///< sigma travelled (line contact); 0 for point contact
  double rolling_rate_rad_s = 0; ///< d(sigma)/dt (line contact) or |omega| (point contact)
  double kinetic_energy_j = 0;
  double potential_energy_j = 0; ///< m g (height of the centre of mass)
  double dissipated_energy_j = 0;
  double normal_force_n = 0;
  double centre_of_pressure = 0.5; ///< along the ruling, 0 at its start, 1 at its end (line contact)
  double friction_ratio = 0;       ///< |tangential force| / normal force needed to roll without slip
};

struct RollingTrajectory
{
  ContactMode mode = ContactMode::point;
  std::vector<RollingSample> samples;
  double max_energy_error = 0;        ///< max over samples of |E + W - E0| / E0
  /// false: the run stopped at its last sample, where the normal force vanished
  /// or (line contact) the centre of pressure left the ruling.
  bool contact_held = true;
  double loop_turning_angle_rad = 0;  ///< line contact: sigma of one loop of the contact curve
  long accepted_steps = 0;
  long rejected_steps = 0;
};

/// Geometry of the contact ruling of a two-circle body for a support direction
/// u on the curve h_1(u) = h_2(u), with its derivatives along the curve.
struct Ruling
{
  Eigen::Vector3d direction;    ///< u, unit (body frame)
  Eigen::Vector3d start_m;      ///< s_1(u)
  Eigen::Vector3d end_m;        ///< s_2(u)
  Eigen::Vector3d axis;         ///< b, unit, from start to end
  Eigen::Vector3d tangent;      ///< T = u x b = du/dsigma
  Eigen::Vector3d start_rate_m; ///< ds_1/dsigma
  Eigen::Vector3d end_rate_m;   ///< ds_2/dsigma
  double length_m;
  /// Radii of normal curvature across the ruling at its ends, ds_i/dsigma . T.
  double start_radius_m;
  double end_radius_m;
};

/// Ruling at u, after projecting u onto the curve h_1 = h_2 (Newton on the
/// sphere). ComputationError if u is too far from the curve or a circle lies
/// flat (the contact is then a disc, not a ruling).
Ruling ruling_at(const TwoCircleBody& body, const Eigen::Vector3d& direction);

/// J = b.I b + m |(s_1 - c) x b|^2, the moment of inertia about the ruling (kg m^2).
double ruling_inertia(const Ruling& ruling, const MassModel& mass);
/// (s_1 - c).u, the height of the centre of mass above the plane (m).
double centre_of_mass_height(const Ruling& ruling, const MassModel& mass);

/// A point of the contact curve near `hint` (any direction): bisection along
/// the great circle from `hint` to the nearest direction of opposite sign of
/// h_2 - h_1. ComputationError if the curve is empty (one circle inside the
/// other's hull).
Eigen::Vector3d contact_curve_point(const TwoCircleBody& body, const Eigen::Vector3d& hint);

/// The loop of the contact curve through `start`, sampled at `points` equal
/// steps of turning angle, and its total turning angle.
struct ContactLoop
{
  std::vector<Eigen::Vector3d> directions;
  double turning_angle_rad = 0;
};
ContactLoop trace_contact_loop(const TwoCircleBody& body, const Eigen::Vector3d& start, int points = 2000);

/// The direction on the loop through `start` where the centre of mass is lowest
/// (the stable resting ruling), refined by golden-section search.
Eigen::Vector3d resting_direction(const TwoCircleBody& body, const MassModel& mass, const Eigen::Vector3d& start);

struct LineContactStart
{
  Eigen::Vector3d direction;        ///< u on the contact curve (body frame); projected onto it
  double rolling_rate_rad_s = 0;    ///< d(sigma)/dt at t = 0
  double heading_rad = 0;           ///< world angle of the ruling about z at t = 0
};

RollingTrajectory roll_on_ruling(const TwoCircleBody& body, const MassModel& mass, const LineContactStart& start,
                                 const RollingParameters& parameters);

struct PointContactStart
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); ///< body to world at t = 0
  Eigen::Vector3d angular_velocity_rad_s = Eigen::Vector3d::Zero(); ///< world frame
};

RollingTrajectory roll_on_point(const Ellipsoid& body, const MassModel& mass, const PointContactStart& start,
                                const RollingParameters& parameters);
} // namespace rollcheck::oracle
