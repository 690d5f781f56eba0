#pragma once
// Real rolling of a named body, scored on a mesh: the scene the audit runs for
// its "corrected physics" column.
//
// The body starts on its stable ruling (the lowest centre of mass on the loop
// of the contact curve nearest the body-frame direction -z; line contact) or
// on the pole of a sphere, is given a rolling rate and rolls without slipping
// under gravity (rolling_dynamics.h). Its contact measure is accumulated over
// `loops` complete loops of the contact curve (contact_density.h) and scored
// (uniformity_score.h) on the body's mesh with every face cut into
// face_subdivisions^2 parts. Undamped, the motion repeats every loop, so the
// score of one loop is the score of any whole number of loops.
//
// Initial rate: the body's potential V varies along its contact loop by
// dV = m g (max - min height of the centre of mass). To roll over every
// barrier it needs a kinetic energy above dV at the stable ruling; it is given
// (1 + rolling_energy) dV. Faster starts make most rollers lift a rim off
// the plane (the centre of pressure leaves the ruling, reported as
// contact_held = false), which this line-contact model does not follow. Bodies
// with constant V (the cylinder; Stewart's roller, d = sqrt(2)) start at
// sqrt(g / size); the cylinder's density does not depend on the rate.
#include "geometry/body.h"
#include "oracle/contact_density.h"
#include <string>

namespace rollcheck::oracle
{
struct RollingStudyParameters
{
  double mass_kg = 1.0;                 ///< the preprint's m (scores do not depend on it)
  double gravity_m_s2 = 9.81;           ///< the preprint's g
  double rolling_energy = 0.1;   ///< initial kinetic energy / dV - 1 (see above)
  double rolling_rate_rad_s = 0;        ///< > 0: this initial rate instead
  double rolling_resistance_n_m_s = 0;  ///< C; > 0 needs `duration_s`
  int loops = 1;                        ///< complete loops scored
  double duration_s = 0;               ///< 0: loops x the undamped loop period (+2 %)
  double sample_interval_s = 1e-3;      ///< strips of the contact density
  /// > 0: sample the line-contact loop this many times per undamped loop
  /// period instead (every body's loop resolved alike, whatever its period).
  long samples_per_loop = 0;
  double relative_tolerance = 1e-10;    ///< Dormand-Prince local error
  int mass_points = 2048;               ///< samples per circle (or cylinder sides) of the mass and area mesh
  ContactWidth contact_width;           ///< Hertz patch (default) or rigid unit width
  int face_subdivisions = 1;            ///< the body's mesh faces are cut into this^2 for scoring
};

/// One real-rolling run of a body, ready to be scored on any mesh of it.
struct RealRolling
{
  RollingTrajectory trajectory;
  double initial_rate_rad_s = 0;
  double loop_period_s = 0;     ///< undamped period from the energy integral; 0 if the body cannot roll over
  double scored_end_s = 0;      ///< end of the scored window (`loops` complete loops, or the end of the run)
  double first_loop_end_s = 0;  ///< NaN if the first loop is not completed
  double loops_completed = 0;   ///< loops of the contact curve in the scored window
  double surface_area_m2 = 0;   ///< of the exact body (from the fine mass mesh)
  /// The body's generating circles (empty for the sphere) and mass model, in
  /// the frame of geometry::make_body(spec).
  std::vector<Circle> circles;
  MassModel mass;
};

/// InputError unless `spec` is an exact body that is the hull of two circles
/// (the oloid, the preprint's body, a two-circle roller, the cylinder as the
/// hull of its rims), whose contact with a plane is a ruling: not a mesh
/// file, a sphere (point contact: `rollcheck hertz`) or a roller of more
/// circles. Every scene that follows rulings (fem-sds, rim, flat-rim,
/// whole-body) starts here.
void require_line_contact(const geometry::BodySpec& spec);
/// The circles whose hull is the body (require_line_contact).
std::vector<Circle> line_contact_circles(const geometry::BodySpec& spec);

/// Runs the dynamics. InputError for bodies the rolling model does not cover
/// (uv-sphere, hemisphere, rollers of three or more circles) and for bad parameters.
RealRolling real_rolling(const geometry::BodySpec& spec, const RollingStudyParameters& parameters);
/// The body's mass model and surface area as real_rolling takes them (from
/// mass_mesh at parameters.mass_points, of parameters.mass_kg): they do not
/// depend on how the body rolls, so a study that rolls one body at several
/// energies builds them once (the mesh's hull is most of a short run's time).
struct RollingMass
{
  MassModel mass;
  double surface_area_m2 = 0;
};
RollingMass rolling_mass(const geometry::BodySpec& spec, const RollingStudyParameters& parameters);
/// real_rolling of a body with line contact (require_line_contact: not the
/// sphere) with its mass built already: rolling_mass(spec, parameters) of
/// the same spec, mass_points and mass_kg.
RealRolling real_rolling(const geometry::BodySpec& spec, const RollingStudyParameters& parameters,
                         const RollingMass& mass);
/// The body's mesh for its mass and area, as real_rolling builds it:
/// `mass_points` samples per circle (or cylinder sides).
geometry::SurfaceMesh mass_mesh(const geometry::BodySpec& spec, int mass_points);
/// The body's centre of mass as real_rolling takes it (body frame): that of
/// mass_mesh at the default mass_points.
Eigen::Vector3d rolling_centre_of_mass(const geometry::BodySpec& spec);

struct RollingStudyResult
{
  std::string contact;              ///< "line" or "point"
  long faces = 0;                   ///< of the scoring mesh (subdivided)
  double uniformity = 0;            ///< U on the scoring mesh
  double continuum_uniformity = 0;  ///< U_inf of the first loop (line contact), NaN otherwise
  double coverage = 0;              ///< area fraction of the mesh touched
  double max_over_mean = 0;
  double initial_rate_rad_s = 0;
  double loop_period_s = 0;
  double loops_completed = 0;
  double scored_time_s = 0;
  bool contact_held = true;         ///< false: stopped where a rim would lift (see rolling_dynamics.h)
  double max_energy_error = 0;
  double centre_of_pressure_min = 0;
  double centre_of_pressure_max = 0;
  double friction_ratio_max = 0;    ///< least friction coefficient that rolls without slip
};

/// Scores a run on `body_mesh` (the body's mesh in its own frame), its faces
/// cut into parameters.face_subdivisions^2.
RollingStudyResult score_real_rolling(const RealRolling& run, const geometry::SurfaceMesh& body_mesh,
                                      const RollingStudyParameters& parameters);

/// real_rolling, scored on geometry::make_body(spec).
RollingStudyResult rolling_study(const geometry::BodySpec& spec, const RollingStudyParameters& parameters);
} // namespace rollcheck::oracle
