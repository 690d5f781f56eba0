// `rollcheck hertz`: penalty-contact FEM of a sphere or cylinder on a rigid
// plane, every result next to Hertz theory (src/fem, README "Hertz FEM").
// Also the scene "hertz" of case files, and the convergence and penalty
// studies (`--study`).
#include "cli/cli.h"
#include "cli/scenes.h"
#include "contact/hertz.h"
#include "fem/fem.h"
#include "geometry/error.h"
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
const io::Schema& hertz_schema()
{
  static const io::Schema schema = [] {
    const fem::HertzSetup d;
    io::Schema s{"hertz", {}};
    s.parameters = {
        {"model", "--model", std::string("axi"), "",
         "axi: sphere on plane, axisymmetric (r, z); plane-strain: cylinder on plane, per unit length; 3d: "
         "hemisphere (a quarter by symmetry)",
         {"axi", "plane-strain", "3d"}},
        {"radius_m", "--radius", d.radius_m, "m", "Radius R of the sphere or cylinder (10 mm)"},
        {"youngs_modulus_pa", "--E", d.youngs_modulus_pa, "Pa", "Young's modulus of the body (steel)"},
        {"poisson_ratio", "--nu", d.poisson_ratio, "", "Poisson's ratio of the body (steel)"},
        {"force_n", "--load", d.force_n, "N", "Total force pressing the body onto the plane"},
        {"length_m", "--length", d.length_m, "m",
         "plane-strain: cylinder length carrying the load, force per length = load / length (2R)"},
        {"degree", "--degree", std::int64_t{d.degree}, "", "Lagrange degree of the displacement: 1 or 2"},
        {"refine", "--refine", std::int64_t{d.refine}, "",
         "Mesh level: 10 * 2^(refine/2) elements across the Hertz contact radius; -1 = the model's default "
         "(axi/plane-strain P1: 4, P2: 2; 3d P1: 2, P2: 0)"},
        {"penalty_c", "--penalty-c", d.penalty_c, "",
         "Penalty kappa = c E / h_c (README: penalty study)"},
        {"elastic_plane", "--elastic-plane", false, "",
         "Compare with two identical elastic bodies, E* = E / (2 (1 - nu^2)), as the preprint did (flagged)"},
        {"contact_element_size_m", "--contact-element-size", 0.0, "m",
         "Fixed contact-zone element size instead of --refine (0 = from --refine)"},
        {"force_rtol", "--force-rtol", d.force_rtol, "", "Relative tolerance of the load control on the force"},
        {"petsc_options", "--petsc-options", std::string(), "",
         "PETSc options for the solver (prefix hertz_), e.g. '-hertz_ksp_type gmres'"},
        {"xdmf", "--xdmf", std::string(), "",
         "Write displacement, stress, von Mises, max shear and contact pressure to this .xdmf (+ .h5)"},
    };
    return s;
  }();
  return schema;
}

fem::HertzSetup setup_from(const io::Parameters& params)
{
  fem::HertzSetup s;
  s.model = fem::parse_model(params.text("model"), "option --model");
  s.radius_m = params.real("radius_m");
  s.youngs_modulus_pa = params.real("youngs_modulus_pa");
  s.poisson_ratio = params.real("poisson_ratio");
  s.force_n = params.real("force_n");
  s.length_m = params.real("length_m");
  s.degree = static_cast<int>(params.integer("degree"));
  s.refine = static_cast<int>(params.integer("refine"));
  s.penalty_c = params.real("penalty_c");
  s.elastic_plane = params.flag("elastic_plane");
  s.contact_element_size_m = params.real("contact_element_size_m");
  s.force_rtol = params.real("force_rtol");
  s.petsc_options = params.text("petsc_options");
  s.xdmf_path = params.text("xdmf");
  return s;
}

/// value, Hertz value and relative error under `name`, `name`_hertz, `name`_error.
void compared(nlohmann::json& j, const std::string& name, const std::string& unit, double fem, double hertz)
{
  j[name + unit] = fem;
  j[name + "_hertz" + unit] = hertz;
  j[name + "_error"] = fem::relative_error(fem, hertz);
}

