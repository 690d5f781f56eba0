#include "study/life/life_study.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "core/json_number.h"
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <future>
#include <limits>
#include <map>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::study::life
{
namespace
{
using robustness::Cell;
using robustness::Choice;

const std::array<std::string, 2> model_names{"lundberg_palmgren", "ioannides_harris"};
const std::array<std::string, 2> criterion_names{"orthogonal_shear", "largest_shear"};

int choice_index(const std::vector<Choice>& grid, const std::string& name)
{
  for (std::size_t c = 0; c < grid.size(); ++c)
    if (grid[c].name == name)
      return static_cast<int>(c);
  throw InputError(fmt::format("life: the grid has no choice '{}'", name));
}

const std::string& value_of(const std::vector<Choice>& grid, const Cell& cell, const std::string& name)
{
  const int c = choice_index(grid, name);
  return grid[c].values[cell[c]];
}

/// Rolling runs per body and energy, made once (two bodies at a time).
using Runs = std::vector<std::map<std::string, oracle::RealRolling>>;

Runs roll_every_body(const LifeSettings& s)
{
  const std::vector<std::string>& energies = s.grid[choice_index(s.grid, "rolling_energy")].values;
  Runs runs(s.bodies.size());
  auto roll = [&](std::size_t b) {
    oracle::RollingStudyParameters p;
    p.samples_per_loop = s.samples_per_loop;
    const oracle::RollingMass mass = oracle::rolling_mass(s.bodies[b].spec, p); // the same at every energy
    for (const std::string& energy : energies)
    {
      p.rolling_energy = std::stod(energy);
      runs[b].emplace(energy, oracle::real_rolling(s.bodies[b].spec, p, mass));
    }
    spdlog::info("life: {} rolled at {} energies", s.bodies[b].name, energies.size());
  };
  for (std::size_t b = 0; b < s.bodies.size(); b += 2)
  {
    auto second = b + 1 < s.bodies.size() ? std::async(std::launch::async, roll, b + 1) : std::future<void>{};
    roll(b);
    if (second.valid())
      second.get();
  }
  return runs;
}

LoopLifeSettings loop_settings(const LifeSettings& s, const Cell& cell, double load_n)
{
  LoopLifeSettings l;
  l.load_rule = parse_named(contact::load_rule_names(), value_of(s.grid, cell, "load_rule"), "load rule", "life grid");
  l.end_margin = std::stod(value_of(s.grid, cell, "end_margin"));
  l.normal_load_n = load_n;
  l.effective_modulus_pa = contact::effective_modulus_identical_bodies(s.youngs_modulus_pa, s.poisson_ratio);
  l.pieces = s.pieces;
  return l;
}

/// L10(A) / L10(B) = (I_B / I_A)^(1 / e); none where both live for ever.
std::optional<double> life_ratio(double integral_a, double integral_b, double weibull_slope)
{
  if (std::isnan(integral_a) || std::isnan(integral_b) || (integral_a == 0 && integral_b == 0))
    return std::nullopt;
  if (integral_a == 0)
    return std::numeric_limits<double>::infinity();
  return std::pow(integral_b / integral_a, 1 / weibull_slope);
}

/// The range of the half-widths b of a loop's passes.
std::pair<double, double> half_width_range(const oracle::RealRolling& run, const LoopLifeSettings& l)
{
  double lo = INFINITY, hi = 0;
  for_each_loaded_element(run, l, [&](const LoadedElement& e) {
    lo = std::min(lo, e.half_width_m), hi = std::max(hi, e.half_width_m);
  });
  return {lo, hi};
}

/// Lundberg-Palmgren's integral of the orthogonal shear by direct quadrature
/// over absolute depth (one depth grid for every load, covering 1e-3 of the
/// smallest b to 10 times the largest) at each exponent load, on the
/// robustness study's default cell (E = 0.1, dynamic, margin 0.05), 4 Gauss
/// pieces per ruling; the exponent is the least-squares slope of
/// ln L10 = -ln(I) / e + const against ln F, negated.
ExponentCheck measure_exponent(const LifeSettings& s, const std::string& body, const oracle::RealRolling& run,
                               const std::array<const DepthIntegrals*, 2>& tables)
{
  const Cell cell = {1, 1, 1};
  auto settings_at = [&](double load) {
    LoopLifeSettings l = loop_settings(s, cell, load);
    l.pieces = 4;
    return l;
  };
  const double z_lo = 1e-3 * half_width_range(run, settings_at(s.exponent_loads_n.front())).first;
  const double z_hi = 10 * half_width_range(run, settings_at(s.exponent_loads_n.back())).second;
  const int depths = static_cast<int>(std::ceil(500 * std::log10(z_hi / z_lo))); // the tables' density
  ExponentCheck e{body, {}, 0, 0};
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(s.exponent_loads_n.size());
  for (const double load : s.exponent_loads_n)
  {
    const double integral = lundberg_palmgren_by_depth(run, settings_at(load), s.constants, *tables[0], z_lo, z_hi, depths);
    e.integrals.push_back(integral);
    const double x = std::log(load), y = -std::log(integral) / s.constants.weibull_slope;
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  e.exponent = -(n * sxy - sx * sy) / (n * sxx - sx * sx);
  const std::size_t middle = s.exponent_loads_n.size() / 2;
  const LoopIntegrals tabulated
      = loop_integrals(run, settings_at(s.exponent_loads_n[middle]), s.constants, tables, {1.0, 1.0}, *tables[0]);
  e.table_agreement = e.integrals[middle] / tabulated.lundberg_palmgren[0] - 1;
  return e;
}


/// The pairs compared: every body against the cylinder, the oloid against every other body.
std::vector<std::pair<std::size_t, std::size_t>> compared_pairs(const std::vector<robustness::NamedBody>& bodies)
{
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (a != b && bodies[b].spec.body == "cylinder")
        pairs.emplace_back(a, b);
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (a != b && bodies[a].name == "oloid" && bodies[b].spec.body != "cylinder")
        pairs.emplace_back(a, b);
  return pairs;
}

/// L10(A) / L10(B) of integral key k at load l over the grid, with its verdict, and why it cannot be tested.
LifeComparison compare(const LifeSettings& s, const LifeResult& r, const std::vector<Cell>& cells, std::size_t a,
                       std::size_t b, std::size_t l, int k)
{
  LifeComparison c{s.bodies[a].name + " vs " + s.bodies[b].name,
                   {s.bodies[a].name, s.bodies[b].name},
                   r.loads_n[l], model_names[k / 2], criterion_names[k % 2], {}};
  const auto& ia = r.integrals[a][l][k];
  const auto& ib = r.integrals[b][l][k];
  c.verdict = robustness::judge_comparison(s.grid, [&](const Cell& cell) {
    const std::size_t i = std::lower_bound(cells.begin(), cells.end(), cell) - cells.begin();
    return life_ratio(ia[i], ib[i], s.constants.weibull_slope);
  });
  int rolled = 0;
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    c.infinite_life_cells[0] += ia[i] == 0, c.infinite_life_cells[1] += ib[i] == 0;
    rolled += !std::isnan(ia[i]) && !std::isnan(ib[i]);
  }
  c.grid_cells = static_cast<int>(cells.size());
  if (c.verdict.cells == 0)
    c.untested = rolled == 0 ? "neither body rolls a whole loop in any cell of the grid"
                             : fmt::format("neither body's {} reaches its fatigue limit (the stress at a {:.3g} GPa "
                                           "contact) anywhere in the {} cells where both roll a whole loop: both "
                                           "lives are infinite at {:.4g} N",
                                           c.criterion, s.constants.fatigue_limit_contact_pa / 1e9, rolled, c.load_n);
  return c;
}
} // namespace

std::vector<Choice> default_life_grid()
{
  return {{"rolling_energy", {"0.02", "0.1", "0.36", "1", "3"}},
          {"load_rule", {"static", "dynamic", "uniform"}},
          {"end_margin", {"0.02", "0.05", "0.1"}}};
}

double cylinder_load_for_peak(const geometry::BodySpec& cylinder, double p0, double e_star)
{
  return std::numbers::pi * cylinder.radius_m * cylinder.height_m * p0 * p0 / e_star;
}

/// QuadratureCheck at each load, for the bodies named "oloid" and the
/// cylinder; none without both.
std::vector<QuadratureCheck> check_quadrature(const LifeSettings& s, const LifeResult& r, const Runs& runs,
                                              const Cell& cell, const std::array<const DepthIntegrals*, 2>& tables,
                                              const std::array<double, 2>& ratio, const DepthIntegrals& dang_van)
{
  std::optional<std::size_t> oloid, cylinder;
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (s.bodies[b].name == "oloid")
      oloid = b;
    else if (s.bodies[b].spec.body == "cylinder")
      cylinder = b;
  if (!oloid || !cylinder)
    return {};
  const std::string& energy = value_of(s.grid, cell, "rolling_energy");
  auto half_run = [&](std::size_t b) {
    oracle::RollingStudyParameters p;
    p.rolling_energy = std::stod(energy);
    p.samples_per_loop = std::max<long>(2, s.samples_per_loop / 2);
    return oracle::real_rolling(s.bodies[b].spec, p);
  };
  const oracle::RealRolling half_oloid = half_run(*oloid), half_cylinder = half_run(*cylinder);
  std::vector<QuadratureCheck> checks;
  for (const double load : r.loads_n)
  {
    LoopLifeSettings full = loop_settings(s, cell, load), half = full;
    half.pieces = std::max(1, full.pieces / 2);
    auto integral = [&](const oracle::RealRolling& run, const LoopLifeSettings& l) {
      return loop_integrals(run, l, s.constants, tables, ratio, dang_van).lundberg_palmgren[0];
    };
    const double slope = s.constants.weibull_slope;
    QuadratureCheck q{load,
                      life_ratio(integral(runs[*oloid].at(energy), full), integral(runs[*cylinder].at(energy), full),
                                 slope).value_or(NAN),
                      life_ratio(integral(half_oloid, half), integral(half_cylinder, half), slope).value_or(NAN)};
    if (!(std::abs(q.change()) < 0.05))
      spdlog::warn("life: the oloid / cylinder life ratio at {:g} N changes by {:+.1f} % from half the loop's "
                   "quadrature: raise --samples-per-loop and --pieces",
                   load, 100 * q.change());
    checks.push_back(q);
  }
  return checks;
}

LifeResult run_life(const LifeSettings& s)
{
  const auto start = std::chrono::steady_clock::now();
  if (s.loads_n.empty() || s.exponent_loads_n.size() < 2)
    throw InputError("life: needs at least one load and two exponent loads");
  LifeResult r;
  r.settings = s;
  validate(s.rims);
  r.end_ratios = read_rounded_end_ratios(s.end_ratios_path.empty() ? default_rounded_end_ratios_path()
                                                                   : std::filesystem::path(s.end_ratios_path));
  r.derived_exponent = derived_load_life_exponent(s.constants);
  const double e_star = contact::effective_modulus_identical_bodies(s.youngs_modulus_pa, s.poisson_ratio);
  r.loads_n = s.loads_n;
  for (const auto& body : s.bodies)
    if (body.spec.body == "cylinder")
      r.loads_n.push_back(cylinder_load_for_peak(body.spec, s.cylinder_peak_pressure_pa, e_star));
  r.subsurface = check_subsurface(s.subsurface, s.poisson_ratio);
  const DepthIntegrals orthogonal(contact::FatigueCriterion::orthogonal_shear, s.constants);
  const DepthIntegrals largest(contact::FatigueCriterion::largest_shear, s.constants);
  const DepthIntegrals dang_van(contact::FatigueCriterion::dang_van, s.constants);
  r.dang_van_peak_over_p0 = dang_van.peak();
  r.dang_van_peak_depth_over_b = dang_van.peak_depth();
  const std::array<const DepthIntegrals*, 2> tables{&orthogonal, &largest};
  const std::array<double, 2> ratio{r.subsurface.orthogonal_shear_ratio, r.subsurface.max_shear_ratio};
  const Runs runs = roll_every_body(s);
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (s.bodies[b].name == "oloid" || s.bodies[b].spec.body == "cylinder")
      r.exponents.push_back(measure_exponent(s, s.bodies[b].name, runs[b].at("0.1"), tables));
  const std::vector<Cell> cells = robustness::grid_cells(s.grid);
  for (const std::string& m : model_names)
    for (const std::string& c : criterion_names)
      r.integral_keys.push_back(m + "_" + c);
  r.integrals.assign(s.bodies.size(), std::vector(r.loads_n.size(), std::vector(4, std::vector<double>(cells.size()))));
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (const auto& [energy, run] : runs[b])
      if (!std::isfinite(run.first_loop_end_s))
        r.incomplete_loops.emplace_back(s.bodies[b].name, energy);
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (std::size_t l = 0; l < r.loads_n.size(); ++l)
    {
      double largest_dang_van = 0;
      for (std::size_t i = 0; i < cells.size(); ++i)
      {
        if (!std::isfinite(runs[b].at(value_of(s.grid, cells[i], "rolling_energy")).first_loop_end_s))
        {
          for (auto& key : r.integrals[b][l])
            key[i] = std::numeric_limits<double>::quiet_NaN(); // not a rolling loop
          continue;
        }
        const LoopIntegrals li = loop_integrals(runs[b].at(value_of(s.grid, cells[i], "rolling_energy")),
                                                loop_settings(s, cells[i], r.loads_n[l]), s.constants, tables, ratio,
                                                dang_van);
        for (int c = 0; c < 2; ++c)
          r.integrals[b][l][c][i] = li.lundberg_palmgren[c], r.integrals[b][l][2 + c][i] = li.ioannides_harris[c];
        largest_dang_van = std::max(largest_dang_van, li.max_dang_van_pa);
      }
      r.dang_van.push_back({s.bodies[b].name, r.loads_n[l],
                            largest_dang_van / (dang_van.peak() * s.constants.fatigue_limit_contact_pa)});
    }
  for (const auto& [a, b] : compared_pairs(s.bodies))
    for (std::size_t l = 0; l < r.loads_n.size(); ++l)
      for (int k = 0; k < 4; ++k)
        r.comparisons.push_back(compare(s, r, cells, a, b, l, k));
  const Cell defaults = {1, 1, 1};
  for (std::size_t c = 0; c < s.grid.size(); ++c)
    r.rim_cell[s.grid[c].name] = s.grid[c].values[defaults[c]];
  std::vector<const oracle::RealRolling*> default_runs;
  std::optional<std::size_t> cylinder;
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
  {
    default_runs.push_back(&runs[b].at(value_of(s.grid, defaults, "rolling_energy")));
    if (s.bodies[b].spec.body == "cylinder")
      cylinder = b;
  }
  r.quadrature = check_quadrature(s, r, runs, defaults, tables, ratio, dang_van);
  r.rims = rim_lives(s.rims, s.bodies, default_runs, r.loads_n,
                     [&](double load) { return loop_settings(s, defaults, load); }, s.constants, tables, ratio,
                     r.end_ratios, cylinder);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}
} // namespace rollcheck::study::life
