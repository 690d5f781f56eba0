#include "study/robustness/robustness.h"
#include "core/error.h"
#include "core/json_number.h"
#include "oracle/rolling_study.h"
#include <chrono>
#include <cmath>
#include <algorithm>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <optional>
#include <future>
#include <mutex>
#include <set>
#include <tuple>
#include <spdlog/spdlog.h>

namespace rollcheck::study::robustness
{
namespace
{
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// The settings of one cell, read from the grid by the choices' names.
struct CellSettings
{
  double energy_excess = 0.1;
  bool uniform_rate = false;
  contact::ContinuumLoopSettings scores;
};

int choice_index(const std::vector<Choice>& grid, const std::string& name)
{
  for (std::size_t c = 0; c < grid.size(); ++c)
    if (grid[c].name == name)
      return static_cast<int>(c);
  throw InputError(fmt::format("robustness: the grid has no choice '{}'", name));
}

CellSettings decode(const std::vector<Choice>& grid, const Cell& cell, const RobustnessSettings& s)
{
  CellSettings c;
  const std::string& energy = grid[choice_index(grid, "rolling_energy")].values[cell[choice_index(grid, "rolling_energy")]];
  c.uniform_rate = energy == "uniform_rate";
  c.energy_excess = c.uniform_rate ? 0.1 : std::stod(energy); // a uniform rate re-times the loop of E = 0.1
  const std::string& width = grid[choice_index(grid, "contact_width")].values[cell[choice_index(grid, "contact_width")]];
  c.scores.width = width == "hertz" ? oracle::ContactWidthModel::hertz : oracle::ContactWidthModel::rigid;
  c.scores.load_rule = parse_named(contact::load_rule_names(),
                                    grid[choice_index(grid, "load_rule")].values[cell[choice_index(grid, "load_rule")]],
                                    "load rule", "robustness grid");
  c.scores.end_margin = std::stod(grid[choice_index(grid, "end_margin")].values[cell[choice_index(grid, "end_margin")]]);
  c.scores.time_law = c.uniform_rate ? contact::TimeLaw::uniform_rate : contact::TimeLaw::free_rolling;
  c.scores.normal_load_n = s.normal_load_n;
  c.scores.pieces = s.pieces;
  return c;
}

/// Rolling runs of each body, one per energy, kept for every cell and
/// bisection; each body's mass model (its hull, the same at every energy)
/// built once. Safe to share between threads that each work on other bodies.
class Runs
{
public:
  explicit Runs(const std::vector<NamedBody>& bodies) : bodies_(bodies) {}
  const oracle::RealRolling& at(int body, double energy_excess, long samples_per_loop)
  {
    const auto key = std::tuple{body, energy_excess, samples_per_loop};
    const oracle::RollingMass* mass = nullptr;
    {
      std::lock_guard lock(mutex_);
      if (auto it = runs_.find(key); it != runs_.end())
        return it->second;
      if (auto it = masses_.find(body); it != masses_.end())
        mass = &it->second;
    }
    oracle::RollingStudyParameters p;
    p.rolling_energy = energy_excess;
    p.samples_per_loop = samples_per_loop;
    const geometry::BodySpec& spec = bodies_[body].spec;
    if (!mass)
    {
      oracle::RollingMass built = oracle::rolling_mass(spec, p);
      std::lock_guard lock(mutex_);
      mass = &masses_.emplace(body, std::move(built)).first->second; // std::map: references stay valid
    }
    oracle::RealRolling run = oracle::real_rolling(spec, p, *mass);
    std::lock_guard lock(mutex_);
    return runs_.emplace(key, std::move(run)).first->second;
  }

private:
  const std::vector<NamedBody>& bodies_;
  std::mutex mutex_;
  std::map<std::tuple<int, double, long>, oracle::RealRolling> runs_;
  std::map<int, oracle::RollingMass> masses_;
};

/// The scores over the run's first whole loop (callers skip a run whose rim
/// lifts before the loop closes: a part of a loop is not a loop's score).
contact::ContinuumLoopScores scores_of(const oracle::RealRolling& run, const contact::ContinuumLoopSettings& s)
{
  const contact::RollingBodyMass mass{run.mass.centre_of_mass_m, run.mass.mass_kg, 9.81};
  return contact::continuum_loop_scores(run.trajectory, 0, run.first_loop_end_s, run.surface_area_m2, mass, s);
}

/// The score keys' values from one evaluation, in score_names() order.
std::vector<double> pick(const contact::ContinuumLoopScores& r)
{
  return {r.contact_time.whole,  r.accumulated_pressure.whole, r.accumulated_pressure.touched, r.peak_pressure.whole,
          r.peak_pressure.touched, r.peak_pressure.peak_to_mean, r.damage.whole};
}

/// Every score of body b at a cell; NaN where the model does not apply.
std::vector<double> evaluate(Runs& runs, int b, const CellSettings& c, long samples_per_loop)
{
  if (c.uniform_rate && c.scores.load_rule == contact::LoadRule::dynamic)
    return std::vector<double>(score_names().size(), nan); // no free motion rolls at a uniform rate
  const oracle::RealRolling& run = runs.at(b, c.energy_excess, samples_per_loop);
  if (!run.trajectory.contact_held || !std::isfinite(run.first_loop_end_s))
    return std::vector<double>(score_names().size(), nan); // a rim lifts before the loop closes
  return pick(scores_of(run, c.scores));
}

std::optional<double> ratio(double a, double b)
{
  if (std::isnan(a) || std::isnan(b) || (a == 0 && b == 0))
    return std::nullopt;
  return b == 0 ? std::numeric_limits<double>::infinity() : a / b;
}

/// Places a flip along the rolling energy between two numeric energies of
/// the grid: log(ratio) interpolated linearly in log(E) at the grid's two
/// ratios, then, if `bisect`, bisection in log(E) with the other choices held.
/// The interpolation alone; false if either energy is the uniform rate.
bool interpolate_energy_flip(Flip& flip, const std::vector<Choice>& grid, double ratio_from, double ratio_to)
{
  const auto& values = grid[flip.choice].values;
  if (values[flip.from] == "uniform_rate" || values[flip.to] == "uniform_rate")
    return false;
  const double lo = std::stod(values[flip.from]), hi = std::stod(values[flip.to]);
  const double a = std::log(ratio_from), b = std::log(ratio_to);
  flip.value = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * a / (a - b));
  return true;
}

void refine_energy_flip(Flip& flip, const std::vector<Choice>& grid, const std::vector<int>& body_index, int score,
                        double ratio_from, double ratio_to, bool bisect, Runs& runs, const RobustnessSettings& s)
{
  if (!interpolate_energy_flip(flip, grid, ratio_from, ratio_to) || !bisect || !std::isfinite(std::log(ratio_from))
      || !std::isfinite(std::log(ratio_to)))
    return;
  const auto& values = grid[flip.choice].values;
  double lo = std::stod(values[flip.from]), hi = std::stod(values[flip.to]);
  CellSettings c = decode(grid, flip.cell, s);
  auto r_at = [&](double energy) {
    c.energy_excess = energy;
    const double x = evaluate(runs, body_index[0], c, s.samples_per_loop)[score];
    const double y = evaluate(runs, body_index[1], c, s.samples_per_loop)[score];
    return ratio(x, y).value_or(nan);
  };
  const bool below_at_lo = ratio_from < 1;
  for (int k = 0; k < s.bisection_steps; ++k)
  {
    const double mid = std::sqrt(lo * hi);
    (r_at(mid) < 1) == below_at_lo ? lo = mid : hi = mid;
  }
  flip.value = std::sqrt(lo * hi);
}

std::vector<BodyConvergence> convergence(Runs& runs, const std::vector<NamedBody>& bodies, const RobustnessSettings& s)
{
  std::vector<BodyConvergence> out;
  const auto names = score_names();
  for (std::size_t b = 0; b < bodies.size(); ++b)
  {
    CellSettings c;
    c.scores.normal_load_n = s.normal_load_n;
    c.scores.pieces = s.pieces;
    const std::vector<double> base = evaluate(runs, static_cast<int>(b), c, s.samples_per_loop);
    c.scores.pieces = 2 * s.pieces;
    const std::vector<double> fine = evaluate(runs, static_cast<int>(b), c, 2 * s.samples_per_loop);
    BodyConvergence bc{bodies[b].name, {}, {}};
    for (std::size_t k = 0; k < names.size(); ++k)
    {
      bc.scores.emplace_back(names[k].first, base[k]);
      bc.change.emplace_back(names[k].first, base[k] != 0 ? fine[k] / base[k] - 1 : fine[k]);
    }
    out.push_back(bc);
  }
  return out;
}

/// The index in grid_cells(grid) of the cell with these values, by choice name.
std::size_t cell_index(const std::vector<Choice>& grid, const std::vector<Cell>& cells,
                       const std::vector<std::pair<std::string, std::string>>& values)
{
  Cell cell(grid.size(), 0);
  for (const auto& [name, value] : values)
  {
    const auto& choices = grid[choice_index(grid, name)].values;
    const auto it = std::find(choices.begin(), choices.end(), value);
    if (it == choices.end())
      throw InputError(fmt::format("robustness: the grid's choice '{}' has no value '{}'", name, value));
    cell[choice_index(grid, name)] = static_cast<int>(it - choices.begin());
  }
  return std::lower_bound(cells.begin(), cells.end(), cell) - cells.begin();
}

/// One genome's `score` over every cell: each energy rolled once, without
/// keeping the run; NaN where it has no whole loop.
std::vector<double> genome_values(const geometry::BodySpec& spec, const std::vector<Cell>& cells, int score,
                                  const RobustnessSettings& s)
{
  std::vector<double> values(cells.size(), nan);
  std::map<double, std::vector<std::size_t>> by_energy;
  for (std::size_t i = 0; i < cells.size(); ++i)
    by_energy[decode(s.grid, cells[i], s).energy_excess].push_back(i);
  std::optional<oracle::RollingMass> mass; // the same at every energy: built once
  for (const auto& [energy, at] : by_energy)
  {
    oracle::RollingStudyParameters p;
    p.rolling_energy = energy;
    p.samples_per_loop = s.family_samples_per_loop;
    oracle::RealRolling run;
    try
    {
      if (!mass)
        mass = oracle::rolling_mass(spec, p);
      run = oracle::real_rolling(spec, p, *mass);
    }
    catch (const InputError&)
    {
      continue; // it cannot roll over its potential barrier
    }
    if (!run.trajectory.contact_held || !std::isfinite(run.first_loop_end_s))
      continue; // a rim lifts before the loop closes
    for (const std::size_t i : at)
    {
      const CellSettings c = decode(s.grid, cells[i], s);
      if (!(c.uniform_rate && c.scores.load_rule == contact::LoadRule::dynamic))
        values[i] = pick(scores_of(run, c.scores))[score];
    }
  }
  return values;
}

/// The family's distinct bodies over the grid, two at a time, and its best at
/// the reference cell by the accumulated line-Hertz pressure (g = 1 of the
/// continuum FEM-SDS).
FamilyRanking rank_family(oracle::SearchGrid grid, const std::vector<Cell>& cells, const RobustnessSettings& s)
{
  FamilyRanking r;
  r.grid = std::string(oracle::name_of(grid));
  r.score = "accumulated_pressure_whole";
  const auto names = score_names();
  const int score = static_cast<int>(
      std::find_if(names.begin(), names.end(), [&](const auto& n) { return n.first == r.score; }) - names.begin());
  r.reference_cell = cell_index(s.grid, cells, {{"rolling_energy", "0.1"}, {"contact_width", "geometric"},
                                                 {"load_rule", "dynamic"}, {"end_margin", "0.05"}});
  const std::vector<geometry::RollerGenome> all = oracle::search_grid(grid);
  for (const geometry::RollerGenome& genome : distinct_bodies(all))
    r.genomes.push_back({genome, {}});
  r.mirrors_merged = all.size() - r.genomes.size();
  auto spec_of = [&](std::size_t g) {
    geometry::BodySpec spec;
    spec.body = "roller";
    spec.family = geometry::RollerFamily::paper;
    spec.genome = r.genomes[g].genome;
    return spec;
  };
  auto score_range = [&](std::size_t from, std::size_t step) {
    for (std::size_t g = from; g < r.genomes.size(); g += step)
      r.genomes[g].values = genome_values(spec_of(g), cells, score, s);
  };
  auto second = std::async(std::launch::async, score_range, 1, 2);
  score_range(0, 2);
  second.get();
  r.best = best_genomes(r.genomes, r.reference_cell, s.family_best);
  spdlog::info("robustness: the {} grid's {} genomes scored over {} cells", r.grid, r.genomes.size(), cells.size());
  return r;
}

/// Whether the family's best stay its best over the grid; flips along the
/// rolling energy placed by interpolation.
Comparison family_comparison(const FamilyRanking& family, const std::vector<Cell>& cells, const std::vector<Choice>& grid)
{
  std::string best;
  for (const std::size_t g : family.best)
    best += (best.empty() ? "" : " ") + genome_label(family.genomes[g].genome);
  Comparison c{fmt::format("the {} grid's {} best", family.grid, family.best.size()),
               family.score,
               {fmt::format("the {} best: {}", family.best.size(), best), fmt::format("the rest of the {} grid", family.grid)},
               {}};
  auto ratio_at = [&](const Cell& cell) {
    return best_against_rest(family, std::lower_bound(cells.begin(), cells.end(), cell) - cells.begin());
  };
  c.verdict = judge_comparison(grid, ratio_at);
  const int energy = choice_index(grid, "rolling_energy");
  for (Flip& flip : c.verdict.flips)
    if (flip.choice == energy)
    {
      Cell next = flip.cell;
      next[flip.choice] = flip.to;
      interpolate_energy_flip(flip, grid, *ratio_at(flip.cell), *ratio_at(next));
    }
  return c;
}

nlohmann::json flip_json(const Flip& flip, const std::vector<Choice>& grid)
{
  nlohmann::json settings = nlohmann::json::object();
  for (std::size_t c = 0; c < grid.size(); ++c)
    if (static_cast<int>(c) != flip.choice)
      settings[grid[c].name] = grid[c].values[flip.cell[c]];
  const auto& values = grid[flip.choice].values;
  nlohmann::json j{{"choice", grid[flip.choice].name},
                   {"from", values[flip.from]},
                   {"to", values[flip.to]},
                   {"settings", settings}};
  j["value"] = flip.value ? nlohmann::json(json_number(*flip.value)) : nlohmann::json(values[flip.to]);
  return j;
}
} // namespace

