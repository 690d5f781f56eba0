#include "io/result_fields.h"
#include <algorithm>
#include <array>
#include <utility>

namespace rollcheck::io {
namespace {
struct Field {
  std::string_view key;
  std::string_view unit;
};

/// Every summary field with a unit, by its key (sorted, for the lookup).
constexpr auto fields = std::to_array<Field>({
    {"analytic_effective_modulus_pa", "Pa"},
    {"apex_growth_per_level_pa", "Pa"},
    {"apex_pressure_coarsest_pa", "Pa"},
    {"apex_pressure_finest_pa", "Pa"},
    {"approach_at_centre_of_mass_m", "m"},
    {"approach_hertz_m", "m"},
    {"approach_m", "m"},
    {"approximate_wall_s", "s"},
    {"area_m2", "m^2"},
    {"assembly_s", "s"},
    {"balanced_end_line_load_n_per_m", "N/m"},
    {"balanced_loaded_length_m", "m"},
    {"balanced_slope_n_per_m2", "N/m^2"},
    {"batch_wall_s", "s"},
    {"body_edge_pa", "Pa"},
    {"body_interior_pa", "Pa"},
    {"body_load_n_per_m", "N/m"},
    {"body_modulus_pa", "Pa"},
    {"body_near_edge_peak_pa", "Pa"},
    {"body_peak_pa", "Pa"},
    {"boundary_layer_m", "m"},
    {"cell_m", "m"},
    {"centre_of_mass_m", "m"},
    {"centre_of_pressure_m", "m"},
    {"contact_element_m", "m"},
    {"contact_element_size_m", "m"},
    {"contact_length_m", "m"},
    {"contact_start_m", "m"},
    {"contact_time_s", "s"},
    {"contact_width_m", "m"},
    {"cpu_s", "s"},
    {"curvature_floor_per_m", "1/m"},
    {"cut_height_m", "m"},
    {"damping_n_m_s", "N m s"},
    {"dihedral_angle_deg", "deg"},
    {"direct_ends_median_sheet_radius_m", "m"},
    {"direction_deg", "deg"},
    {"dt_s", "s"},
    {"duration_s", "s"},
    {"edge_element_m", "m"},
    {"edge_pressure_pa", "Pa"},
    {"edge_radius_m", "m"},
    {"effective_modulus_pa", "Pa"},
    {"effective_radius_m", "m"},
    {"effective_radius_max_finite_m", "m"},
    {"effective_radius_min_m", "m"},
    {"end_angle_deg", "deg"},
    {"end_dihedral_angle_deg", "deg"},
    {"end_half_width_m", "m"},
    {"end_interior_angle_deg", "deg"},
    {"end_layer_m", "m"},
    {"end_lift_m", "m"},
    {"end_line_load_n_per_m", "N/m"},
    {"end_load_n_per_m", "N/m"},
    {"end_peak_pa", "Pa"},
    {"end_peak_within_half_limit_pa", "Pa"},
    {"end_peak_x_m", "m"},
    {"end_radius_m", "m"},
    {"end_sheet_radius_m", "m"},
    {"end_table_acute_step_deg", "deg"},
    {"end_table_load_n_per_m", "N/m"},
    {"end_table_step_deg", "deg"},
    {"endurance_limit_pa", "Pa"},
    {"exponent_loads_n", "N"},
    {"face_angle_deg", "deg"},
    {"face_areas_m2", "m^2"},
    {"face_gaussian_curvature_mean_per_m2", "1/m^2"},
    {"face_mean_curvature_mean_per_m", "1/m"},
    {"face_mean_curvature_std_per_m", "1/m"},
    {"far_element_m", "m"},
    {"far_element_size_m", "m"},
    {"far_line_hertz_pa", "Pa"},
    {"far_load_n_per_m", "N/m"},
    {"far_peak_pa", "Pa"},
    {"fatigue_limit_contact_pa", "Pa"},
    {"fatigue_load_n", "N"},
    {"fatigue_strength_pa", "Pa"},
    {"fem_half_width_m", "m"},
    {"fem_peak_pa", "Pa"},
    {"fem_peak_refined_pa", "Pa"},
    {"fem_table_wall_s", "s"},
    {"fillet_start_m", "m"},
    {"fine_radius_m", "m"},
    {"finished_end_peak_pa", "Pa"},
    {"flat_radius_m", "m"},
    {"flat_rim_from_deg", "deg"},
    {"force_from_pressure_n", "N"},
    {"force_n", "N"},
    {"force_per_length_from_pressure_n_per_m", "N/m"},
    {"force_per_length_n_per_m", "N/m"},
    {"force_target_n", "N"},
    {"gaussian_curvature_per_m2", "1/m^2"},
    {"gmsh_s", "s"},
    {"half_contact_pressure_pa", "Pa"},
    {"half_space_ends_from_deg", "deg"},
    {"half_width_m", "m"},
    {"hardness_pa", "Pa"},
    {"height_m", "m"},
    {"hertz_peak_pa", "Pa"},
    {"inertia_density1_kg_m2", "kg m^2"},
    {"initial_rate_rad_s", "rad/s"},
    {"interior_angle_deg", "deg"},
    {"interior_peak_pa", "Pa"},
    {"largest_layer_m", "m"},
    {"length_m", "m"},
    {"line_hertz_end_peak_pa", "Pa"},
    {"line_hertz_half_width_m", "m"},
    {"line_hertz_peak_pa", "Pa"},
    {"load_n", "N"},
    {"load_n_per_m", "N/m"},
    {"loaded_end_angle_max_deg", "deg"},
    {"loaded_end_angle_min_deg", "deg"},
    {"loaded_end_dihedral_max_deg", "deg"},
    {"loaded_end_dihedral_min_deg", "deg"},
    {"loads_n", "N"},
    {"longer_window_peak_pa", "Pa"},
    {"loop_period_s", "s"},
    {"mass_kg", "kg"},
    {"matched_edge_pa", "Pa"},
    {"max_angular_speed_rad_s", "rad/s"},
    {"max_orientation_wall_s", "s"},
    {"max_peak_pressure_pa", "Pa"},
    {"max_speed_m_s", "m/s"},
    {"max_stress_amplitude_pa", "Pa"},
    {"mean_curvature_per_m", "1/m"},
    {"mean_peak_pressure_pa", "Pa"},
    {"mean_speed_m_s", "m/s"},
    {"mean_stress_amplitude_pa", "Pa"},
    {"mesh_s", "s"},
    {"mid_peak_pa", "Pa"},
    {"min_peak_pressure_pa", "Pa"},
    {"modelled_angle_deg", "deg"},
    {"normal_load_n", "N"},
    {"p_hertz_pa", "Pa"},
    {"p_max_nodal_pa", "Pa"},
    {"p_pa", "Pa"},
    {"peak_across_m", "m"},
    {"peak_along_m", "m"},
    {"peak_memory_mb", "MB"},
    {"peak_pa", "Pa"},
    {"peak_pressure_pa", "Pa"},
    {"point_hertz_peak_pa", "Pa"},
    {"position_m", "m"},
    {"postprocess_s", "s"},
    {"predicted_edge_pa", "Pa"},
    {"pressure_pa", "Pa"},
    {"r_m", "m"},
    {"radius_m", "m"},
    {"reaction_n", "N"},
    {"reference_radius_m", "m"},
    {"rigid_wall_s", "s"},
    {"rim_overhang_deg", "deg"},
    {"rule_load_n_per_m", "N/m"},
    {"rule_match_distance_m", "m"},
    {"ruling_length_m", "m"},
    {"samples_wall_s", "s"},
    {"scan_step_deg", "deg"},
    {"scored_time_s", "s"},
    {"section_edge_element_m", "m"},
    {"section_edge_zone_m", "m"},
    {"sheet_radius_m", "m"},
    {"singular_from_deg", "deg"},
    {"slice_load_n_per_m", "N/m"},
    {"slice_peak_pa", "Pa"},
    {"slice_radius_m", "m"},
    {"solve_s", "s"},
    {"start_load_n_per_m", "N/m"},
    {"start_radius_m", "m"},
    {"station_load_n_per_m", "N/m"},
    {"station_m", "m"},
    {"station_peak_pa", "Pa"},
    {"stress_pa", "Pa"},
    {"strip_half_width_m", "m"},
    {"surface_centroid_m", "m"},
    {"theta_deg", "deg"},
    {"theta_max_deg", "deg"},
    {"theta_min_deg", "deg"},
    {"theta_start_deg", "deg"},
    {"threshold_m", "m"},
    {"tilt_rad", "rad"},
    {"time_s", "s"},
    {"time_step_s", "s"},
    {"total_peak_memory_mb", "MB"},
    {"unfinished_end_peak_pa", "Pa"},
    {"volume_m3", "m^3"},
    {"volume_mesh_size_m", "m"},
    {"wall_s", "s"},
    {"width_m", "m"},
    {"window_peak_pa", "Pa"},
    {"wobble_amplitude_rad", "rad"},
    {"youngs_modulus_pa", "Pa"},
});

/// The tables: a field of rows, one column each (group "" for any group).
struct Table {
  std::string_view group;
  std::string_view key;
  std::string_view units;
  std::vector<std::string> columns;
};

const std::vector<Table> &tables() {
  // convergence/<score>: the score after the first n samples
  // (contact/trajectory_scores.h).
  static const std::vector<Table> list = {
      {"convergence", "", "1, 1", {"samples", "score"}},
      {"",
       "planes_x_m_peak_pa_load_n_per_m",
       "m, Pa, N/m",
       {"x_m", "peak_pa", "load_n_per_m"}},
      {"", "centre_line_x_m_pressure_pa", "m, Pa", {"x_m", "pressure_pa"}}};
  return list;
}

const Table *find_table(std::string_view group, std::string_view key) {
  for (const Table &t : tables())
    if ((t.group.empty() || t.group == group) &&
        (t.key.empty() || t.key == key))
      return &t;
  return nullptr;
}
} // namespace

ResultField result_field(std::string_view group, std::string_view key) {
  static_assert(std::ranges::is_sorted(fields, {}, &Field::key),
                "fields: keep the table sorted by key");
  if (const Table *t = find_table(group, key))
    return {std::string(t->units), t->columns};
  // hertz's flags: the warnings of a solve (fem/scenes/hertz_json.cpp).
  if (key == "flags")
    return {"", {}, true};
  const auto it = std::ranges::lower_bound(fields, key, {}, &Field::key);
  return {it != fields.end() && it->key == key ? std::string(it->unit) : "1",
          {}};
}
} // namespace rollcheck::io
