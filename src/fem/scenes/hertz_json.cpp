#include "fem/scenes/hertz_json.h"
#include "contact/hertz.h"

namespace rollcheck::fem
{
namespace
{
/// value, Hertz value and relative error under `name`, `name`_hertz, `name`_error.
void compared(nlohmann::json& j, const std::string& name, const std::string& unit, double fem, double hertz)
{
  j[name + unit] = fem;
  j[name + "_hertz" + unit] = hertz;
  j[name + "_error"] = relative_error(fem, hertz);
}

void add_setup(nlohmann::json& j, const HertzResult& r)
{
  const HertzSettings& s = r.setup;
  j["model"] = model_name(s.model);
  j["degree"] = s.degree;
  j["refine"] = s.refine >= 0 ? s.refine : default_refine(s.model, s.degree);
  j["pole_refine"] = s.pole_refine;
  j["edge_refine"] = s.edge_refine;
  j["contact_cap"] = contact_cap_name(s.contact_cap);
  j["plane"] = s.elastic_plane ? "elastic: two identical bodies, E* = E / (2 (1 - nu^2))" : "rigid: E* = E / (1 - nu^2)";
  j["radius_m"] = s.radius_m;
  j["youngs_modulus_pa"] = s.youngs_modulus_pa;
  j["poisson_ratio"] = s.poisson_ratio;
  j["effective_modulus_pa"] = r.hertz.effective_modulus_pa;
  j["body_modulus_pa"] = r.hertz.body_modulus_pa;
  j["penalty_c"] = s.penalty_c;
  j["contact_element_size_m"] = r.grading.contact_size_m;
  j["fine_radius_m"] = r.grading.fine_radius_m;
  j["far_element_size_m"] = r.grading.far_size_m;
  j["size_growth"] = r.grading.growth;
  j["elements_across_contact"] = r.elements_across_contact;
}

/// The measured contact against Hertz: force, size, pressure, approach, stress, profile.
void add_contact(nlohmann::json& j, const HertzResult& r)
{
  const HertzSettings& s = r.setup;
  const bool line = s.model == Model::plane_strain;
  const std::string c = line ? "b" : "a";
  const double length = line ? s.length_m : 1.0;
  j["force_target_n"] = s.force_n;
  j["force_n"] = r.load_reaction * length;
  j["force_error"] = relative_error(r.load_reaction * length, s.force_n);
  j["force_from_pressure_n"] = r.load_contact * length;
  if (line)
  {
    j["length_m"] = s.length_m;
    j["force_per_length_n_per_m"] = r.load_reaction;
    j["force_per_length_from_pressure_n_per_m"] = r.load_contact;
  }
  compared(j, c, "_m", r.contact_size_m, r.hertz.contact_size_m);
  j[c + "_edge_m"] = r.contact_edge_m;
  // The fitted p0 and the pointwise one side by side: the fit averages the
  // nodes' scatter, the largest nodal pressure and the profile's RMS show it.
  compared(j, "p0", "_pa", r.peak_pressure_pa, r.hertz.peak_pressure_pa);
  j["p0_source"] = "least-squares fit of p^2 = p0^2 (1 - s^2 / c^2) to the nodes with at least half the largest "
                   "nodal pressure";
  j["p_max_nodal_pa"] = r.max_nodal_pressure_pa;
  j["p_max_nodal_error"] = relative_error(r.max_nodal_pressure_pa, r.hertz.peak_pressure_pa);
  j["approach_m"] = r.approach_m;
  if (r.hertz.approach_m)
  {
    j["approach_hertz_m"] = *r.hertz.approach_m;
    j["approach_error"] = relative_error(r.approach_m, *r.hertz.approach_m);
    j["approach_note"] = "the FEM approach includes the compliance of the finite, clamped body; Hertz's is a half-space's";
  }
  compared(j, "max_shear", "_pa", r.max_shear.value, r.hertz.max_shear_pa);
  compared(j, "max_shear_depth", "_m", r.max_shear.depth_m, r.hertz.max_shear_depth_m);
  compared(j, "max_von_mises", "_pa", r.max_von_mises.value, r.hertz.max_von_mises_pa);
  compared(j, "max_von_mises_depth", "_m", r.max_von_mises.depth_m, r.hertz.max_von_mises_depth_m);
  nlohmann::json s_m = nlohmann::json::array(), p_pa = nlohmann::json::array(), p_hertz = nlohmann::json::array();
  for (const SurfaceNode& node : r.profile)
  {
    s_m.push_back(node.s);
    p_pa.push_back(node.pressure);
    p_hertz.push_back(contact::pressure_profile(r.hertz.peak_pressure_pa, r.hertz.contact_size_m, node.s));
  }
  j["profile"] = {{line ? "x_m" : "r_m", s_m}, {"p_pa", p_pa}, {"p_hertz_pa", p_hertz}};
  j["profile_rms_error"] = r.profile_rms_error;
  j["profile_rms_error_interior"] = r.profile_rms_error_interior;
  j["pressure_recovery"] = recovery_name(s.pressure_recovery);
  j["touching_nodes"] = r.touching_nodes;
  j["penalty_error_estimate"] = r.penalty_error_estimate;
  j["discretisation_error_estimate"] = r.discretisation_error_estimate;
  j["flags"] = r.flags;
}

void add_cost(nlohmann::json& j, const HertzResult& r)
{
  j["dofs"] = r.dofs;
  j["cells"] = r.cells;
  j["ranks"] = r.ranks;
  j["load_steps"] = r.load_steps;
  j["newton_its"] = r.newton_iterations;
  j["krylov_its"] = r.krylov_iterations;
  j["mesh_s"] = r.mesh_s;
  j["assembly_s"] = r.assembly_s;
  j["solve_s"] = r.solve_s;
  j["postprocess_s"] = r.postprocess_s;
  j["wall_s"] = r.wall_s;
  j["peak_memory_mb"] = r.peak_memory_mb;
  j["total_peak_memory_mb"] = r.total_peak_memory_mb;
}
} // namespace

nlohmann::json to_json(const HertzResult& result)
{
  nlohmann::json j;
  add_setup(j, result);
  add_contact(j, result);
  add_cost(j, result);
  if (!result.setup.xdmf_path.empty())
    j["xdmf"] = result.setup.xdmf_path.string();
  return j;
}
} // namespace rollcheck::fem
