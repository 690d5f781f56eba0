#pragma once
// Every requested score of one body under one oracle: the preprint's
// approximate oracle (Algorithm 1) or rigid-body oracle (Algorithm 2), in
// paper-compatible or corrected form, scored with CDS, SDS, TDS, WDS and FDS
// (contact/trajectory_scores.h); or real rolling without slipping of a named
// body, scored with the uniformity score U (oracle/rolling_study.h). The one
// entry point of `rollcheck oracle`, the search's revalidation, the tests and
// the benchmark (tests/bench/bench_oracle.cpp).
#include "contact/contact_parameters.h"
#include "core/json_number.h"
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/trajectory_scores.h"
#include "geometry/body.h"
#include "geometry/surface_mesh.h"
#include "oracle/approximate_oracle.h"
#include "oracle/paper_compat.h"
#include "oracle/parametric_search.h"
#include "oracle/rigid_body_oracle.h"
#include "oracle/rolling_body.h"
#include "oracle/rolling_study.h"
#include "contact/continuum_loop_scores.h"
#include "oracle/trajectory.h"
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace rollcheck::study::body_scores
{
enum class Oracle
{
  approximate, ///< Algorithm 1: a prescribed rotation sequence
  rigid,       ///< Algorithm 2: damped rigid-body dynamics from the reference's initial spins
  rolling      ///< real rolling without slipping under gravity, scored with U
};

/// The largest trajectory the preprint's oracles record (samples): a resource
/// guard, about 0.1 GB of orientations and contacts.
inline constexpr long max_oracle_samples = 1'000'000;

struct ScoreBodySettings
{
  geometry::BodySpec body;
  Oracle oracle = Oracle::rigid;
  oracle::ApproximateSettings approximate;
  oracle::RigidBodySettings rigid;
  /// Real rolling; the scoring mesh's faces cut 8 x 8 (the README's real-rolling table).
  oracle::RollingStudyParameters rolling = [] {
    oracle::RollingStudyParameters p;
    p.face_subdivisions = 8;
    return p;
  }();
  contact::ContactParameters contact;
  /// Real rolling's continuum scores on the exact surface (line contact):
  /// their load rule (dynamic: the motion's own normal force, which the time
  /// law's dynamics imply), end margin and time law; the contact width is
  /// rolling's. U_inf (uniformity_score_continuum) is their contact time.
  contact::ContinuumLoopSettings continuum;
  /// false: real rolling leaves BodyScores::continuum empty (a search reading U alone).
  bool with_continuum = true;
  oracle::PaperCompat compat = oracle::PaperCompat::corrected();
  contact::MetricSet metrics;
  long convergence_every = 50; ///< score snapshots every this many samples (the reference outputs': 50); 0: none
};

struct BodyScores
{
  std::string body;  ///< geometry::body_label
  Oracle oracle = Oracle::rigid;
  long n_faces = 0;  ///< of the body's mesh (rolling: of the subdivided scoring mesh)
  double wall_s = 0;
  double cpu_s = 0;  ///< processor time of the scoring (all threads): its cost, independent of machine load
  // The preprint's oracles (approximate, rigid).
  contact::ScoreVector scores;
  contact::FaceCurvature curvature;
  contact::FacePressure pressure;
  Eigen::VectorXd face_areas_m2;
  oracle::PaperCompat compat;
  contact::MetricSet metrics;
  // Real rolling.
  oracle::RollingStudyResult rolling;
  oracle::RollingStudyParameters rolling_parameters;
  /// Over the first loop, line contact only (none: point contact, or no whole loop).
  std::optional<contact::ContinuumLoopScores> continuum;
  contact::ContinuumLoopSettings continuum_settings;
};

/// Builds (or reads) settings.body and scores it under settings.oracle.
/// InputError for bad settings, a bad body, or a body the oracle does not
/// cover (rolling: a mesh file, uv-sphere, hemisphere, rollers of 3+ circles).
BodyScores score_body(const ScoreBodySettings& settings);
/// settings.continuum with the rolling oracle's contact width.
contact::ContinuumLoopSettings rolling_continuum_settings(const ScoreBodySettings& settings);

/// The scoring half of score_body: every requested score of a trajectory of
/// `body` (the rolling body of `mesh`), with settings' contact parameters,
/// switches, metrics and convergence_every. For trajectories run elsewhere
/// (the search's rigid-body revalidation).
contact::ScoreVector score_trajectory(const geometry::SurfaceMesh& mesh, const oracle::RollingBody& body,
                                      const oracle::Trajectory& trajectory, const ScoreBodySettings& settings);

/// The search's revalidation scores (oracle/parametric_search.h): score_trajectory
/// of each revalidated genome's rigid-body trajectory, named sds,
/// mean_peak_pressure_pa, stress_cv, tds, wds_vol, wds_depth and fds as settings.metrics asks.
oracle::RevalidationMetrics revalidation_scores(const ScoreBodySettings& settings);

/// Named keys (docs/methods/oracles.md#rollcheck-oracle); scores not computed are null,
/// infinite ones "inf". With `per_face`, the per-face arrays.
nlohmann::json to_json(const BodyScores& scores, bool per_face);

/// One line for the log: the body, the oracle and its scores.
std::string summary_line(const BodyScores& scores);

} // namespace rollcheck::study::body_scores
