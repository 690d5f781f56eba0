// The life study's JSON and Markdown (study/life/life_study.h).
#include "core/json_number.h"
#include "study/life/life_study.h"
#include <algorithm>
#include <fmt/format.h>

namespace rollcheck::study::life
{
namespace
{
nlohmann::json flip_json(const robustness::Flip& f, const std::vector<robustness::Choice>& grid)
{
  nlohmann::json settings = nlohmann::json::object();
  for (std::size_t c = 0; c < grid.size(); ++c)
    if (static_cast<int>(c) != f.choice)
      settings[grid[c].name] = grid[c].values[f.cell[c]];
  return {{"choice", grid[f.choice].name},
          {"from", grid[f.choice].values[f.from]},
          {"to", grid[f.choice].values[f.to]},
          {"settings", settings}};
}

nlohmann::json constants_json(const LifeConstants& k)
{
  return {{"weibull_slope", json_number(k.weibull_slope)},
          {"stress_exponent", json_number(k.stress_exponent)},
          {"depth_exponent", json_number(k.depth_exponent)},
          {"fatigue_limit_contact_pa", json_number(k.fatigue_limit_contact_pa)},
          {"dang_van_alpha", json_number(k.dang_van_alpha)},
          {"poisson_ratio", json_number(k.poisson_ratio)}};
}

std::string ratio_text(double x) { return std::isinf(x) ? "inf" : fmt::format("{:.3g}", x); }

std::string optional_text(const std::optional<double>& x) { return x ? ratio_text(*x) : "-"; }

/// The rims' table: per load and body, the life with the ends over without at the rim study's r_e and the r_e
/// from which the interior governs.
std::string rims_markdown(const LifeResult& r)
{
  const double at = r.settings.rims.rim_study_edge_radius_over_radius;
  std::string out = fmt::format("\n| body | load N | L10 with ends / without (r_e = {:g} r1) | L10 / cylinder's, "
                                "without ends | with ends | interior governs from r_e / r1 |\n|---|---|---|---|---|---|\n",
                                at);
  for (const RimLife& l : r.rims)
  {
    const auto row = std::find_if(l.rows.begin(), l.rows.end(),
                                  [&](const RimLifeRow& x) { return x.edge_radius_over_radius == at; });
    if (row == l.rows.end())
      continue;
    out += fmt::format("| {} | {:.4g} | {} | {} | {} | {} |\n", l.body, l.load_n,
                       ratio_text(row->life_with_over_without_ends), optional_text(l.interior_life_ratio_to_cylinder),
                       optional_text(row->life_ratio_to_cylinder),
                       l.governs_at_every_radius ? "every r_e computed" : optional_text(l.interior_governs_from));
  }
  return out;
}
/// The rounded rim ends: the cell, the end table, the assumptions and each body's lives.
nlohmann::json rims_json(const LifeResult& r)
{
  nlohmann::json rim_lives = nlohmann::json::array();
  for (const RimLife& l : r.rims)
    rim_lives.push_back(to_json(l));
  return {{"cell", r.rim_cell},
         {"model", "lundberg_palmgren"},
         {"criterion", "orthogonal_shear"},
         {"edge_radius_over_radius", r.settings.rims.edge_radius_over_radius},
         {"rim_study_edge_radius_over_radius", json_number(r.settings.rims.rim_study_edge_radius_over_radius)},
         {"zone_over_half_width", json_number(r.settings.rims.zone_over_half_width)},
         {"end_table",
          {{"r_over_edge_radius", r.end_ratios.r_over_edge_radius},
           {"end_over_line_hertz", r.end_ratios.end_over_line_hertz},
           {"interior_angle_deg", json_number(r.end_ratios.interior_angle_deg)},
           {"source", r.end_ratios.source}}},
         {"assumptions",
          "each loaded end's pass is a line contact at the end's q on R = max(R_end, r_e), its peak rho(R_end / r_e) "
          "times line Hertz's there (the end table, held at its ends, whatever the rim's interior angle), over one "
          "patch of zone_over_half_width b along the ruling; the interior as without the ends"},
         {"lives", rim_lives}};
}

} // namespace

nlohmann::json to_json(const LifeResult& r)
{
  nlohmann::json grid = nlohmann::json::object(), order = nlohmann::json::array();
  for (const robustness::Choice& c : r.settings.grid)
    grid[c.name] = c.values, order.push_back(c.name);
  nlohmann::json comparisons = nlohmann::json::array();
  for (const LifeComparison& c : r.comparisons)
  {
    nlohmann::json flips = nlohmann::json::array();
    for (const robustness::Flip& f : c.verdict.flips)
      flips.push_back(flip_json(f, r.settings.grid));
    const bool tested = c.verdict.cells > 0;
    comparisons.push_back({{"name", c.name},
                           {"bodies", c.bodies},
                           {"load_n", json_number(c.load_n)},
                           {"model", c.model},
                           {"criterion", c.criterion},
                           {"verdict", c.verdict.text},
                           {"life_ratio_min", tested ? json_number(c.verdict.ratio_min) : nlohmann::json(nullptr)},
                           {"life_ratio_max", tested ? json_number(c.verdict.ratio_max) : nlohmann::json(nullptr)},
                           {"cells", c.verdict.cells},
                           {"grid_cells", c.grid_cells},
                           {"range_over", "the cells of the grid where the ratio is defined (both bodies roll a whole "
                                          "loop and not both lives are infinite): `cells` of `grid_cells`"},
                           {"untested_because", c.untested.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.untested)},
                           {"infinite_life_cells", c.infinite_life_cells},
                           {"flips", flips}});
  }
  nlohmann::json exponents = nlohmann::json::array();
  double oloid_exponent = 0;
  for (const ExponentCheck& e : r.exponents)
  {
    nlohmann::json integrals = nlohmann::json::array();
    for (const double v : e.integrals)
      integrals.push_back(json_number(v));
    exponents.push_back({{"body", e.body},
                         {"load_life_exponent", json_number(e.exponent)},
                         {"integrals", integrals},
                         {"direct_over_tabulated_minus_one", json_number(e.table_agreement)}});
    if (e.body == "oloid")
      oloid_exponent = e.exponent;
  }
  nlohmann::json dang_van = nlohmann::json::array();
  for (const DangVanCheck& d : r.dang_van)
    dang_van.push_back({{"body", d.body}, {"load_n", json_number(d.load_n)}, {"max_over_limit", json_number(d.max_over_limit)}});
  nlohmann::json quadrature = nlohmann::json::array();
  for (const QuadratureCheck& q : r.quadrature)
    quadrature.push_back({{"load_n", json_number(q.load_n)},
                          {"oloid_over_cylinder_life", json_number_or_null(q.life_ratio)},
                          {"oloid_over_cylinder_life_half_quadrature", json_number_or_null(q.life_ratio_half)},
                          {"change", json_number_or_null(q.change())}});
  nlohmann::json integrals = nlohmann::json::object();
  for (std::size_t b = 0; b < r.settings.bodies.size(); ++b)
    for (std::size_t l = 0; l < r.loads_n.size(); ++l)
      for (std::size_t k = 0; k < r.integral_keys.size(); ++k)
      {
        nlohmann::json row = nlohmann::json::array();
        for (const double v : r.integrals[b][l][k])
          row.push_back(json_number_or_null(v));
        integrals[r.settings.bodies[b].name][fmt::format("{:.6g}", r.loads_n[l])][r.integral_keys[k]] = row;
      }
  nlohmann::json bodies = nlohmann::json::array(), loads = nlohmann::json::array(), exponent_loads = loads;
  for (const auto& b : r.settings.bodies)
    bodies.push_back(b.name);
  for (const double l : r.loads_n)
    loads.push_back(json_number(l));
  for (const double l : r.settings.exponent_loads_n)
    exponent_loads.push_back(json_number(l));
  nlohmann::json incomplete = nlohmann::json::array();
  for (const auto& [body, energy] : r.incomplete_loops)
    incomplete.push_back({{"body", body}, {"rolling_energy", energy}});
  return {{"subsurface", to_json(r.subsurface)},
          {"rims", rims_json(r)},
          {"incomplete_loops", incomplete},
          {"load_life_exponent", json_number(oloid_exponent)},
          {"load_life_exponent_derived", json_number(r.derived_exponent)},
          {"load_life_exponents", exponents},
          {"exponent_loads_n", exponent_loads},
          {"constants", constants_json(r.settings.constants)},
          {"dang_van_peak_over_p0", json_number(r.dang_van_peak_over_p0)},
          {"dang_van_peak_depth_over_b", json_number(r.dang_van_peak_depth_over_b)},
          {"dang_van", dang_van},
          {"bodies", bodies},
          {"loads_n", loads},
          {"grid", grid},
          {"grid_order", order},
          {"comparisons", comparisons},
          {"integral_keys", r.integral_keys},
          {"integrals", integrals},
          {"samples_per_loop", r.settings.samples_per_loop},
          {"quadrature_convergence", quadrature},
          {"pieces", r.settings.pieces},
          {"wall_s", json_number(r.wall_s)}};
}

