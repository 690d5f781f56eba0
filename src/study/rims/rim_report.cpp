// The rim command's text reports (study/rims/rim_report.h).
#include "study/rims/rim_report.h"
#include "core/degree.h"
#include "core/named_values.h"
#include "study/rims/rim_end_json.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace rollcheck::study::rims
{
namespace
{

std::string levels_table(const fem::RimEndStudy& study)
{
  const double b = study.half_width_m;
  std::string table = "| h_e / b | DOFs | Newton | s | far q (N/m) | far p / p0 | scatter | mid / far | end peak / far "
                      "| at x / b | edge / far |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const fem::RimEndLevel& l : study.levels)
    table += fmt::format("| {:.4f} | {} | {} | {:.1f} | {:.5g} | {:.4f} | {:.3f} | {:.4f} | {:.4f} | {:.3f} | {} |\n",
                         l.edge_element_m / b, l.dofs, l.newton_iterations, l.wall_s, l.far_load_n_per_m,
                         l.far_peak_pa / study.hertz_peak_pa, l.far_scatter, l.mid_peak_pa / l.far_peak_pa,
                         l.end_peak_pa / l.far_peak_pa, l.end_peak_x_m / b,
                         l.edge_pressure_pa > 0 ? fmt::format("{:.4f}", l.edge_pressure_pa / l.far_peak_pa) : "-");
  return table;
}

/// A loop end's verdict in the ends' table.
std::string end_verdict(const fem::RimEndStudy& study)
{
  if (study.singular)
    return fmt::format("singular, measured {:.3f}", study.measured_exponent.value_or(std::nan("")));
  if (!study.end_to_interior || !study.resolved)
    return "rounded edge not resolved";
  return fmt::format("{:.3f}{}", *study.end_to_interior, study.converged ? "" : " (NOT converged)");
}

std::string ends_table(const RimLoopResult& r)
{
  std::string ends = "| orientation | end | section / dihedral angle (deg) | q (N/m) | R (mm) | b (um) | "
                     "wedge exponent | FEM: exponent or end/interior | end peak / orientation's peak | end table | run time (s) |\n"
                     "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const RimLoopEnd& e : r.ends)
    ends += fmt::format("| {} | {} | {:.1f} / {:.1f}{} | {:.4g} | {:.3g} | {:.3g} | {:.3f} | {} | {} | {} | {:.0f} |\n",
                        e.orientation, e.end == 0 ? "start" : "end", e.section_angle_rad / degree,
                        e.dihedral_angle_rad / degree, e.modelled_angle_rad != e.dihedral_angle_rad
                            ? fmt::format(" (modelled {:.1f})", e.modelled_angle_rad / degree)
                            : "",
                        e.study.setup.load_n_per_m, e.study.setup.radius_m * 1e3, e.study.half_width_m * 1e6,
                        e.study.wedge_exponent,
                        !e.outside_model.empty() ? e.outside_model
                                                 : end_verdict(e.study) + (e.half_space ? " (half-space)" : ""),
                        // The orientation's peak is known under the static rule only (RimLoopEnd::interior_peak_pa).
                        e.end_peak_pa && e.interior_peak_pa > 0 ? fmt::format("{:.3f}", *e.end_peak_pa / e.interior_peak_pa)
                                                                : "-",
                        e.table_ratio ? fmt::format("{:.3f}", *e.table_ratio) : "-", e.study.wall_s());
  return ends;
}

/// The end table's columns in words: its R, or its range of R.
std::string table_columns_text(const RimLoopResult& r)
{
  if (r.table.empty() || r.table.front().sheet_radius_m == r.table.back().sheet_radius_m)
    return fmt::format("R = {:.4g} m", r.reference_radius_m);
  const auto angles = static_cast<std::size_t>(std::ranges::count_if(
      r.table, [&](const EndTableNode& n) { return n.sheet_radius_m == r.table.front().sheet_radius_m; }));
  return fmt::format("{} columns of R from {:.4g} to {:.4g} m ({} angles each)", r.table.size() / angles,
                     r.table.front().sheet_radius_m, r.table.back().sheet_radius_m, angles);
}

/// The flat-rim table in words: its nodes' ratios, where it meets the end
/// table, or why there is none.
std::string flat_table_text(const RimLoopResult& r)
{
  if (r.flat_table.empty())
    return r.flat_rim_refused.empty() ? "" : "; no flat-rim table (" + r.flat_rim_refused + ")";
  std::string flat = fmt::format("; from {:.1f} deg the flat-rim table (the loop's own ends, half-space theory), "
                                 "peak / line Hertz:",
                                 r.flat_from_rad / degree);
  for (const FlatRimNode& n : r.flat_table)
    flat += fmt::format(" {:.3f} at {:.1f}{}", n.ratio(), n.section_angle_rad / degree,
                        n.converged() ? "" : " (NOT converged)");
  if (const auto seam = r.flat_rim_seam())
    flat += fmt::format(" deg; where the tables meet the end table gives {:.3f}", seam->end_table_ratio);
  else
    flat += " deg";
  if (!r.flat_rim_refused.empty())
    flat += " (" + r.flat_rim_refused + ")";
  return flat;
}

/// The loop's largest end pressure over its largest interior pressure, in words.
std::string loop_ratio_text(const RimLoopResult& r)
{
  if (const auto ratio = r.loop_end_to_interior())
  {
    // A ratio implies end-aware scores (loop_end_to_interior).
    const loop_scores::EndAwareScores& all = r.loop.end_aware[0];
    if (all.finished_ends == 0)
      return fmt::format("{:.3f}", *ratio);
    return fmt::format("{:.3f}; {} of the {} loaded ends lie near a sheet's apex, taken at R = r_e (the finish's "
                       "least radius): their largest {:.3f}, the other ends' {:.3f}",
                       *ratio, all.finished_ends, r.loop.loaded_ends, all.finished_peak_pa / r.loop.fem_peak_pa,
                       all.unfinished_peak_pa / r.loop.fem_peak_pa);
  }
  if (r.loop.end_aware.empty() || r.loop.loaded_ends == 0)
    return "none (no loaded end)";
  const loop_scores::EndAwareScores& all = r.loop.end_aware[0];
  if (all.singular_ends > 0)
    return "singular";
  std::string covered = "none";
  if (const auto ratio = r.covered_end_to_interior())
  {
    covered = fmt::format("{:.3f}", *ratio);
    if (const auto change = r.covered_limit_change())
      covered += std::abs(*change) < r.fem_sds.loop.tolerance
                     ? fmt::format(" (halving the limit on b / R changes it by {:+.2f} %)", 100 * *change)
                     : fmt::format(", {:.1f} % above the ends within half the limit on b / R: set by the limit, "
                                   "no peak (line Hertz grows as R^-1/2 towards a sheet's apex)",
                                   100 * *change);
  }
  return fmt::format("undefined: {} of the {} loaded ends (in {} of the {} samples) lie outside the line-contact "
                     "model; over the ends it covers {}",
                     all.outside_model_ends, r.loop.loaded_ends, all.outside_model_samples, r.loop.samples, covered);
}

/// A score and its change when the samples halve; `missing_word` without one.
std::string score_text(const loop_scores::ConvergedScore& c, const std::string& missing_word = "singular")
{
  if (!c.value)
    return missing_word;
  if (std::isinf(*c.value))
    return std::string("infinite (no stress amplitude above the endurance limit)");
  return fmt::format("{:.5g} (halving the samples {:+.2f} %)", *c.value, 100 * c.sample_change());
}

/// FEM-SDS and FEM-FDS of the interior and with the ends.
std::string scores_text(const RimLoopResult& r)
{
  const loop_scores::LoopSds& loop = r.loop;
  std::string scores = fmt::format("interior only: FEM-SDS {}, FEM-FDS {}", score_text(loop.fem_rulings),
                                   score_text(loop.fem_fds_rulings));
  if (loop.end_aware.empty())
    return scores;
  // A missing score: a singular end, or an end outside the model (undefined).
  const std::string missing
      = loop.end_aware[0].singular_ends == 0 && loop.end_aware[0].outside_model_ends > 0 ? "undefined" : "singular";
  scores += fmt::format("\nwith the ends:  FEM-SDS {}, FEM-FDS {}; {}\nover the loop ({} load rule): largest end "
                        "pressure / largest interior pressure {}",
                        score_text(loop.end_aware[0].sds, missing), score_text(loop.end_aware[0].fds, missing),
                        r.end_aware_status(), name_of(contact::load_rule_names(), r.load_rule, "load rule"),
                        loop_ratio_text(r));
  for (const RuleLoop& other : r.other_rules)
  {
    const auto ratio = r.loop_end_to_interior(other.loop);
    const auto& sds = other.loop.end_aware.empty() ? loop_scores::ConvergedScore{} : other.loop.end_aware[0].sds;
    scores += fmt::format("\nunder the {} load rule: largest end / largest interior pressure {}, FEM-SDS with the "
                          "ends {} (interior {}); {}",
                          name_of(contact::load_rule_names(), other.rule, "load rule"),
                          ratio ? fmt::format("{:.3f}", *ratio) : "none", score_text(sds, "none"),
                          score_text(other.loop.fem_rulings, "none"), r.end_aware_status(other.loop));
  }
  return scores;
}
} // namespace

std::string rim_end_verdict(const fem::RimEndStudy& study)
{
  const double b = study.half_width_m;
  const bool sharp = !(study.setup.edge_radius_m > 0);
  if (study.singular)
    return fmt::format("singular: the edge's pressure grows as h_e^{:.3f} (the wedge's eigenvalue: {:.3f}); no peak "
                       "value",
                       study.measured_exponent.value_or(std::nan("")), study.wedge_exponent);
  if (!study.end_change)
    return fmt::format("one level: end pressure / interior {:.4f}, convergence not checked", *study.end_to_interior);
  if (!study.resolved)
    return fmt::format("NOT resolved: the rounded edge's boundary layer s = {:.3g} b needs edge elements of s / 4, "
                       "the last level has {:.3g} b; end pressure / interior {:.4f} is a number of the mesh",
                       study.boundary_layer_m / b, study.levels.back().edge_element_m / b, *study.end_to_interior);
  if (study.converged)
    return fmt::format("converged: end pressure / interior {:.4f} (last change {:+.2f} %; {})", *study.end_to_interior,
                       100 * *study.end_change, sharp ? "the sharp edge's own" : "the rounded edge's peak");
  return fmt::format("NOT converged: end pressure / interior {:.4f} changed {:+.2f} % at the last level",
                     *study.end_to_interior, 100 * *study.end_change);
}

std::string report(const fem::RimEndStudy& study)
{
  const fem::RimEndSettings& setup = study.setup;
  const double b = study.half_width_m;
  return fmt::format("\nrim end, interior angle {:.4g} deg, edge radius {:.3g} m ({:.3g} b), R = {:.4g} m, q = {:.5g} "
                     "N/m (b = {:.4g} m, p0 = {:.5g} Pa):\n\n{}\n{}; far side in plane strain to {:.2f} % (standard "
                     "error {:.2f} %).\n\n",
                     setup.interior_angle_rad * 180 / std::numbers::pi, setup.edge_radius_m, setup.edge_radius_m / b,
                     setup.radius_m, setup.load_n_per_m, b, study.hertz_peak_pa, levels_table(study),
                     rim_end_verdict(study), 100 * study.plane_strain_change, 100 * study.plane_strain_noise);
}

std::string report(const RimLoopResult& r)
{
  const loop_scores::LoopSds& loop = r.loop;
  return fmt::format("\nrims of {} ({}), counter-face {}, edge {}:\n\n{}\nloaded rim ends over the loop: {} in {} of {} "
                     "samples, section angles {:.1f} to {:.1f} deg, dihedral {:.1f} to {:.1f} deg (singular above "
                     "{:.2f} deg; "
                     "a sharp edge's exponent at the dihedral above the section's by {:.3f} on average, {:.3f} at "
                     "most); end table of {} nodes "
                     "at q = {:.4g} N/m, {}, against the direct ends {}{}\n{}\n\n",
                     r.fem_sds.body, r.fem_sds.source, counter_face_name(r.end_setup.counter_face),
                     r.end_setup.edge_radius_m > 0 ? fmt::format("rounded, r_e = {:.3g} m", r.end_setup.edge_radius_m)
                                                   : "sharp",
                     ends_table(r), loop.loaded_ends, loop.loaded_end_samples, loop.samples,
                     loop.loaded_end_angle_min_rad / degree, loop.loaded_end_angle_max_rad / degree,
                     r.loaded_end_dihedral_min_rad / degree, r.loaded_end_dihedral_max_rad / degree,
                     r.singular_from_rad / degree, r.exponent_shift_mean, r.exponent_shift_max, r.table.size(),
                     r.reference_load_n_per_m, table_columns_text(r),
                     r.table_vs_direct ? fmt::format("{:.2f} %", 100 * *r.table_vs_direct) : "-", flat_table_text(r),
                     scores_text(r));
}
} // namespace rollcheck::study::rims
