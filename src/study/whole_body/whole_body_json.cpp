// The whole-body check's JSON (study/whole_body/whole_body_check.h): one
// to_json per record, the check's assembled from them.
#include "core/json_number.h"
#include "core/degree.h"
#include "study/whole_body/share_rules.h"
#include "study/whole_body/whole_body_check.h"

namespace rollcheck::study::whole_body
{
namespace
{
/// [x, peak, q] on each node plane.
nlohmann::json planes_json(const fem::WholeBodyFem& fem)
{
  nlohmann::json planes = nlohmann::json::array();
  for (std::size_t k = 0; k < fem.plane_x_m.size(); ++k)
    planes.push_back({fem.plane_x_m[k], fem.plane_peak_pa[k], fem.plane_load_n_per_m[k]});
  return planes;
}

/// What the fine and the coarse whole body both report of their solve: the
/// reaction, the centre of pressure (fraction of L), approach, tilt, planes.
nlohmann::json body_solve_json(const fem::WholeBodyFem& fem, double length_m)
{
  return {{"reaction_n", fem.reaction_n},
          {"centre_of_pressure", fem.centre_of_pressure_m / length_m},
          {"approach_m", fem.approach_m},
          {"tilt_rad", fem.tilt_rad},
          {"planes_x_m_peak_pa_load_n_per_m", planes_json(fem)}};
}

/// The end model's centre-line pressure within 100 b of the edge (x <= 0),
/// where a rule may be matched to it.
nlohmann::json centre_line_json(const fem::RimEndLevel& level, double half_width_m)
{
  nlohmann::json line = nlohmann::json::array();
  const double reach = 100 * half_width_m;
  for (const fem::CentreLineNode& node : level.centre_line)
    if (node.x_m >= -reach)
      line.push_back({node.x_m, node.pressure_pa});
  return line;
}

nlohmann::json end_model_level_json(const fem::RimEndLevel& l, double half_width_m)
{
  return {{"edge_element_m", l.edge_element_m},
          {"dofs", l.dofs},
          {"far_peak_pa", l.far_peak_pa},
          {"edge_pressure_pa", l.edge_pressure_pa},
          {"end_peak_pa", l.end_peak_pa},
          {"end_peak_x_m", l.end_peak_x_m},
          {"centre_line_x_m_pressure_pa", centre_line_json(l, half_width_m)},
          {"wall_s", l.wall_s}};
}

/// The end model's own record within an end's (end_model_... keys).
nlohmann::json end_model_json(const fem::RimEndStudy& model)
{
  nlohmann::json levels = nlohmann::json::array();
  for (const fem::RimEndLevel& l : model.levels)
    levels.push_back(end_model_level_json(l, model.half_width_m));
  return {{"end_model_depth_over_half_width", model.setup.depth_over_half_width},
          {"end_model_mesh", model.setup.mesh == fem::RimEndMesh::grid ? "grid" : "delaunay"},
          {"end_model_singular", model.singular},
          {"end_model_converged", model.converged},
          {"end_model_end_to_interior", json_number(model.end_to_interior)},
          {"end_model_change", json_number(model.end_change)},
          {"end_model_levels", levels},
          {"end_model_measured_exponent", json_number(model.measured_exponent)},
          {"wedge_exponent", model.wedge_exponent}};
}

nlohmann::json coarse_body_json(const WholeBodyCheck::CoarseBody& coarse, double length_m)
{
  nlohmann::json j = body_solve_json(coarse.fem, length_m);
  j.update({{"contact_element_m", coarse.sizes.contact_m},
            {"end_layer_m", coarse.sizes.end_layer_m},
            {"node_planes", coarse.node_planes},
            {"dofs", coarse.fem.dofs},
            {"wall_s", coarse.wall_s}});
  return j;
}

nlohmann::json whole_body_json(const fem::WholeBodyFem& fem, double length_m)
{
  nlohmann::json j = body_solve_json(fem, length_m);
  j.update({{"force_n", fem.force_n},
            {"load_steps", fem.load_steps},
            {"newton_iterations", fem.newton_iterations},
            {"edge_pressure_pa", {fem.edge_pressure_pa[0], fem.edge_pressure_pa[1]}},
            {"solve_s", fem.solve_s}});
  return j;
}

/// The whole body's mesh: its sizes and counts.
nlohmann::json mesh_json(const WholeBodyCheck& r)
{
  return {{"contact_element_m", r.sizes.contact_m},
          {"strip_half_width_m", r.sizes.strip_half_width_m},
          {"section_growth", r.sizes.growth},
          {"far_element_m", r.sizes.far_m},
          {"end_layer_m", r.sizes.end_layer_m},
          {"layer_growth", r.sizes.layer_growth},
          {"largest_layer_m", r.sizes.largest_layer_m},
          {"section_edge_element_m", r.sizes.edge_m},
          {"section_edge_zone_m", r.sizes.edge_zone_m},
          {"node_planes", r.node_planes},
          {"section_nodes", r.section_nodes},
          {"dofs", r.fem.dofs},
          {"cut_height_m", r.orientation.centre_of_mass_height_m},
          {"gmsh_s", r.gmsh_s}};
}

/// [to_json(record), ...]
template <class Records>
nlohmann::json array_json(const Records& records)
{
  nlohmann::json array = nlohmann::json::array();
  for (const auto& record : records)
    array.push_back(to_json(record));
  return array;
}
} // namespace

nlohmann::json to_json(const WholeBodyOrientation& o)
{
  return {{"direction_deg", o.direction_deg},
          {"length_m", o.ruling.length_m},
          {"start_radius_m", o.ruling.start_radius_m},
          {"end_radius_m", o.ruling.end_radius_m},
          {"centre_of_pressure", o.centre_of_pressure},
          {"in_equilibrium", o.in_equilibrium},
          {"loaded_from", o.loaded_from},
          {"loaded_to", o.loaded_to},
          {"rim_overhang_deg", {o.rim_overhang_rad[0] / degree, o.rim_overhang_rad[1] / degree}},
          {"interior_angle_deg", {o.interior_angle_deg(0), o.interior_angle_deg(1)}},
          {"end_load_n_per_m", o.end_load_n_per_m},
          {"end_half_width_m", o.end_half_width_m}};
}

nlohmann::json scan_json(const WholeBodyCheckSettings& settings, std::span<const WholeBodyOrientation> scan)
{
  return {{"body", geometry::body_label(settings.body)},
          {"normal_load_n", settings.normal_load_n},
          {"orientations", array_json(scan)}};
}

nlohmann::json to_json(const StationComparison& st)
{
  return {{"position_m", st.position_m},
          {"radius_m", st.radius_m},
          {"rule_load_n_per_m", st.rule_load_n_per_m},
          {"hertz_peak_pa", st.hertz_peak_pa},
          {"slice_peak_pa", st.slice_peak_pa},
          {"body_peak_pa", st.body_peak_pa},
          {"body_load_n_per_m", st.body_load_n_per_m},
          {"peak_difference", json_number(st.peak_difference())},
          {"load_difference", json_number(st.load_difference())},
          {"peak_difference_at_body_load", json_number(st.peak_difference_at_body_load())}};
}

nlohmann::json to_json(const EndComparison& e)
{
  nlohmann::json j = end_model_json(e.end_model);
  j.update({{"position_m", e.position_m},
            {"radius_m", e.radius_m},
            {"load_n_per_m", e.load_n_per_m},
            {"half_width_m", e.half_width_m},
            {"interior_angle_deg", e.interior_angle_deg},
            {"rule_match_distance_m", json_number(e.rule_match_distance_m)},
            {"end_model_ratio", json_number(e.end_model_ratio)},
            {"end_model_ratio_change", json_number(e.end_model_ratio_change)},
            {"slice_peak_pa", e.slice_peak_pa},
            {"predicted_edge_pa", json_number(e.predicted_edge_pa)},
            {"compared", e.near_edge_peak ? "near-edge peak (acute end)" : "edge"},
            {"body_near_edge_peak_pa", e.body_near_edge_peak_pa},
            {"body_edge_pa", e.body_edge_pa},
            {"body_interior_pa", e.body_interior_pa},
            {"body_edge_to_interior", e.body_edge_pa / e.body_interior_pa},
            {"difference", json_number(e.difference)},
            {"matched_level", e.matched_level ? nlohmann::json(*e.matched_level) : nlohmann::json()},
            {"matched_edge_pa", json_number(e.matched_edge_pa)},
            {"matched_difference", json_number(e.matched_difference)}});
  return j;
}

nlohmann::json to_json(const WholeBodyCheck& r)
{
  const WholeBodyCheckSettings& s = r.settings;
  const double L = r.orientation.ruling.length_m;
  nlohmann::json ruling = to_json(r.orientation);
  ruling["half_width_m"] = r.half_width_m;
  ruling["half_width_over_length"] = r.half_width_m / L;
  return {{"body", r.body},
          {"direction_deg", s.direction_deg},
          {"normal_load_n", s.normal_load_n},
          {"youngs_modulus_pa", s.youngs_modulus_pa},
          {"poisson_ratio", s.poisson_ratio},
          {"end_depth", s.end_depth == EndModelDepth::body ? "body" : "local"},
          {"effective_modulus_pa", r.effective_modulus_pa},
          {"ruling", ruling},
          {"mesh", mesh_json(r)},
          {"whole_body", whole_body_json(r.fem, L)},
          {"share_rule", std::string(share_rule_strategy(s.share_rule).name)},
          {"section_share", r.section_share ? to_json(*r.section_share) : nlohmann::json()},
          {"coarse_body_share", r.coarse_body ? coarse_body_json(*r.coarse_body, L) : nlohmann::json()},
          {"stations", array_json(r.stations)},
          {"ends", array_json(r.ends)},
          {"worst_along", r.worst_along},
          {"worst_end", json_number(r.worst_end)},
          {"worst_load", r.worst_load},
          {"largest_peak_difference", r.largest_peak_difference},
          {"tolerance", s.tolerance},
          {"end_match_over_half_width", s.end_match_over_half_width},
          {"outcome", outcome_name(r.outcome)},
          {"pass", r.pass},
          {"verdict", r.verdict},
          {"wall_s", {{"slices", r.slices_s}, {"end_models", r.ends_s}, {"whole_body", r.body_s}, {"total", r.wall_s}}}};
}
} // namespace rollcheck::study::whole_body