std::vector<NamedBody> default_bodies()
{
  auto roller = [](double theta, double offset, double ratio) {
    geometry::BodySpec spec;
    spec.body = "roller";
    spec.family = geometry::RollerFamily::centre_line;
    spec.genome = {theta, offset, ratio, 2};
    return spec;
  };
  geometry::BodySpec oloid, cylinder, paper;
  cylinder.body = "cylinder";
  paper.body = "paper-oloid";
  return {{"oloid", oloid},
          {"cylinder", cylinder},
          {"paper-oloid", paper},
          {"u-optimum", roller(74.1, 0.757, 1.071)},
          {"fem-sds-optimum", roller(62.8, 0.996, 0.982)}};
}

std::vector<Choice> default_grid()
{
  return {{"rolling_energy", {"0.02", "0.1", "0.36", "1", "3", "uniform_rate"}},
          {"contact_width", {"hertz", "geometric"}},
          {"load_rule", {"static", "dynamic", "uniform"}},
          {"end_margin", {"0.02", "0.05", "0.1"}}};
}

std::vector<std::pair<std::string, std::string>> score_names()
{
  return {{"contact_time_u", "contact-time uniformity U_inf over the whole surface"},
          {"accumulated_pressure_whole", "accumulated pressure over the whole surface (the preprint's SDS template)"},
          {"accumulated_pressure_touched", "accumulated pressure over the touched surface"},
          {"peak_pressure_whole", "per-pass peak pressure over the whole surface"},
          {"peak_pressure_touched", "per-pass peak pressure over the touched surface"},
          {"peak_to_mean_pressure", "largest per-pass peak pressure over its mean on the touched surface"},
          {"basquin_damage_whole", "Basquin damage per loop over the whole surface"}};
}

