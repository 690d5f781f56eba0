// `rollcheck hertz`: penalty-contact FEM of a sphere or cylinder on a rigid
// plane, every result next to Hertz theory (src/fem, README "Hertz FEM").
// Also the scene "hertz" of case files, and the convergence and penalty
// studies (`--study`).
#include "cli/cli.h"
#include "cli/scenes.h"
#include "contact/hertz.h"
#include "fem/fem.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <spdlog/spdlog.h>
#include <sstream>

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
/// Runs a study's setups one after the other; a failed run (e.g. a diverged
/// solve at an extreme penalty) becomes a row with its message.
nlohmann::json run_study(const std::string& name, const std::vector<fem::HertzSetup>& setups,
                         const std::filesystem::path& out_dir)
{
  const bool root = fem::world_rank() == 0;
  std::ostringstream csv;
  csv << "model,degree,refine,penalty_c,elements_across_contact,dofs,cells,ranks,newton_its,krylov_its,"
         "wall_s,solve_s,size_error,p0_error,p_max_nodal_error,max_shear_error,max_shear_depth_error,"
         "max_von_mises_error,max_von_mises_depth_error,force_error,profile_rms_error,penalty_error_estimate,"
         "discretisation_error_estimate,flags,status\n";
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < setups.size(); ++i)
  {
    const fem::HertzSetup& s = setups[i];
    const int refine = s.refine >= 0 ? s.refine : fem::default_refine(s.model, s.degree);
    if (root)
      spdlog::info("study {} [{}/{}]: {} P{} refine {} c {}", name, i + 1, setups.size(), fem::model_name(s.model),
                   s.degree, refine, s.penalty_c);
    csv << fmt::format("{},{},{},{},", fem::model_name(s.model), s.degree, refine, s.penalty_c);
    try
    {
      const fem::HertzResult r = fem::solve_hertz(MPI_COMM_WORLD, s);
      const nlohmann::json j = summary(r);
      const std::string c = s.model == fem::Model::plane_strain ? "b" : "a";
      csv << fmt::format("{:.6g},{},{},{},{},{},{:.6g},{:.6g},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
                         "{:.6e},{:.6e},{:.6e},{},ok\n",
                         r.elements_across_contact, r.dofs, r.cells, r.ranks, r.newton_iterations, r.krylov_iterations,
                         r.wall_s, r.solve_s, j[c + "_error"].get<double>(), j["p0_error"].get<double>(),
                         j["p_max_nodal_error"].get<double>(), j["max_shear_error"].get<double>(),
                         j["max_shear_depth_error"].get<double>(), j["max_von_mises_error"].get<double>(),
                         j["max_von_mises_depth_error"].get<double>(), j["force_error"].get<double>(), r.profile_rms_error, r.penalty_error_estimate,
                         r.discretisation_error_estimate, fmt::join(r.flags, " "));
      rows.push_back(j);
    }
    catch (const ComputationError& e)
    {
      std::string message = e.what();
      std::replace(message.begin(), message.end(), ',', ';');
      csv << std::string(20, ',') << "failed: " << message << "\n";
      rows.push_back({{"model", fem::model_name(s.model)}, {"degree", s.degree}, {"refine", refine},
                      {"penalty_c", s.penalty_c}, {"failed", e.what()}});
    }
  }
  const std::filesystem::path csv_path = out_dir / ("hertz_" + name + ".csv");
  const std::filesystem::path png_path = out_dir / ("hertz_" + name + ".png");
  if (root)
  {
    std::filesystem::create_directories(out_dir);
    write_atomically(csv_path, [&](const std::filesystem::path& tmp) {
      std::ofstream file(tmp);
      file << csv.str();
      if (!file)
        throw InputError(fmt::format("cannot write '{}'", csv_path.string()));
    });
    const std::string command = fmt::format("/usr/bin/python3 '{}/hertz_study_plot.py' '{}' '{}'",
                                            ROLLCHECK_POSTPROCESS_DIR, csv_path.string(), png_path.string());
    if (std::system(command.c_str()) != 0)
      throw ComputationError(fmt::format("the plot script failed: {}", command));
    spdlog::info("study {}: {} and {}", name, csv_path.string(), png_path.string());
  }
  return {{"study", name}, {"csv", csv_path.string()}, {"png", png_path.string()}, {"runs", rows}};
}

std::vector<fem::Model> parse_models(const std::vector<std::string>& names)
{
  std::vector<fem::Model> models;
  for (const std::string& name : names)
    models.push_back(fem::parse_model(name, "option --study-models"));
  return models;
}
} // namespace

void add_hertz_command(CLI::App& app)
{
  CLI::App* sub = app.add_subcommand(
      "hertz", "Penalty-contact FEM of a sphere or cylinder on a rigid plane, verified against Hertz theory");
  static std::string json_path, study, out_dir = "results/hertz";
  static std::vector<std::string> study_models = {"axi", "plane-strain", "3d"};
  add_json_option(sub, json_path);
  static io::SchemaOptions* options = new io::SchemaOptions(sub, hertz_schema());
  sub->add_option("--study", study,
                  "Run a study instead of one case: convergence (refine levels of every model and degree) or "
                  "penalty (penalty_c from 0.1 to 1000); writes a CSV and a PNG to --out")
      ->check(CLI::IsMember({"convergence", "penalty"}));
  sub->add_option("--out", out_dir, "Folder for the study's CSV and PNG (default: results/hertz)");
  sub->add_option("--study-models", study_models, "Models the study covers (default: axi plane-strain 3d)")
      ->check(CLI::IsMember({"axi", "plane-strain", "3d"}));
  register_scene({&hertz_schema(), run_hertz});
  on_run(sub, [] {
    fem::ensure_petsc();
    const io::Parameters params = options->apply();
    nlohmann::json result;
    if (study.empty())
      result = run_hertz(params);
    else
    {
      const fem::HertzSetup base = setup_from(params);
      const std::vector<fem::Model> models = parse_models(study_models);
      result = run_study(study,
                         study == "convergence" ? fem::convergence_study(base, models)
                                                : fem::penalty_study(base, models),
                         out_dir);
    }
    if (fem::world_rank() == 0)
      emit_json(json_path, result);
    return 0;
  });
}
} // namespace rollcheck::cli
