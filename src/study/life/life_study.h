#pragma once
// Wing of the study layer (study/life): does the oloid live longer? The
// rolling-contact fatigue life of the bodies of the robustness study
// (study/robustness/robustness.h) from the subsurface stress of every pass
// over one loop (loop_life.h), by the stress-volume integrals of
// Lundberg-Palmgren and Ioannides-Harris (stress_volume.h) of the
// closed-form field, verified against the FEM slice (fem_subsurface.h: its
// ratio to the closed form scales every body alike and cancels from the
// ratios), compared body against body as L10 life ratios at the
// same load and steel over the grid of modelling choices, each with the
// robustness study's verdict (comparison_verdict.h).
//
// The grid is the robustness study's without its contact width (the
// subsurface field needs the elastic half-width) and without the uniform
// rolling rate (a pass's life does not depend on how fast it rolls, and the
// rate enters only through the dynamic load, which a uniform rate does not
// define): rolling_energy x load_rule x end_margin.
//
// Each body is compared with the cylinder, and the oloid with each other
// body (the preprint's and the family's best). The rounded rim ends are
// added at the grid's default cell (rim_life.h).
#include "study/life/fem_subsurface.h"
#include "study/life/loop_life.h"
#include "study/life/rim_life.h"
#include "study/robustness/robustness.h"
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rollcheck::study::life
{
/// rolling_energy (0.02, 0.1, 0.36, 1, 3) x load_rule x end_margin (0.02, 0.05, 0.1).
std::vector<robustness::Choice> default_life_grid();

struct LifeSettings
{
  std::vector<robustness::NamedBody> bodies = robustness::default_bodies();
  std::vector<robustness::Choice> grid = default_life_grid();
  std::vector<double> loads_n = {100, 5000};  ///< the preprint's
  double cylinder_peak_pressure_pa = 1.5e9;   ///< and the load that gives the cylinder this peak
  long samples_per_loop = 4000;
  int pieces = 32;                            ///< Gauss pieces along each ruling
  double youngs_modulus_pa = 200e9, poisson_ratio = 0.3; ///< steel on steel
  LifeConstants constants;
  SubsurfaceSettings subsurface;
  /// The load-life exponent is measured on these loads (N), default cell.
  std::vector<double> exponent_loads_n = {100, 1000, 10000};
  RimLifeSettings rims;
  std::string end_ratios_path; ///< the rounded-end table; empty: default_rounded_end_ratios_path()
};

struct LifeComparison
{
  std::string name;      ///< "oloid vs cylinder"
  std::array<std::string, 2> bodies;
  double load_n = 0;
  std::string model;     ///< lundberg_palmgren, ioannides_harris
  std::string criterion; ///< orthogonal_shear, largest_shear
  robustness::Verdict verdict; ///< of L10(A) / L10(B): > 1, A lives longer
  std::array<int, 2> infinite_life_cells{}; ///< cells where A, B never reach the fatigue limit
  int grid_cells = 0;    ///< of the grid; the verdict's range is over its `cells` where both roll a whole loop
  std::string untested = {}; ///< why the comparison cannot be tested (empty: it can)
};

struct ExponentCheck
{
  std::string body;
  std::vector<double> integrals; ///< per exponent load, by direct depth quadrature
  double exponent = 0;           ///< least-squares slope of ln L10 against ln F, negated
  double table_agreement = 0;    ///< direct / tabulated integral - 1 at the middle load
};

/// The oloid-over-cylinder Lundberg-Palmgren life ratio (orthogonal shear) at
/// the grid's default cell at one load, at the run's loop quadrature and at
/// half of it (the loop rolled again at half the samples, half the Gauss
/// pieces along each ruling): the change says whether the quadrature has
/// converged (the life follows the highest pressures, which a coarse loop
/// misses).
struct QuadratureCheck
{
  double load_n = 0;
  double life_ratio = 0, life_ratio_half = 0;
  double change() const { return life_ratio / life_ratio_half - 1; }
};

struct DangVanCheck
{
  std::string body;
  double load_n = 0;
  double max_over_limit = 0; ///< the largest Dang Van stress over the grid / its value at the limit contact stress
};

struct LifeResult
{
  LifeSettings settings;
  std::vector<double> loads_n;    ///< settings' loads and the cylinder's peak-pressure load
  SubsurfaceCheck subsurface;
  double derived_exponent = 0;
  std::vector<ExponentCheck> exponents;
  std::vector<LifeComparison> comparisons;
  std::vector<DangVanCheck> dang_van;
  std::vector<QuadratureCheck> quadrature; ///< per load; empty without an oloid and a cylinder
  double dang_van_peak_over_p0 = 0, dang_van_peak_depth_over_b = 0;
  /// Bodies and energies whose run leaves the plane (a rim lifts) before
  /// completing a loop: their cells are not defined (NaN integrals).
  std::vector<std::pair<std::string, std::string>> incomplete_loops;
  /// integrals[body][load][key][cell], key: model_criterion.
  std::vector<std::vector<std::vector<std::vector<double>>>> integrals;
  std::vector<std::string> integral_keys;
  RoundedEndRatios end_ratios;
  std::vector<RimLife> rims; ///< per load, per body, at the grid's default cell
  std::map<std::string, std::string> rim_cell; ///< that cell's choices
  double wall_s = 0;
};

/// The load giving a cylinder (radius r, length L) the Hertz peak p0: pi r L p0^2 / E*.
double cylinder_load_for_peak(const geometry::BodySpec& cylinder, double peak_pressure_pa, double effective_modulus_pa);

LifeResult run_life(const LifeSettings& settings);

nlohmann::json to_json(const LifeResult& result);
/// The comparisons and checks as Markdown.
std::string markdown_report(const LifeResult& result);
} // namespace rollcheck::study::life