RobustnessResult run_robustness(const RobustnessSettings& s)
{
  const auto start = std::chrono::steady_clock::now();
  RobustnessResult result;
  result.grid = s.grid;
  for (const auto& [key, what] : score_names())
    result.scores.push_back(key);
  const std::vector<Cell> cells = grid_cells(s.grid);
  std::vector<NamedBody> bodies = s.bodies;
  if (s.family)
  {
    result.family = rank_family(*s.family, cells, s);
    if (!result.family->best.empty())
    {
      geometry::BodySpec best;
      best.body = "roller";
      best.family = geometry::RollerFamily::paper;
      best.genome = result.family->genomes[result.family->best.front()].genome;
      bodies.push_back({"quick-grid-best", best});
    }
  }
  Runs runs(bodies);
  // Every body over the grid, two bodies at a time (each body's runs are its own).
  auto score_body = [&](std::size_t b) {
    std::vector<std::vector<double>> by_score(result.scores.size(), std::vector<double>(cells.size(), nan));
    for (std::size_t i = 0; i < cells.size(); ++i)
    {
      const std::vector<double> v = evaluate(runs, static_cast<int>(b), decode(s.grid, cells[i], s), s.samples_per_loop);
      for (std::size_t k = 0; k < v.size(); ++k)
        by_score[k][i] = v[k];
    }
    spdlog::info("robustness: {} scored over {} cells", bodies[b].name, cells.size());
    return by_score;
  };
  result.values.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); b += 2)
  {
    auto second = b + 1 < bodies.size() ? std::async(std::launch::async, score_body, b + 1)
                                           : std::future<std::vector<std::vector<double>>>{};
    result.values[b] = score_body(b);
    if (second.valid())
      result.values[b + 1] = second.get();
  }
  for (const NamedBody& body : bodies)
    result.bodies.push_back(body.name);
  const std::vector<std::array<std::string, 3>> pairs = {{"oloid vs cylinder", "oloid", "cylinder"},
                                                         {"oloid vs the preprint's body", "oloid", "paper-oloid"},
                                                         {"U optimum vs oloid", "u-optimum", "oloid"},
                                                         {"FEM-SDS optimum vs oloid", "fem-sds-optimum", "oloid"},
                                                         {"quick-grid best vs oloid", "quick-grid-best", "oloid"}};
  auto index_of = [&](const std::string& name) {
    for (std::size_t b = 0; b < result.bodies.size(); ++b)
      if (result.bodies[b] == name)
        return static_cast<int>(b);
    return -1;
  };
  const int energy_choice = choice_index(s.grid, "rolling_energy");
  for (const auto& [name, a, b] : pairs)
  {
    const std::vector<int> body_index{index_of(a), index_of(b)};
    if (body_index[0] < 0 || body_index[1] < 0)
      continue;
    for (std::size_t k = 0; k < result.scores.size(); ++k)
    {
      Comparison c{name, result.scores[k], {a, b}, {}};
      auto ratio_at = [&](const Cell& cell) {
        const std::size_t i = std::lower_bound(cells.begin(), cells.end(), cell) - cells.begin();
        return ratio(result.values[body_index[0]][k][i], result.values[body_index[1]][k][i]);
      };
      c.verdict = judge_comparison(s.grid, ratio_at);
      const bool bisect = std::find(s.bisected.begin(), s.bisected.end(), name) != s.bisected.end();
      for (Flip& flip : c.verdict.flips)
        if (flip.choice == energy_choice)
        {
          Cell next = flip.cell;
          next[flip.choice] = flip.to;
          refine_energy_flip(flip, s.grid, body_index, static_cast<int>(k), *ratio_at(flip.cell), *ratio_at(next),
                             bisect, runs, s);
        }
      result.comparisons.push_back(std::move(c));
    }
  }
  if (result.family)
    result.comparisons.push_back(family_comparison(*result.family, cells, s.grid));
  result.convergence = convergence(runs, bodies, s);
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

