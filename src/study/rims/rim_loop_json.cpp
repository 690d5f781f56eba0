// The rim loop's JSON (study/rims/rim_loop.h): every record's to_json,
// declared beside its struct.
#include "study/rims/rim_loop.h"
#include "core/degree.h"
#include "core/json_number.h"
#include "core/named_values.h"
#include "study/rims/rim_end_json.h"
#include <algorithm>
#include <numbers>

namespace rollcheck::study::rims
{
namespace
{

template <typename Record>
nlohmann::json array_json(const std::vector<Record>& records)
{
  nlohmann::json array = nlohmann::json::array();
  for (const Record& r : records)
    array.push_back(to_json(r));
  return array;
}

/// Where the two tables meet (RimLoopResult::flat_rim_seam), or null.
nlohmann::json seam_json(const RimLoopResult& r)
{
  const auto seam = r.flat_rim_seam();
  if (!seam)
    return nullptr;
  return {{"interior_angle_deg", r.flat_from_rad / degree},
          {"dihedral_angle_deg", seam->dihedral_angle_rad / degree},
          {"sheet_radius_m", seam->sheet_radius_m},
          {"end_table_ratio", seam->end_table_ratio},
          {"flat_rim_ratio", seam->flat_rim_ratio}};
}
/// An end model in brief, by which model, and the half-space end's own
/// record where it stood for the FEM's.
nlohmann::json loop_end_model_json(const fem::RimEndStudy& study, const std::optional<HalfSpaceEndStudy>& half_space)
{
  nlohmann::json j = end_model_json(study);
  j["end_model"] = half_space ? "half-space" : "fem";
  j["half_space"] = half_space ? to_json(*half_space) : nlohmann::json(nullptr);
  return j;
}
} // namespace

nlohmann::json to_json(const EndTableNode& node)
{
  // A node no look-up of the loop reads is not solved: its place alone.
  nlohmann::json j = !node.reached ? nlohmann::json{{"sheet_radius_m", node.sheet_radius_m}}
                                   : loop_end_model_json(node.study, node.half_space);
  j["dihedral_angle_deg"] = node.dihedral_angle_rad / degree;
  j["reached"] = node.reached;
  return j;
}

nlohmann::json to_json(const FlatRimSide& side)
{
  return {{"centre_of_pressure", side.centre_of_pressure},
          {"end_line_load_n_per_m", side.end_line_load_n_per_m},
          {"end_sheet_radius_m", side.end_radius_m},
          {"peak_pressure_pa", side.peak_pressure_pa},
          {"line_hertz_peak_pa", side.line_hertz_peak_pa},
          {"last_change", side.last_change},
          {"window_change", side.window_change},
          {"converged", side.converged},
          {"wall_s", side.wall_s},
          {"after_over_half_width", side.after_over_half_width},
          {"across_scale", side.across_scale},
          {"whole_ruling", side.whole_ruling},
          {"window_peak_pa", side.whole_ruling ? nlohmann::json(side.window_peak_pa) : nlohmann::json(nullptr)}};
}

nlohmann::json to_json(const FlatRimNode& node)
{
  return {{"interior_angle_deg", node.section_angle_rad / degree},
          {"dihedral_angle_deg", node.dihedral_angle_rad / degree},
          {"peak_pressure_pa", node.peak_pa()},
          {"ratio", node.ratio()},
          {"converged", node.converged()},
          {"sides", array_json(node.sides)}};
}

nlohmann::json to_json(const RimLoopEnd& e)
{
  nlohmann::json j = loop_end_model_json(e.study, e.half_space);
  j["orientation"] = e.orientation;
  j["end"] = e.end == 0 ? "start" : "end";
  j["interior_angle_deg"] = e.section_angle_rad / degree;
  j["dihedral_angle_deg"] = e.dihedral_angle_rad / degree;
  j["modelled_angle_deg"] = e.modelled_angle_rad / degree;
  // A sharp edge's wedge equation at the angle normal to the rim (the
  // end's) and at the section's (the reduction that was used before).
  j["dihedral_wedge_exponent"] = sharp_edge_exponent(e.study.setup, e.dihedral_angle_rad);
  j["section_wedge_exponent"] = sharp_edge_exponent(e.study.setup, e.section_angle_rad);
  j["interior_peak_pa"] = e.interior_peak_pa;
  j["end_peak_pa"] = json_number(e.end_peak_pa);
  j["end_peak_over_interior_peak"]
      = e.end_peak_pa && e.interior_peak_pa > 0 ? json_number(*e.end_peak_pa / e.interior_peak_pa)
                                                : nlohmann::json(nullptr);
  j["table_ratio"] = json_number(e.table_ratio);
  j["outside_model"] = e.outside_model.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.outside_model);
  return j;
}