std::string markdown_report(const LifeResult& r)
{
  const SubsurfaceLevel& fine = r.subsurface.levels.back();
  std::string out = fmt::format(
      "FEM slice (finest level, {:.0f} elements across b): largest shear {:.4f} p0 at {:.4f} b (closed form {:.4f} at "
      "{:.4f}); orthogonal shear {:.4f} p0 (closed form {:.4f})\n\n",
      fine.fem.elements_across_b, fine.max_shear_over_p0, fine.max_shear_depth_over_b, r.subsurface.closed_max_shear_over_p0,
      r.subsurface.closed_max_shear_depth_over_b, fine.orthogonal_shear_over_p0, r.subsurface.closed_orthogonal_shear_over_p0);
  for (const ExponentCheck& e : r.exponents)
    out += fmt::format("load-life exponent ({}): {:.4f} measured, {:.4f} derived\n", e.body, e.exponent, r.derived_exponent);
  for (const QuadratureCheck& q : r.quadrature)
    out += fmt::format("oloid / cylinder life at {:.4g} N (default cell): {} at the loop's quadrature, {} at half of "
                       "it ({:+.2f} %)\n",
                       q.load_n, ratio_text(q.life_ratio), ratio_text(q.life_ratio_half), 100 * q.change());
  for (const auto& [body, energy] : r.incomplete_loops)
    out += fmt::format("not a rolling loop (a rim lifts before the loop closes): {} at E = {}\n", body, energy);
  out += "\n| comparison | load N | model | criterion | verdict | life ratio min | life ratio max |\n"
         "|---|---|---|---|---|---|---|\n";
  for (const LifeComparison& c : r.comparisons)
    out += fmt::format("| {} | {:.4g} | {} | {} | {} | {} | {} |\n", c.name, c.load_n, c.model, c.criterion,
                       c.verdict.text, c.verdict.cells ? ratio_text(c.verdict.ratio_min) : "-",
                       c.verdict.cells ? ratio_text(c.verdict.ratio_max) : "-");
  out += rims_markdown(r);
  return out;
}
} // namespace rollcheck::study::life