nlohmann::json to_json(const RobustnessResult& r)
{
  nlohmann::json grid = nlohmann::json::object(), order = nlohmann::json::array();
  for (const Choice& c : r.grid)
    grid[c.name] = c.values, order.push_back(c.name);
  nlohmann::json comparisons = nlohmann::json::array();
  for (const Comparison& c : r.comparisons)
  {
    nlohmann::json flips = nlohmann::json::array();
    for (const Flip& f : c.verdict.flips)
      flips.push_back(flip_json(f, r.grid));
    comparisons.push_back({{"name", c.name},
                           {"score", c.score},
                           {"bodies", c.bodies},
                           {"verdict", c.verdict.text},
                           {"ratio_min", c.verdict.cells > 0 ? json_number(c.verdict.ratio_min) : nlohmann::json()},
                           {"ratio_max", c.verdict.cells > 0 ? json_number(c.verdict.ratio_max) : nlohmann::json()},
                           {"cells", c.verdict.cells},
                           {"flips", flips}});
  }
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t b = 0; b < r.bodies.size(); ++b)
    for (std::size_t k = 0; k < r.scores.size(); ++k)
    {
      nlohmann::json row = nlohmann::json::array();
      for (double v : r.values[b][k])
        row.push_back(json_number_or_null(v));
      values[r.bodies[b]][r.scores[k]] = row;
    }
  nlohmann::json conv = nlohmann::json::array();
  for (const BodyConvergence& bc : r.convergence)
  {
    nlohmann::json scores = nlohmann::json::object(), change = nlohmann::json::object();
    for (const auto& [k, v] : bc.scores)
      scores[k] = json_number_or_null(v);
    for (const auto& [k, v] : bc.change)
      change[k] = json_number_or_null(v);
    conv.push_back({{"body", bc.body}, {"scores_default_cell", scores}, {"change_doubled_resolution", change}});
  }
  nlohmann::json names = nlohmann::json::object();
  for (const auto& [k, what] : score_names())
    names[k] = what;
  nlohmann::json j = {{"grid", grid},           {"bodies", r.bodies},           {"scores", names},
                      {"comparisons", comparisons}, {"values", values},         {"grid_order", order},
                      {"convergence", conv},    {"wall_s", r.wall_s}};
  j["family"] = r.family ? to_json(*r.family, r.grid) : nlohmann::json(nullptr);
  return j;
}