namespace
{
/// The loop under one load rule in brief: its largest end pressure over its
/// largest interior pressure, where it sits, and its FEM-SDS with and
/// without the ends.
nlohmann::json rule_json(const RimLoopResult& r, contact::LoadRule rule, const loop_scores::LoopSds& loop,
                         const std::optional<LoopLargestEnd>& largest_end)
{
  const bool end_aware = !loop.end_aware.empty();
  return {{"load_rule", name_of(contact::load_rule_names(), rule, "load rule")},
          {"loop_end_to_interior", json_number(r.loop_end_to_interior(loop))},
          {"covered_end_to_interior", json_number(r.covered_end_to_interior(loop))},
          {"largest_end", largest_end ? to_json(*largest_end) : nlohmann::json(nullptr)},
          {"end_peak_pa", end_aware ? json_number(loop.end_aware[0].peak_pa) : nlohmann::json(nullptr)},
          {"interior_peak_pa", loop.fem_peak_pa},
          {"end_aware_fem_sds", end_aware ? json_number(loop.end_aware[0].sds.value) : nlohmann::json(nullptr)},
          {"interior_fem_sds", json_number(loop.fem_rulings.value)},
          {"loaded_ends", loop.loaded_ends},
          {"outside_model_ends", end_aware ? loop.end_aware[0].outside_model_ends : 0},
          {"end_aware_status", r.end_aware_status(loop)}};
}
} // namespace

nlohmann::json to_json(const RimLoopResult& r)
{
  nlohmann::json rules = nlohmann::json::array({rule_json(r, r.load_rule, r.loop, r.largest_end)});
  for (const RuleLoop& other : r.other_rules)
    rules.push_back(rule_json(r, other.rule, other.loop, other.largest_end));
  const bool end_aware = !r.loop.end_aware.empty();
  return {{"body", r.fem_sds.body},
          {"loop", r.fem_sds.source},
          {"counter_face", counter_face_name(r.end_setup.counter_face)},
          {"load_rule", name_of(contact::load_rule_names(), r.load_rule, "load rule")},
          {"edge_radius_m", r.end_setup.edge_radius_m},
          {"singular_from_deg", r.singular_from_rad / degree},
          {"loaded_end_dihedral_min_deg", r.loaded_end_dihedral_min_rad / degree},
          {"loaded_end_dihedral_max_deg", r.loaded_end_dihedral_max_rad / degree},
          {"dihedral_minus_section_exponent_mean", r.exponent_shift_mean},
          {"dihedral_minus_section_exponent_max", r.exponent_shift_max},
          {"ends", array_json(r.ends)},
          {"worst_end_to_interior", json_number(r.worst_end_to_interior())},
          {"loop_end_to_interior", json_number(r.loop_end_to_interior())},
          {"covered_end_to_interior", json_number(r.covered_end_to_interior())},
          {"covered_limit_change", json_number(r.covered_limit_change())},
          {"largest_end", r.largest_end ? to_json(*r.largest_end) : nlohmann::json(nullptr)},
          {"outside_model_ends", end_aware ? r.loop.end_aware[0].outside_model_ends : 0},
          {"outside_model_samples", end_aware ? r.loop.end_aware[0].outside_model_samples : 0},
          {"finished_ends", end_aware ? r.loop.end_aware[0].finished_ends : 0},
          {"half_space_ends_from_deg", r.half_space_from_rad < std::numbers::pi
                                           ? nlohmann::json(r.half_space_from_rad / degree)
                                           : nlohmann::json(nullptr)},
          {"half_space_ends",
           std::ranges::count_if(r.ends, [](const RimLoopEnd& e) { return e.half_space.has_value(); })
               + std::ranges::count_if(r.table, [](const EndTableNode& n) { return n.half_space.has_value(); })},
          {"end_table", array_json(r.table)},
          {"end_table_load_n_per_m", r.reference_load_n_per_m},
          // The table's R only when it has one column; its nodes carry their own.
          {"direct_ends_median_sheet_radius_m", r.reference_radius_m},
          {"end_table_converged", r.table_converged},
          {"flat_rim_from_deg", r.flat_table.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.flat_from_rad / degree)},
          {"flat_rim_table", array_json(r.flat_table)},
          {"flat_rim_refused", r.flat_rim_refused.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.flat_rim_refused)},
          {"flat_rim_seam", seam_json(r)},
          {"end_table_vs_direct", json_number(r.table_vs_direct)},
          {"end_aware_status", r.end_aware_status()},
          {"loop_scores", to_json(r.loop)},
          {"load_rules", rules},
          {"interior", to_json(r.fem_sds)},
          {"wall_s", r.wall_s}};
}
} // namespace rollcheck::study::rims