nlohmann::json summary(const fem::HertzResult& r)
{
  const fem::HertzSetup& s = r.setup;
  const bool line = s.model == fem::Model::plane_strain;
  const std::string c = line ? "b" : "a";
  nlohmann::json j;
  j["model"] = fem::model_name(s.model);
  j["degree"] = s.degree;
  j["refine"] = s.refine >= 0 ? s.refine : fem::default_refine(s.model, s.degree);
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

  const double length = line ? s.length_m : 1.0;
  j["force_target_n"] = s.force_n;
  j["force_n"] = r.load_reaction * length;
  j["force_error"] = fem::relative_error(r.load_reaction * length, s.force_n);
  j["force_from_pressure_n"] = r.load_contact * length;
  if (line)
  {
    j["length_m"] = s.length_m;
    j["force_per_length_n_per_m"] = r.load_reaction;
    j["force_per_length_from_pressure_n_per_m"] = r.load_contact;
  }
  compared(j, c, "_m", r.contact_size_m, r.hertz.contact_size_m);
  j[c + "_edge_m"] = r.contact_edge_m;
  compared(j, "p0", "_pa", r.peak_pressure_pa, r.hertz.peak_pressure_pa);
  j["p_max_nodal_pa"] = r.max_nodal_pressure_pa;
  j["p_max_nodal_error"] = fem::relative_error(r.max_nodal_pressure_pa, r.hertz.peak_pressure_pa);
  j["approach_m"] = r.approach_m;
  if (r.hertz.approach_m)
  {
    j["approach_hertz_m"] = *r.hertz.approach_m;
    j["approach_error"] = fem::relative_error(r.approach_m, *r.hertz.approach_m);
    j["approach_note"] = "the FEM approach includes the compliance of the finite, clamped body; Hertz's is a half-space's";
  }
  compared(j, "max_shear", "_pa", r.max_shear.value, r.hertz.max_shear_pa);
  compared(j, "max_shear_depth", "_m", r.max_shear.depth_m, r.hertz.max_shear_depth_m);
  compared(j, "max_von_mises", "_pa", r.max_von_mises.value, r.hertz.max_von_mises_pa);
  compared(j, "max_von_mises_depth", "_m", r.max_von_mises.depth_m, r.hertz.max_von_mises_depth_m);
  nlohmann::json s_m = nlohmann::json::array(), p_pa = nlohmann::json::array(), p_hertz = nlohmann::json::array();
  for (const fem::SurfaceNode& node : r.profile)
  {
    s_m.push_back(node.s);
    p_pa.push_back(node.pressure);
    p_hertz.push_back(contact::pressure_profile(r.hertz.peak_pressure_pa, r.hertz.contact_size_m, node.s));
  }
  j["profile"] = {{line ? "x_m" : "r_m", s_m}, {"p_pa", p_pa}, {"p_hertz_pa", p_hertz}};
  j["profile_rms_error"] = r.profile_rms_error;
  j["touching_nodes"] = r.touching_nodes;
  j["penalty_error_estimate"] = r.penalty_error_estimate;
  j["discretisation_error_estimate"] = r.discretisation_error_estimate;
  j["flags"] = r.flags;

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
  if (!s.xdmf_path.empty())
    j["xdmf"] = s.xdmf_path.string();
  return j;
}

nlohmann::json run_hertz(const io::Parameters& params)
{
  const fem::HertzResult result = fem::solve_hertz(MPI_COMM_WORLD, setup_from(params));
  const std::string c = result.setup.model == fem::Model::plane_strain ? "b" : "a";
  if (fem::world_rank() == 0)
    spdlog::info("{} = {:.6e} m ({:+.3f} %), p0 = {:.6e} Pa ({:+.3f} %), F = {:.6g} N, {} dofs, {} Newton its, "
                 "{:.2f} s",
                 c, result.contact_size_m,
                 100 * fem::relative_error(result.contact_size_m, result.hertz.contact_size_m),
                 result.peak_pressure_pa,
                 100 * fem::relative_error(result.peak_pressure_pa, result.hertz.peak_pressure_pa),
                 result.load_reaction * (c == "b" ? result.setup.length_m : 1.0), result.dofs,
                 result.newton_iterations, result.wall_s);
  return summary(result);
}
} // namespace

void add_hertz_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "hertz", "Penalty-contact FEM of a sphere or cylinder on a rigid plane, verified against Hertz theory");
  static std::string json_path;
  add_json_option(sub, json_path);
  static io::SchemaOptions* options = new io::SchemaOptions(sub, hertz_schema());
  register_scene({&hertz_schema(), run_hertz});
  on_run(sub, [] {
    fem::ensure_petsc();
    const nlohmann::json result = run_hertz(options->apply());
    if (fem::world_rank() == 0)
      emit_json(json_path, result);
    return 0;
  });
}
} // namespace rollcheck::cli