std::string markdown_report(const RobustnessResult& r)
{
  std::string out = "| comparison | score | verdict | ratio min | ratio max | where the ranking flips |\n"
                    "|---|---|---|---|---|---|\n";
  for (const Comparison& c : r.comparisons)
  {
    // Each distinct flip once: an energy with the width and load rule it
    // holds at (the margin rarely moves it), or the categorical choice.
    std::set<std::string> seen;
    std::string flips;
    for (const Flip& f : c.verdict.flips)
    {
      const auto& value_of = [&](const std::string& name) {
        for (std::size_t k = 0; k < r.grid.size(); ++k)
          if (r.grid[k].name == name)
            return r.grid[k].values[f.cell[k]];
        return std::string();
      };
      const std::string text
          = f.value ? fmt::format("E = {:.3g} ({}, {})", *f.value, value_of("contact_width"), value_of("load_rule"))
                    : fmt::format("{} {} -> {}", r.grid[f.choice].name, r.grid[f.choice].values[f.from],
                                  r.grid[f.choice].values[f.to]);
      if (seen.insert(text).second && seen.size() <= 4)
        flips += (flips.empty() ? "" : "; ") + text;
    }
    if (seen.size() > 4)
      flips += fmt::format("; {} more", seen.size() - 4);
    out += fmt::format("| {} | {} | {} | {:.3g} | {:.3g} | {} |\n", c.name, c.score, c.verdict.text,
                       c.verdict.ratio_min, c.verdict.ratio_max, flips.empty() ? "-" : flips);
  }
  return out;
}
} // namespace rollcheck::study::robustness
