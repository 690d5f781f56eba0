// The JSON of the FEM end model's study (study/rims/rim_end_json.h).
#include "study/rims/rim_end_json.h"
#include "contact/edge_on_elastic_block_exponent.h"
#include "core/json_number.h"
#include "study/rims/rim_report.h"
#include <numbers>

namespace rollcheck::study::rims
{
namespace
{
/// The keys both records share: the end's q and R, line Hertz's b and p0,
/// and what the levels say.
nlohmann::json verdict_json(const fem::RimEndStudy& study)
{
  return {{"load_n_per_m", study.setup.load_n_per_m},
          {"sheet_radius_m", study.setup.radius_m},
          {"half_width_m", study.half_width_m},
          {"hertz_peak_pa", study.hertz_peak_pa},
          {"singular", study.singular},
          {"wedge_exponent", study.wedge_exponent},
          {"measured_exponent", json_number(study.measured_exponent)},
          {"end_to_interior",
           study.singular || !study.resolved ? nlohmann::json(nullptr) : json_number(study.end_to_interior)},
          {"end_change", json_number(study.end_change)},
          {"resolved", study.resolved},
          {"converged", study.converged},
          {"plane_strain_change", study.plane_strain_change}};
}

/// A level, its centre line from `from_x_m` to the edge.
nlohmann::json level_json(const fem::RimEndLevel& l, double from_x_m)
{
  nlohmann::json centre_line = nlohmann::json::array();
  for (const fem::CentreLineNode& n : l.centre_line)
    if (n.x_m > from_x_m)
      centre_line.push_back({n.x_m, n.pressure_pa});
  return {{"edge_element_m", l.edge_element_m},
          {"dofs", l.dofs},
          {"approach_m", l.approach_m},
          {"start_load_n_per_m", l.start_load_n_per_m},
          {"load_steps", l.load_steps},
          {"newton_iterations", l.newton_iterations},
          {"krylov_iterations", l.krylov_iterations},
          {"mesh_wall_s", l.mesh_wall_s},
          {"wall_s", l.wall_s},
          {"far_load_n_per_m", l.far_load_n_per_m},
          {"far_peak_pa", l.far_peak_pa},
          {"far_scatter", l.far_scatter},
          {"mid_peak_pa", l.mid_peak_pa},
          {"end_peak_pa", l.end_peak_pa},
          {"end_peak_x_m", l.end_peak_x_m},
          {"edge_pressure_pa", l.edge_pressure_pa > 0 ? json_number(l.edge_pressure_pa) : nlohmann::json(nullptr)},
          {"centre_line_x_m_pressure_pa", centre_line}};
}
} // namespace

std::string counter_face_name(fem::CounterFace face)
{
  return face == fem::CounterFace::rigid ? "rigid" : "steel";
}

nlohmann::json to_json(const fem::RimEndStudy& study)
{
  const fem::RimEndSettings& setup = study.setup;
  nlohmann::json levels = nlohmann::json::array();
  // As far as 3 b beyond where the sheet ends: an acute rim's fillet, and
  // the peak at its start, lie further from the edge than 3 b.
  for (const fem::RimEndLevel& l : study.levels)
    levels.push_back(level_json(l, -3 * study.half_width_m - study.fillet_start_m));
  nlohmann::json j = verdict_json(study);
  j.update({{"counter_face", counter_face_name(setup.counter_face)},
            {"interior_angle_deg", setup.interior_angle_rad * 180 / std::numbers::pi},
            {"crossing_angle_deg", setup.crossing_angle_rad * 180 / std::numbers::pi},
            {"dihedral_angle_deg", study.dihedral_angle_rad * 180 / std::numbers::pi},
            {"edge_radius_m", setup.edge_radius_m},
            {"effective_modulus_pa", study.effective_modulus_pa},
            // What a block of the body's own material would make of a sharp
            // edge (analytic; the elastic counter-face is not modelled here).
            {"same_material_block_exponent",
             setup.edge_radius_m > 0 ? nlohmann::json(nullptr)
                                     : json_number(contact::edge_on_elastic_block_exponent(
                                           setup.interior_angle_rad, setup.youngs_modulus_pa, setup.poisson_ratio,
                                           setup.youngs_modulus_pa, setup.poisson_ratio))},
            {"sheet", study.flat_sheet ? "flat" : "cylinder"},
            {"end_mesh", name_of(fem::rim_end_mesh_names(), fem::rim_end_mesh_used(study), "rim end mesh")},
            {"fillet_start_m", study.fillet_start_m},
            {"boundary_layer_m", study.boundary_layer_m},
            {"plane_strain_noise", study.plane_strain_noise},
            {"verdict", rim_end_verdict(study)},
            {"levels", levels}});
  return j;
}

nlohmann::json end_model_json(const fem::RimEndStudy& study)
{
  int load_steps = 0, newton_iterations = 0;
  double mesh_wall_s = 0;
  for (const fem::RimEndLevel& l : study.levels)
  {
    load_steps += l.load_steps;
    newton_iterations += l.newton_iterations;
    mesh_wall_s += l.mesh_wall_s;
  }
  nlohmann::json j = verdict_json(study);
  j.update({{"depth_over_half_width", study.setup.depth_over_half_width},
            {"levels", study.levels.size()},
            {"load_steps", load_steps},
            {"newton_iterations", newton_iterations},
            {"mesh_wall_s", mesh_wall_s},
            {"wall_s", study.wall_s()}});
  return j;
}
} // namespace rollcheck::study::rims
