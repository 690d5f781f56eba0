#include "study/life/rim_life.h"
#include "core/error.h"
#include "core/json_number.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::study::life
{
std::optional<double> interior_governs_from(const std::vector<RimLifeRow>& rows)
{
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    if (!(rows[i].end_integral < rows[i].interior_integral))
      continue;
    if (i == 0)
      return rows[0].edge_radius_over_radius;
    const double y0 = std::log(rows[i - 1].end_integral / rows[i - 1].interior_integral);
    const double y1 = std::log(rows[i].end_integral / rows[i].interior_integral);
    const double x0 = std::log(rows[i - 1].edge_radius_over_radius), x1 = std::log(rows[i].edge_radius_over_radius);
    return std::exp(x0 + (x1 - x0) * y0 / (y0 - y1));
  }
  return std::nullopt;
}

void validate(const RimLifeSettings& s)
{
  const auto& radii = s.edge_radius_over_radius;
  if (radii.empty() || !(radii.front() > 0)
      || std::adjacent_find(radii.begin(), radii.end(), std::greater_equal<>()) != radii.end())
    throw InputError("life: --edge-radii needs one or more positive edge radii, ascending");
  if (!(s.zone_over_half_width > 0))
    throw InputError(fmt::format("life: the rim ends' zone must be positive, got {} b", s.zone_over_half_width));
}

std::vector<RimLife> rim_lives(const RimLifeSettings& s, const std::vector<robustness::NamedBody>& bodies,
                               const std::vector<const oracle::RealRolling*>& runs, const std::vector<double>& loads_n,
                               const std::function<LoopLifeSettings(double)>& loop_settings,
                               const LifeConstants& k, const std::array<const DepthIntegrals*, 2>& depth,
                               const std::array<double, 2>& ratio, const RoundedEndRatios& end_ratios,
                               std::optional<std::size_t> cylinder)
{
  validate(s);
  const double e = k.weibull_slope;
  std::vector<RimLife> out;
  for (const double load : loads_n)
  {
    const std::size_t first = out.size();
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
      RimLife life{bodies[b].name, load, {}, std::nullopt, std::nullopt, false};
      if (!std::isfinite(runs[b]->first_loop_end_s))
      {
        out.push_back(life); // not a rolling loop at this cell: no rows
        continue;
      }
      for (const double re : s.edge_radius_over_radius)
      {
        const RoundedEnds ends{re * bodies[b].spec.radius_m, &end_ratios, s.zone_over_half_width};
        const LoopIntegrals li = loop_integrals(*runs[b], loop_settings(load), k, depth, ratio, *depth[0], &ends);
        const double interior = li.lundberg_palmgren[0], end = li.end_lundberg_palmgren[0];
        life.rows.push_back({re, interior, end, std::pow(interior / (interior + end), 1 / e), li.ends,
                             li.ends_outside_table, std::nullopt});
      }
      life.interior_governs_from = interior_governs_from(life.rows);
      life.governs_at_every_radius = life.rows.front().end_integral < life.rows.front().interior_integral;
      out.push_back(life);
    }
    if (!cylinder || out[first + *cylinder].rows.empty())
      continue;
    const RimLife& cyl = out[first + *cylinder];
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
      RimLife& life = out[first + b];
      if (b == *cylinder || life.rows.empty())
        continue;
      life.interior_life_ratio_to_cylinder
          = std::pow(cyl.rows[0].interior_integral / life.rows[0].interior_integral, 1 / e);
      for (std::size_t r = 0; r < life.rows.size(); ++r)
        life.rows[r].life_ratio_to_cylinder
            = std::pow((cyl.rows[r].interior_integral + cyl.rows[r].end_integral)
                           / (life.rows[r].interior_integral + life.rows[r].end_integral),
                       1 / e);
    }
  }
  return out;
}

nlohmann::json to_json(const RimLife& l)
{
  nlohmann::json rows = nlohmann::json::array();
  for (const RimLifeRow& r : l.rows)
    rows.push_back({{"edge_radius_over_radius", json_number(r.edge_radius_over_radius)},
                    {"interior_integral", json_number(r.interior_integral)},
                    {"end_integral", json_number(r.end_integral)},
                    {"end_over_interior", json_number(r.end_integral / r.interior_integral)},
                    {"life_with_over_without_ends", json_number(r.life_with_over_without_ends)},
                    {"ends", r.ends},
                    {"ends_outside_table", r.ends_outside_table},
                    {"life_ratio_to_cylinder_with_ends", r.life_ratio_to_cylinder
                                                             ? json_number(*r.life_ratio_to_cylinder)
                                                             : nlohmann::json(nullptr)}});
  std::string governs;
  if (l.rows.empty())
    governs = "not a rolling loop at this cell (a rim lifts before the loop closes)";
  else if (l.governs_at_every_radius)
    governs = "the interior governs at every edge radius computed";
  else if (!l.interior_governs_from)
    governs = "the ends govern at every edge radius computed";
  else
    governs = "the interior governs from this edge radius on (interpolated in ln r_e)";
  return {{"body", l.body},
          {"load_n", json_number(l.load_n)},
          {"rows", rows},
          {"interior_life_ratio_to_cylinder", l.interior_life_ratio_to_cylinder
                                                  ? json_number(*l.interior_life_ratio_to_cylinder)
                                                  : nlohmann::json(nullptr)},
          {"interior_governs_from_edge_radius_over_radius",
           l.interior_governs_from ? json_number(*l.interior_governs_from) : nlohmann::json(nullptr)},
          {"interior_governs", governs}};
}
} // namespace rollcheck::study::life
