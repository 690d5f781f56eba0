// `rollcheck hertz`: penalty-contact FEM of a sphere or cylinder on a rigid
// plane, every result next to Hertz theory (src/fem, docs/methods/hertz-fem.md).
// Also the scene "hertz" of case files, and the convergence and penalty
// studies (`--study`).
#include "cli/cli.h"
#include "cli/scenes.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "fem/petsc_session.h"
#include "fem/scenes/scenes.h"
#include "fem/scenes/hertz_json.h"
#include "io/batch_report.h"
#include <fmt/format.h>
#include <fstream>
#include <spdlog/spdlog.h>

namespace rollcheck::cli
{
namespace
{
const SceneSchema<fem::HertzSettings>& hertz_schema()
{
  using fem::HertzSettings;
  using fem::Model;
  // Resource guard: refine 12 puts 640 elements across the contact, far
  // beyond the convergence study's finest level (6).
  static const io::Bounds refine_range{-1, 12};
  return kept_schema<HertzSettings>("hertz",
                                    "Penalty-contact FEM of a sphere or cylinder on a rigid plane, verified against "
                                    "Hertz theory",
                                    [](io::BoundSchema<HertzSettings>& s) {
    std::vector<std::pair<std::string, Model>> models;
    for (Model m : {Model::axisymmetric, Model::plane_strain, Model::solid})
      models.emplace_back(fem::model_name(m), m);
    s.choice("model", "--model", &HertzSettings::model,
             "axi: sphere on plane, axisymmetric (r, z); plane-strain: cylinder on plane, per unit length; 3d: "
             "hemisphere (a quarter by symmetry)",
             models)
        .real("radius_m", "--radius", &HertzSettings::radius_m, "m", "Radius R of the sphere or cylinder (10 mm)",
              io::positive);
    add_material(s, &HertzSettings::youngs_modulus_pa, &HertzSettings::poisson_ratio);
    s.real("force_n", "--load", &HertzSettings::force_n, "N", "Total force pressing the body onto the plane",
           io::positive)
        .real("length_m", "--length", &HertzSettings::length_m, "m",
              "plane-strain: cylinder length carrying the load, force per length = load / length (2R)", io::positive)
        .integer("degree", "--degree", &HertzSettings::degree, "",
                 "Lagrange degree of the displacement: 1 or 2; 0 = the model's default (3d: 2, axi and plane-strain: 1)",
                 io::Bounds{0, 2})
        .integer("refine", "--refine", &HertzSettings::refine, "",
                 "Mesh level: 10 * 2^(refine/2) elements across the Hertz contact radius; -1 = the model's default "
                 "(axi/plane-strain P1: 4, P2: 2; 3d P1: 2, P2: 0)",
                 refine_range)
        .integer("pole_refine", "--pole-refine", &HertzSettings::pole_refine, "",
                 "3d: extra refine levels about the first point of contact; -1 = the model's default (3d P2: 2, "
                 "else 0)",
                 io::Bounds{-1, 6})
        .integer("edge_refine", "--edge-refine", &HertzSettings::edge_refine, "",
                 "3d: extra refine levels about the contact's edge circle (the Hertz radius); -1 = the model's "
                 "default (3d P2: 2, else 0)",
                 io::Bounds{-1, 6})
        .choice("contact_cap", "--contact-cap", &HertzSettings::contact_cap,
                "3d: the contact cap's surface mesh (s < 2 a): unstructured (gmsh's, with the rest), rings (node "
                "rings about the axis, the Hertz edge midway between two; --pole-refine and --edge-refine set their "
                "spacing) or auto (3d P2: rings, else unstructured)",
                {{"auto", fem::ContactCapMesh::automatic},
                 {"unstructured", fem::ContactCapMesh::unstructured},
                 {"rings", fem::ContactCapMesh::rings}})
        .include(penalty_schema(), &HertzSettings::penalty_c)
        .choice("pressure_recovery", "--pressure-recovery", &HertzSettings::pressure_recovery,
                "Nodal contact pressure: lumped (nodal contact force over tributary area), consistent (the contact "
                "patch's mass-matrix system, exact for a linear pressure), penalty (kappa <-g>_+ at the node), "
                "touching (lumped where the node's gap is closed, 0 where it is open) or auto (3d P2: touching, else "
                "lumped)",
                {{"auto", fem::PressureRecovery::automatic},
                 {"lumped", fem::PressureRecovery::lumped},
                 {"consistent", fem::PressureRecovery::consistent},
                 {"penalty", fem::PressureRecovery::penalty},
                 {"touching", fem::PressureRecovery::touching}})
        .flag("elastic_plane", "--elastic-plane", &HertzSettings::elastic_plane,
              "Compare with two identical elastic bodies, E* = E / (2 (1 - nu^2)), as the preprint did (flagged)")
        .real("contact_element_size_m", "--contact-element-size", &HertzSettings::contact_element_size_m, "m",
              "Fixed contact-zone element size instead of --refine (0 = from --refine)", io::non_negative)
        // The load control's end point must be tighter than any error it verifies (fem::validate).
        .real("force_rtol", "--force-rtol", &HertzSettings::force_rtol, "",
              "Relative tolerance of the load control on the force", io::Bounds{0, 0.01, true, true})
        .text("petsc_options", "--petsc-options", &HertzSettings::petsc_options,
              "PETSc options for the solver (prefix hertz_), e.g. '-hertz_ksp_type gmres'; on the command line "
              "they may also follow `--`")
        .text("xdmf", "--xdmf", &HertzSettings::xdmf_path,
              "Write displacement, stress, von Mises, max shear and contact pressure of every load step to this .xdmf, "
              "their data to the .h5 beside it (ParaView)");
  });
}

nlohmann::json run_hertz(const io::Parameters& params)
{
  const fem::HertzResult result = fem::solve_hertz(MPI_COMM_WORLD, hertz_schema().bind(params));
  const std::string c = result.setup.model == fem::Model::plane_strain ? "b" : "a";
  auto error = [](double fem, double theory) { return fmt::format("{:+.3f} %", 100 * fem::relative_error(fem, theory)); };
  print_summary(fmt::format(
      "| {} ({}, P{}) | FEM | Hertz | error |\n|---|---|---|---|\n"
      "| contact size {} (Hertz-form fit) [m] | {:.6e} | {:.6e} | {} |\n"
      "| p0 (Hertz-form fit) [Pa] | {:.6e} | {:.6e} | {} |\n"
      "| largest nodal pressure [Pa] | {:.6e} | {:.6e} | {} |\n"
      "| pressure profile RMS / p0 | {:.4f} | | |\n"
      "| force [N] | {:.6g} | | |\n\n{} dofs, {} Newton iterations\n",
      "hertz", fem::model_name(result.setup.model), result.setup.degree, c, result.contact_size_m,
      result.hertz.contact_size_m, error(result.contact_size_m, result.hertz.contact_size_m), result.peak_pressure_pa,
      result.hertz.peak_pressure_pa, error(result.peak_pressure_pa, result.hertz.peak_pressure_pa),
      result.max_nodal_pressure_pa, result.hertz.peak_pressure_pa,
      error(result.max_nodal_pressure_pa, result.hertz.peak_pressure_pa), result.profile_rms_error,
      result.load_reaction * (c == "b" ? result.setup.length_m : 1.0), result.dofs, result.newton_iterations));
  spdlog::info("hertz: {:.2f} s", result.wall_s);
  return fem::to_json(result);
}

/// What --study, --out and --study-models chose.
struct StudyChoice
{
  std::string name; ///< empty: one case, no study
  std::string out = "results/hertz";
  std::vector<std::string> models = {"axi", "plane-strain", "3d"};
};

/// Runs the chosen study from the base setup of `params`; its table goes to
/// out/hertz_<name>.csv and its plot, by postprocess/hertz_study_plot.py, beside it.
nlohmann::json run_hertz_study(const StudyChoice& choice, const io::Parameters& params)
{
  const fem::HertzSettings base = hertz_schema().bind(params);
  const std::filesystem::path out = choice.out;
  const std::filesystem::path csv = out / ("hertz_" + choice.name + ".csv");
  const std::filesystem::path png = out / ("hertz_" + choice.name + ".png");
  const std::filesystem::path plot_log = out / ("hertz_" + choice.name + "_plot.log");
  // --out is a shared folder (every study's files): the study replaces only
  // its own, and only if rollcheck wrote them (core/output_manifest.h).
  const std::vector<std::string> written = {csv.filename().string(), png.filename().string(), plot_log.filename().string()};
  check_output_location(out, "option --out");
  check_output_entries(out, written, "option --out");
  std::vector<fem::Model> models;
  for (const std::string& name : choice.models)
    models.push_back(fem::parse_model(name, "option --study-models"));
  const fem::HertzStudy study = fem::run_study(MPI_COMM_WORLD, choice.name,
                                               choice.name == "convergence" ? fem::convergence_study(base, models)
                                               : choice.name == "pointwise" ? fem::pointwise_study(base)
                                                                            : fem::penalty_study(base, models));
  if (fem::world_rank() == 0)
  {
    std::filesystem::create_directory(out);
    claim_outputs(out, written);
    write_file_atomically(csv, fem::to_csv(study));
    // The script runs in `out`: it gets absolute paths.
    io::run_script("/usr/bin/python3", io::default_scripts_folder() / "hertz_study_plot.py",
                   {std::filesystem::absolute(csv).string(), std::filesystem::absolute(png).string()}, out,
                   std::filesystem::absolute(plot_log));
    spdlog::info("study {}: {} and {}", choice.name, csv.string(), png.string());
  }
  nlohmann::json summary = fem::to_json(study);
  summary["csv"] = csv.string();
  summary["png"] = png.string();
  return summary;
}
} // namespace

void add_hertz_command(CLI::App& app)
{
  static StudyChoice study;
  CLI::App* sub = add_scene_command(app, hertz_schema(), run_hertz, [](const io::Parameters& params) {
    return study.name.empty() ? run_hertz(params) : run_hertz_study(study, params);
  });
  declare_outputs(hertz_schema().schema(), {{"xdmf", OutputKind::file}});
  sub->add_option("--study", study.name,
                  "Run a study instead of one case: convergence (refine levels of every model and degree) or "
                  "penalty (penalty_c from 0.1 to 1000) or pointwise (3d cost against the largest nodal pressure's "
                  "and the profile's error, by pressure recovery); writes a CSV and a PNG to --out")
      ->check(CLI::IsMember({"convergence", "penalty", "pointwise"}));
  sub->add_option("--out", study.out, "Folder for the study's CSV and PNG (default: results/hertz)");
  sub->add_option("--study-models", study.models, "Models the study covers (default: axi plane-strain 3d)")
      ->check(CLI::IsMember({"axi", "plane-strain", "3d"}));
}
} // namespace rollcheck::cli
