#include "audit/claims.h"
#include "audit/claim_groups.h"
#include <fmt/format.h>
#include <map>
#include <stdexcept>

namespace rollcheck::audit
{
std::string at_claim_tolerance(std::string_view text)
{
  return fmt::format(fmt::runtime(text), fmt::arg("tolerance", fmt::format("{:.0f} %", 100 * claim_tolerance)));
}

std::vector<ClaimCell> cells_in(const std::vector<std::string>& modes, const PerMode& commands, const Rule& rule)
{
  std::vector<ClaimCell> cells;
  for (const std::string& mode : modes)
    cells.push_back({mode, commands.at(mode), rule});
  return cells;
}

ClaimCell not_built(const std::string& mode) { return {mode, {}, {}}; }

TruthSource truth_in(std::string mode, std::string note) { return {std::move(mode), {}, {}, {}, std::move(note)}; }

TruthSource truth_over_choices(const ClaimCommands& c, std::vector<Ranking> rankings, std::string note)
{
  return {{}, c.robustness, rules::rankings_over_choices(std::move(rankings)), {}, std::move(note)};
}

TruthSource truth_untestable(std::string reason) { return {{}, {}, {}, std::move(reason)}; }

std::vector<ClaimCell> joined(std::initializer_list<std::vector<ClaimCell>> lists)
{
  std::vector<ClaimCell> cells;
  for (const std::vector<ClaimCell>& list : lists)
    cells.insert(cells.end(), list.begin(), list.end());
  return cells;
}

std::vector<std::string> audit_verdict_rules()
{
  return {fmt::format("A value or ratio claim holds in a mode when the recomputed number is within {:.0f} % of the "
                      "paper's; the other claims state their rule below.",
                      100 * claim_tolerance),
          "holds: the paper-compatible recomputation and every other applicable one satisfy the rule.",
          "holds only in paper-compatible mode: the paper-compatible recomputation satisfies it, another does not.",
          "does not hold: the paper-compatible recomputation (the preprint's own method and meshes) fails it.",
          "real rolling: U is not CDS, so its cell holds when U_inf discriminates the bodies the way the claim does "
          "(the oloid's U_inf below the cylinder's); the numbers are not compared with the paper's.",
          "cannot be tested: no applicable recomputation can decide the claim (each such cell says why); a cell "
          "whose difference lies inside the score's noise says so and is left out (within noise, cannot be decided "
          "at this resolution).",
          "n/a: the mode does not change this claim; not built yet: the code for that mode has no command yet.",
          "reproduced (per claim): the preprint's method and meshes give its number: the paper-compatible cell "
          "holds (reproduced), fails (not reproduced), or is undecided or absent (cannot be tested, with the "
          "reason).",
          "true (per claim): the claim under the best physics the table has, over the modelling choices: a claim "
          "that ranks bodies is judged by `rollcheck robustness` at resolution-free scores (holds: robust the "
          "claim's way; does not hold: robust the other way; depends on CHOICE: the ranking flips, at the flip "
          "named); any other by its best-physics cell (contact mechanics, real rolling or corrected physics) or "
          "cannot be tested, with the reason."};
}

std::vector<Claim> audit_claims(const std::filesystem::path& reference_meshes, bool quick)
{
  // The table's rows, in order; each command is numbered where it first appears.
  const std::vector<std::string> rows = {
      "oloid_cds",              "cds_ratio",              "search_optimum",         "continuous_optimum",
      "convergence",            "face_scaling",           "threshold_independence", "sds_ratio",
      "damage_ratios",          "fatigue",                "oloid_area",             "fem_hertz",
      "approximate_search",     "revalidation",           "improvement_direction",  "sensitivity",
      "discrimination",         "hertz_table",            "pressure_uniformity",    "discrete_gaussian",
      "geometry_only_sds",      "mean_curvature_spread",  "tds_lowest",             "fatigue_values",
      "rolling_convergence",    "surface_coverage",       "speed",                  "all_metrics",
      "sds_point_hertz",        "fixed_loci"};
  const ClaimCommands commands = claim_commands(reference_meshes, quick);
  std::map<std::string, Claim> by_id;
  for (const auto& group : {claims::oloid_score_claims, claims::ratio_claims, claims::body_claims,
                            claims::table_claims, claims::search_claims, claims::rolling_claims,
                            claims::stress_claims})
    for (Claim& claim : group(commands))
      by_id.emplace(claim.id, std::move(claim));
  if (by_id.size() != rows.size())
    throw std::logic_error(fmt::format("audit: {} claims for the table's {} rows", by_id.size(), rows.size()));
  std::vector<Claim> table;
  for (const std::string& id : rows)
    table.push_back(std::move(by_id.at(id)));
  return table;
}
} // namespace rollcheck::audit
