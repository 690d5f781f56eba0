#pragma once
// The two studies behind the defaults (docs/methods/hertz-fem.md):
// - convergence: each model and degree over its refine levels, for the
//   speed-against-error plot and the choice of default_refine();
// - penalty: penalty_c from 0.1 to 1000 on each model's default mesh, for
//   the choice of HertzSettings::default_penalty_c;
// - pointwise: the 3D model's cost against its pointwise errors.
// A study is a list of setups derived from a base setup (its body, load and
// solver options), run one after the other into a table of errors and costs.
#include "fem/scenes/hertz_setup.h"
#include "fem/scenes/hertz_solve.h"
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollcheck::fem
{
/// Refine levels of the convergence study per model and degree: 2D P1
/// 0..6, 2D P2 0..4, 3D P1 0..2, 3D P2 0.
std::vector<HertzSettings> convergence_study(const HertzSettings& base, const std::vector<Model>& models);

/// Cost against pointwise error (the largest nodal pressure and the
/// profile's RMS, besides the fitted a and p0), with the lumped and the
/// consistent pressure recovery: the axisymmetric P1 default as the
/// reference, then 3D P1 refine 0..3, 3D P1 at the default refine with 10x
/// the base's penalty_c, and 3D P2 refine 0 (also with the penalty's nodal
/// pressure); then 3D P2 refine 0 with pole_refine 2 alone (lumped), with
/// edge_refine 2 (lumped and touching), edge_refine 3 (lumped), pole and
/// edge refine 3 (touching), and edge_refine 2 at 10x the base's penalty_c
/// (lumped).
std::vector<HertzSettings> pointwise_study(const HertzSettings& base);

/// penalty_c in {0.1, 0.3, 1, 3, 10, 30, 100, 300, 1000}, P1, default mesh.
std::vector<HertzSettings> penalty_study(const HertzSettings& base, const std::vector<Model>& models);

/// One run of a study: its result, or the message of the ComputationError
/// that ended it (e.g. a diverged solve at an extreme penalty).
struct HertzStudyRun
{
  HertzSettings setup;
  std::optional<HertzResult> result;
  std::string failure;
};

struct HertzStudy
{
  std::string name; ///< "convergence", "penalty" or "pointwise"
  std::vector<HertzStudyRun> runs;
};

/// Solves the setups one after the other on `comm`; a failed solve becomes a
/// run with its message instead of ending the study.
HertzStudy run_study(MPI_Comm comm, const std::string& name, const std::vector<HertzSettings>& setups);

/// The study's table, a header and one line per run: setup, cost, relative
/// errors, flags and status ("ok" or "failed: ..."). postprocess/hertz_study_plot.py reads it.
std::string to_csv(const HertzStudy& study);

/// {"study": name, "runs": [to_json(result), or the setup and "failed"]}.
nlohmann::json to_json(const HertzStudy& study);
} // namespace rollcheck::fem
