#pragma once
// Every distribution score of a trajectory, in one pass over its samples. For
// each sample and each face f in contact (Hertz pressure p_f at the reference
// load, sliding speed v_f):
//   CDS  accumulates 1                              (oracle/contact_distribution.h)
//   SDS  accumulates p_f
//   FDS  accumulates Miner damage of sigma_a = s p_f (p_f s / 2 corrected),
//        s = (F_fatigue / F_ref)^(1/3) the Hertz load scaling
//   TDS  accumulates mu p_f v_f
//   WDS_vol, WDS_depth accumulate Archard wear (contact/wear.h)
// and each score is the template of oracle/distribution_score.h on its
// accumulator (+infinity for an empty one). With them: contact CV and max/mean
// ratio; the per-orientation peak pressure (largest p_f of a sample) with its
// mean, min, max and CV over samples that touch; fatigue, heat and wear ratios
// (max / min over faces that accumulated any); sliding speed statistics; and
// convergence snapshots of each score.
#include "contact/contact_parameters.h"
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "geometry/surface_mesh.h"
#include "oracle/distribution_score.h"
#include "oracle/paper_compat.h"
#include "oracle/rolling_body.h"
#include "oracle/trajectory.h"
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace rollcheck::contact
{
struct MetricSet
{
  bool cds = true, sds = true, tds = true, wds = true, fds = true;
  /// From "cds,sds,tds,wds,fds" or "all"; InputError naming `origin` for an
  /// unknown or empty list.
  static MetricSet parse(std::string_view list, std::string_view origin);
  bool needs_sliding() const { return tds || wds; }
};

struct ScoreVector
{
  long n_samples = 0;
  // CDS
  std::optional<double> cds;
  oracle::DistributionSummary contact;     ///< cv, max/mean ratio, faces with and without contact
  // SDS and Hertz statistics (pressure per orientation, samples that touch)
  std::optional<double> sds;
  oracle::ValueStatistics peak_pressure_pa;
  double effective_modulus_pa = 0;
  // FDS
  std::optional<double> fds;
  double damage_ratio = 0;                 ///< max / min damage over damaged faces
  double first_failure_cycles = 0;         ///< samples / max damage: cycles until the worst face fails
  oracle::ValueStatistics fatigue_stress_pa; ///< per-orientation peak at the fatigue load
  double fraction_above_endurance = 0;     ///< contact events with stress amplitude above sigma_e
  // TDS
  std::optional<double> tds;
  double heat_ratio = 0;                   ///< max / min heat over heated faces
  oracle::ValueStatistics sliding_speed_m_s; ///< over all contact events (cv 0 when the mean is 0)
  // WDS
  std::optional<double> wds_vol, wds_depth;
  double wear_depth_ratio = 0;             ///< max / min depth over worn faces
  /// Per-face accumulators of the metrics asked for (keys: contact_counts,
  /// stress_pa, fatigue_damage, heat, wear_volume, wear_depth).
  std::map<std::string, Eigen::VectorXd> per_face;
  /// Score after every `convergence_every` samples, per metric (keys cds, sds, ...).
  std::map<std::string, oracle::Convergence> convergence;
};

struct ScoreInputs
{
  const oracle::RollingBody& body;
  const FaceCurvature& curvature;
  const FacePressure& pressure;
};

/// InputError when a metric needs angular velocities the trajectory lacks.
ScoreVector score_trajectory(const ScoreInputs& inputs, const oracle::Trajectory& trajectory,
                             const MetricSet& metrics, const ContactParameters& parameters,
                             const oracle::PaperCompat& compat, long convergence_every);
} // namespace rollcheck::contact
