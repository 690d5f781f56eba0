#pragma once
// Wing of the study layer: the robustness study. Every headline comparison of
// bodies, evaluated with resolution-free scores (contact/continuum_loop_scores.h)
// over the grid of modelling choices a reader could reasonably make:
//
//   rolling_energy  the initial kinetic energy over the potential barrier, as
//                   the excess E (0.02, 0.1, 0.36, 1, 3), and "uniform_rate"
//                   (sigma' constant: the limit of a fast roll);
//   contact_width   "hertz" (the elastic patch) or "geometric" (unit width);
//   load_rule       "static" (F through the centre of mass), "dynamic" (the
//                   normal force and centre of pressure of the rolling motion
//                   itself: not defined under a uniform rate, which no free
//                   motion has), "uniform" (F / L along the ruling);
//   end_margin      the fraction of the ruling held at each loaded end
//                   (0.02, 0.05, 0.10);
//
// and over the score definitions (contact-time U; the accumulated pressure
// over the whole surface, the preprint's template, and over the touched
// surface; the per-pass peak pressure likewise and its peak-to-mean; the
// Basquin damage). Each comparison gets a verdict (comparison_verdict.h);
// where it flips along the rolling energy between two energies, the energy of
// the flip is interpolated (log ratio linear in log E) or, for the headline
// comparisons, found by bisection in log(E).
//
// The bodies are exact: the true oloid, the cylinder (r, L = 2r), the
// preprint's body (the paper family's (90, 1, 1) hull) and the two
// centre-line optima of the family (the U optimum (74.1, 0.757, 1.071) and
// the continuum FEM-SDS optimum (62.8, 0.996, 0.982): docs/results/optimize.md).
// Each is rolled once per energy (oracle/rolling_study.h); every other choice
// re-scores the same loop.
//
// The family: every genome of the preprint's quick grid is scored over the
// grid too, by the accumulated line-Hertz pressure over the whole surface
// (the continuum FEM-SDS without its FEM factor, fem_sds_continuum.h), one
// of each mirror pair (family_ranking.h); its five best at fem-sds's defaults (E = 0.1,
// geometric width, dynamic load, 5 % margin) are judged against the rest
// (family_ranking.h), and the best of them, "quick-grid-best", joins the
// bodies against the oloid.
#include "contact/continuum_loop_scores.h"
#include "geometry/body.h"
#include "oracle/search_grid.h"
#include "study/robustness/comparison_verdict.h"
#include "study/robustness/family_ranking.h"
#include <array>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::study::robustness
{
struct NamedBody
{
  std::string name;
  geometry::BodySpec spec;
};

/// The bodies named above, radius 1 m (the preprint's r1).
std::vector<NamedBody> default_bodies();

/// The grid named above.
std::vector<Choice> default_grid();

struct RobustnessSettings
{
  std::vector<NamedBody> bodies = default_bodies();
  std::vector<Choice> grid = default_grid();
  long samples_per_loop = 8000; ///< of each rolling loop
  int pieces = 64;              ///< Gauss pieces along each ruling
  double normal_load_n = 100;   ///< F (the preprint's)
  /// An energy flip is placed by interpolating log(ratio) linearly in log(E)
  /// between the grid's energies; for these comparisons it is then found by
  /// bisection in log(E) with new rolling runs.
  std::vector<std::string> bisected = {"oloid vs cylinder"};
  int bisection_steps = 8;
  /// The family whose best bodies are judged; none: no family.
  std::optional<oracle::SearchGrid> family = oracle::SearchGrid::quick;
  std::size_t family_best = 5;           ///< how many best bodies
  long family_samples_per_loop = 4000;   ///< of each genome's rolling loop
};

struct Comparison
{
  std::string name;                ///< e.g. "oloid vs cylinder"
  std::string score;               ///< a key of score_names()
  std::array<std::string, 2> bodies;
  Verdict verdict;
};

/// Per body, the scores at the default cell (E = 0.1, hertz, dynamic, 0.05)
/// and their relative change when the samples and the Gauss pieces double.
struct BodyConvergence
{
  std::string body;
  std::vector<std::pair<std::string, double>> scores, change;
};

struct RobustnessResult
{
  std::vector<Choice> grid;
  std::vector<std::string> bodies;
  std::vector<std::string> scores;
  /// values[body][score][cell] over grid_cells(grid); NaN where not defined.
  std::vector<std::vector<std::vector<double>>> values;
  std::vector<Comparison> comparisons;
  std::vector<BodyConvergence> convergence;
  std::optional<FamilyRanking> family;
  double wall_s = 0;
};

/// The score keys and what each measures.
std::vector<std::pair<std::string, std::string>> score_names();

RobustnessResult run_robustness(const RobustnessSettings& settings);

nlohmann::json to_json(const RobustnessResult& result);
/// The comparisons as a Markdown table.
std::string markdown_report(const RobustnessResult& result);
} // namespace rollcheck::study::robustness
