#pragma once
// The rim loop's samples under a load rule (study/rims/rim_loop.h): how the
// body's load is spread along each sample's contact ruling, as the `--load-rule`
// of fem-sds's continuum value, oracle, life and robustness has it
// (contact/continuum_loop_scores.h LoadRule):
//
//  - static: F through the centre of mass G, c = ((G - s_1) . b) / L;
//  - dynamic: the normal force N(t) and centre of pressure c(t) of the same
//    rolling motion (oracle/rolling_dynamics.h, Newton-Euler), the force
//    scaled to F: F N / (m g);
//  - uniform: F / L along the whole ruling, which is the linear rule's
//    c = 1/2.
//
// Each rule is a force and the point of the ruling it acts through (body
// frame); the contact locus (contact/contact_locus.h) spreads it by the
// no-tension linear rule of a rigid footing, q(s) = (2 N / L)(2 - 3c + (6c - 3) s/L)
// for 1/3 <= c <= 2/3 and triangularly over 3c (or 3 (1 - c)) nearest the
// loaded end otherwise (oracle/contact_density.h line_load), so every rule
// loads a ruling's end where its line load there is not zero. The samples
// are mapped onto the faces as FEM-SDS maps them (loop_scores::map_loop_samples)
// with that force and point, one sample at a time.
#include "contact/continuum_loop_scores.h"
#include "oracle/rolling_study.h"
#include "study/loop_scores/fem_sds.h"
#include "study/loop_scores/loop_sds.h"
#include <Eigen/Core>
#include <mpi.h>
#include <span>
#include <vector>

namespace rollcheck::study::rims
{
/// A sample's load under the rule: its force and the point (body frame) it acts through.
struct RulingLoad
{
  double force_n = 0;
  Eigen::Vector3d through_m = Eigen::Vector3d::Zero();
};

/// The rule's load on each sample of `run`'s scored loop (its samples up to
/// scored_end_s, in order, as fem-sds's rolling loop has them), for the
/// force `force_n` and gravity `gravity_m_s2` of the run.
std::vector<RulingLoad> ruling_loads(const oracle::RealRolling& run, contact::LoadRule rule, double force_n,
                                     double gravity_m_s2);

/// The loop's samples under a rule, and where each of this rank's ruling
/// samples lies in the loop.
struct RuleSamples
{
  contact::LoadRule rule = contact::LoadRule::dynamic;
  loop_scores::LoopSamples samples;
  std::vector<std::size_t> ruling_sample; ///< per samples.rulings: its index in the loop
  std::vector<double> times_s;            ///< of every sample of the loop
  std::vector<RulingLoad> loads;          ///< of every sample of the loop
};

/// `source`'s samples mapped as loop_scores::map_loop_samples maps them, each
/// with its own load `loads[j]` instead of F through the centre of mass.
/// Collective on `comm` (the ranks share the samples as map_loop_samples
/// does); the point-Hertz sums are zero (no rule moves the preprint's faces'
/// pressures: take them from the static samples). `ruling_sample`, if
/// given, gets each ruling sample's index in the loop.
loop_scores::LoopSamples map_rule_samples(MPI_Comm comm, const loop_scores::LoopSource& source,
                                          std::span<const RulingLoad> loads, const oracle::RollingBody& body,
                                          const oracle::FaceCones& cones, double effective_modulus_pa,
                                          const loop_scores::LoopSdsSettings& settings,
                                          std::vector<std::size_t>* ruling_sample = nullptr);

/// The rim loop's samples under each of `rules` (the rolling oracle's loop,
/// re-run once as fem-sds ran it in `interior`), mapped with the rule's
/// loads, with the static samples' point-Hertz sums. InputError for the
/// rigid oracle, which has no rolling motion.
std::vector<RuleSamples> rule_loop_samples(MPI_Comm comm, const loop_scores::FemSdsSettings& settings,
                                           const loop_scores::FemSdsResult& interior,
                                           std::span<const contact::LoadRule> rules);
} // namespace rollcheck::study::rims
