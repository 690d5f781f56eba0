// FEM-SDS results as JSON (study/loop_scores/fem_sds.h): the keys the CLI writes, the
// audit's pointers and postprocess/plot_fem_*.py read.
#include "core/error.h"
#include "core/json_number.h"
#include "study/loop_scores/fem_sds.h"
#include "contact/wedge_exponent.h"
#include <array>
#include <cmath>
#include <numbers>

namespace rollcheck::study::loop_scores
{
namespace
{

nlohmann::json slice_json(const fem::SliceFem& s)
{
  return {{"position_m", json_number(s.load.position_m)},
          {"radius_m", json_number(s.load.radius_m)},
          {"load_n_per_m", json_number(s.load.load_n_per_m)},
          {"fem_peak_pa", json_number(s.peak_pressure_pa)},
          {"fem_peak_refined_pa", json_number(s.refined_peak_pressure_pa)},
          {"fem_half_width_m", json_number(s.half_width_m)},
          {"line_hertz_peak_pa", json_number(s.hertz_peak_pressure_pa)},
          {"line_hertz_half_width_m", json_number(s.hertz_half_width_m)},
          {"dofs", s.dofs},
          {"refined_dofs", s.refined_dofs}};
}

nlohmann::json slab_json(const FemSdsOrientation& r, const fem::SlabFem& slab)
{
  nlohmann::json peaks = nlohmann::json::array(), planes = nlohmann::json::array();
  for (double p : slab.slice_peak_pressure_pa)
    peaks.push_back(json_number(p));
  for (std::size_t k = 0; k < slab.plane_position_m.size(); ++k)
    planes.push_back({json_number(slab.plane_position_m[k]), json_number(slab.plane_peak_pressure_pa[k])});
  return {{"refine", slab.refine},
          {"dofs", slab.dofs},
          {"layers", slab.layers},
          {"end_layer_m", json_number(slab.end_layer_m)},
          {"newton_iterations", slab.newton_iterations},
          {"krylov_iterations", slab.krylov_iterations},
          {"wall_s", json_number(slab.wall_s)},
          {"approach_factor", json_number(slab.approach_factor)},
          {"force_n", json_number(slab.force_n)},
          {"centre_of_pressure", json_number(slab.centre_of_pressure)},
          {"slice_peak_pa", peaks},
          {"peak_difference_vs_slices", json_number(r.slab_peak_difference(slab))},
          {"max_slice_difference", json_number(r.slab_slice_difference(slab))},
          {"end_peak_pa", {json_number(slab.end_peak_pressure_pa[0]), json_number(slab.end_peak_pressure_pa[1])}},
          {"plane_peaks", planes}};
}

/// The FEM of a solved orientation: its peaks, slices, faces and slab check.
void add_fem_json(nlohmann::json& j, const FemSdsOrientation& r)
{
  const contact::ContactLocus& l = r.locus;
  j["loaded_from"] = json_number(l.loaded_from);
  j["loaded_to"] = json_number(l.loaded_to);
  j["rim_overhang_deg"] = {json_number(r.rim_overhang_rad[0] * 180 / std::numbers::pi),
                           json_number(r.rim_overhang_rad[1] * 180 / std::numbers::pi)};
  j["obtuse_loaded_rims"] = r.obtuse_loaded_rims();
  // The rims' wedges on the rigid plane (contact/wedge_exponent.h): stresses
  // grow as r^exponent at a loaded end; 0: not singular; null: the end carries no load.
  const std::array<bool, 2> loaded{l.loaded_from == 0, l.loaded_to == 1};
  j["rim_stress_exponent"] = nlohmann::json::array();
  for (int end = 0; end < 2; ++end)
    j["rim_stress_exponent"].push_back(
        loaded[end] ? json_number(contact::edge_on_rigid_plane_exponent(std::numbers::pi / 2 + r.rim_overhang_rad[end]))
                    : nlohmann::json(nullptr));
  j["fem_peak_pa"] = json_number(r.fem_peak_pa);
  j["fem_peak_refined_pa"] = json_number(r.fem_peak_refined_pa);
  j["fem_peak_refinement_change"] = json_number(r.fem_peak_refined_pa / r.fem_peak_pa - 1);
  j["line_hertz_peak_pa"] = json_number(r.line_hertz_peak_pa);
  j["fem_vs_line_hertz"] = json_number(r.fem_peak_pa / r.line_hertz_peak_pa - 1);
  j["line_hertz_end_peak_pa"] = json_number(r.line_hertz_end_peak_pa);
  j["contact_length_m"] = json_number(r.contact_length_m);
  j["contact_width_m"] = json_number(r.contact_width_m);
  j["dofs"] = r.dofs;
  j["newton_iterations"] = r.newton_iterations;
  j["krylov_iterations"] = r.krylov_iterations;
  j["wall_s"] = json_number(r.wall_s);
  j["slices"] = nlohmann::json::array();
  for (const fem::SliceFem& s : r.slices)
    j["slices"].push_back(slice_json(s));
  j["table_vs_direct"] = json_number(r.table_vs_direct);
  if (r.slab.empty())
    return;
  j["slab"] = nlohmann::json::array();
  for (const fem::SlabFem& slab : r.slab)
    j["slab"].push_back(slab_json(r, slab));
  j["slab_end_faces"] = "square";
}
} // namespace

nlohmann::json to_json(const FemSdsOrientation& r)
{
  const contact::ContactLocus& l = r.locus;
  nlohmann::json j = {{"index", r.index},
                      {"sample", l.sample},
                      {"time_s", json_number(l.time_s)},
                      {"support", support_name(l.support.kind)},
                      {"creases", l.creases},
                      {"reaches_crease", !l.creases.empty()},
                      {"oracle_faces", l.oracle_faces.size()},
                      {"point_hertz_peak_pa", json_number(r.point_hertz_peak_pa)},
                      {"fem_solved", r.solved}};
  if (l.ruling)
  {
    j["ruling_length_m"] = json_number(l.ruling->length_m);
    j["start_radius_m"] = json_number(l.ruling->start_radius_m);
    j["end_radius_m"] = json_number(l.ruling->end_radius_m);
    j["centre_of_pressure"] = json_number(l.centre_of_pressure);
    j["in_equilibrium"] = l.in_equilibrium;
  }
  if (r.solved)
    add_fem_json(j, r);
  return j;
}

nlohmann::json to_json(const FemSdsResult& result)
{
  nlohmann::json per_orientation = nlohmann::json::array();
  double worst_fem_vs_line_hertz = 0;
  for (const FemSdsOrientation& r : result.orientations)
  {
    per_orientation.push_back(to_json(r));
    if (r.solved)
      worst_fem_vs_line_hertz = std::max(worst_fem_vs_line_hertz, std::abs(r.fem_peak_pa / r.line_hertz_peak_pa - 1));
  }
  const LoopSds& loop = result.loop;
  const bool both = loop.fem.value && loop.line_hertz.value && *loop.line_hertz.value > 0;
  nlohmann::json table = nlohmann::json::array();
  for (const fem::SliceScaling::Node& node : result.table)
    table.push_back({{"load_ratio", json_number(node.lambda)},
                     {"fem_over_hertz", json_number(node.ratio)},
                     {"fem_over_hertz_refined", json_number(node.refined_ratio)},
                     {"dofs", node.fem.dofs},
                     {"refined_dofs", node.fem.refined_dofs},
                     {"newton_iterations", node.fem.newton_iterations},
                     {"wall_s", json_number(node.fem.wall_s)}});
  nlohmann::json j = {
      {"fem_vs_line_hertz_worst", json_number(worst_fem_vs_line_hertz)},
      {"fem_sds_over_line_hertz_sds", both ? json_number(*loop.fem.value / *loop.line_hertz.value) : nullptr},
      {"body", result.body},
      {"oracle", oracle_name(result.oracle)},
      {"source", result.source},
      {"contact_held", result.contact_held},
      {"analytic_sds", json_number(loop.point_hertz.value)},
      {"fem_sds_half_table", json_number(loop.fem_half_table)},
      {"fem_solves", loop.fem_solves},
      {"fem_solves_half_table", loop.fem_solves_half_table},
      {"converged", loop.converged()},
      {"loop", to_json(loop)},
      {"fem_table", table},
      {"fem_table_wall_s", json_number(result.table_wall_s)},
      {"fem_table_nodes_read", result.table_nodes_read},
      {"table_vs_direct_worst", json_number(result.table_vs_direct_worst)},
      {"orientations", result.orientations.size()},
      {"fem_solved_orientations", result.fem_solved},
      {"orientations_reaching_crease", result.reaching_crease},
      {"orientations_standing_on_crease", result.standing_on_crease},
      {"orientations_reaching_obtuse_rim", result.reaching_obtuse_rim},
      {"fem_peak_worst_refinement_change", json_number(result.worst_refinement_change)},
      {"max_orientation_wall_s", json_number(result.max_orientation_wall_s)},
      {"slab_checked_orientations", result.slab_checked},
      {"slab_skipped_orientations", result.slab_skipped},
      {"slab_worst_peak_difference", json_number(result.slab_worst_peak_difference)},
      {"normal_load_n", json_number(result.normal_load_n)},
      {"effective_modulus_pa", result.effective_modulus_pa},
      {"analytic_effective_modulus_pa", result.analytic_effective_modulus_pa},
      {"n_faces", result.n_faces},
      {"wall_s", json_number(result.wall_s)},
      {"per_orientation", per_orientation},
      {"contact_model",
       "every sample of the loop is scored; developable bodies touch the plane along a ruling: the preprint's point-contact Hertz with R = 1/sqrt(k1 k2) "
       "does not apply there (k1 k2 = 0 on the exact surface); the FEM and line-Hertz columns treat the ruling as "
       "plane-strain slices; peaks are taken away from the ruling's ends, where it meets the body's rims (creases: "
       "singular between two elastic bodies, not plane strain in any case; the 3D slab check shows the end)"}};
  j.update(headline_json(loop));
  j.update(continuum_json(result.continuum));
  return j;
}

nlohmann::json continuum_json(const std::optional<ContinuumSds>& continuum)
{
  if (continuum)
    return to_json(*continuum);
  return {{"line_hertz_sds_continuum", nullptr},
          {"fem_sds_continuum", nullptr},
          {"fem_sds_continuum_change", nullptr},
          {"fem_sds_continuum_table_change", nullptr},
          {"fem_sds_continuum_status", nullptr},
          {"fem_sds_continuum_held_below_table", nullptr}};
}
} // namespace rollcheck::study::loop_scores
