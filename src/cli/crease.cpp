// `rollcheck crease`: the FEM peak pressure of a crease inside the contact,
// level by level, against the blunt-wedge solution of half-space theory
// (fem/scenes/crease_contact.h). The demonstration behind fem-sds's "reported apart":
// where a body stands on an edge, the FEM peak is a number of the mesh.
// Also the scene "crease" of case files.
#include "cli/cli.h"
#include "cli/scenes.h"
#include "fem/scenes/crease_contact.h"
#include "core/error.h"
#include <fmt/format.h>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
// A level's JSON record: every member under its own name.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CreaseLevel, refine, contact_element_m, apex_pressure_pa, half_contact_pressure_pa,
                                   contact_edge_m, dofs, newton_iterations, krylov_iterations, wall_s)
} // namespace rollcheck::fem

namespace rollcheck::cli
{
namespace
{
using fem::CreaseSettings;

const SceneSchema<CreaseSettings>& crease_schema()
{
  return kept_schema<CreaseSettings>("crease",
                                     "FEM pressure at a crease inside the contact (plane strain, several mesh levels) "
                                     "against the blunt-wedge solution: the apex peak grows with the mesh, the rest "
                                     "converges",
                                     [](auto& s) {
    s.real("face_angle_deg", "--face-angle", &CreaseSettings::face_angle_rad, "deg",
           "beta, between each face of the crease and the plane: the crease's angle is 180 - 2 beta (half-space "
           "theory needs tan beta << 1)",
           io::Bounds{0, 45, true, false}, std::numbers::pi / 180)
        .real("load_n_per_m", "--load-per-length", &CreaseSettings::load_n_per_m, "N/m",
              "Load per unit length of crease (the preprint's F = 100 N over 10 mm)", io::positive)
        .real("width_m", "--width", &CreaseSettings::width_m, "m", "Width and height of the modelled half of the body",
              io::positive);
    add_material(s, &CreaseSettings::youngs_modulus_pa, &CreaseSettings::poisson_ratio);
    s.include(penalty_schema(), &CreaseSettings::penalty_c)
        .integer("refine", "--refine", &CreaseSettings::refine, "", "First mesh level: h_c = a / (10 2^(level / 2))",
                 io::Bounds{0, 10})
        .integer("levels", "--levels", &CreaseSettings::levels, "", "Mesh levels, each h_c / sqrt 2 of the previous",
                 io::Bounds{2, 6});
  });
}

nlohmann::json run_crease(const io::Parameters& p)
{
  const fem::CreaseSettings setup = crease_schema().bind(p);
  const fem::CreaseStudy study = fem::solve_crease(MPI_COMM_WORLD, setup);

  std::string table = "| level | h_c (m) | DOFs | Newton | s | apex p (Pa) | growth (Pa) | growth / theory | "
                      "p(a/2) (Pa) | p(a/2) / theory - 1 | contact edge / a |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < study.levels.size(); ++k)
  {
    const fem::CreaseLevel& l = study.levels[k];
    const double growth = k > 0 ? l.apex_pressure_pa - study.levels[k - 1].apex_pressure_pa : 0.0;
    table += fmt::format("| {} | {:.3g} | {} | {} | {:.2f} | {:.5g} | {} | {} | {:.5g} | {:+.2f} % | {:.3f} |\n",
                         l.refine, l.contact_element_m, l.dofs, l.newton_iterations, l.wall_s, l.apex_pressure_pa,
                         k > 0 ? fmt::format("{:.4g}", growth) : "-",
                         k > 0 ? fmt::format("{:.3f}", growth / study.apex_growth_per_level_pa) : "-",
                         l.half_contact_pressure_pa,
                         100 * (l.half_contact_pressure_pa / study.half_contact_pressure_pa - 1),
                         l.contact_edge_m / study.half_width_m);
  }
  print_summary(fmt::format("crease of {:.4g} deg under {:.4g} N/m (a = {:.4g} m, p(a/2) = {:.5g} Pa, apex growth per level "
               "{:.4g} Pa by theory):\n\n{}\nThe apex pressure is singular: it grows with every level and is not a "
               "converged number; p(a/2) and the contact edge converge.\n",
               180 - 2 * setup.face_angle_rad * 180 / std::numbers::pi, setup.load_n_per_m, study.half_width_m,
               study.half_contact_pressure_pa, study.apex_growth_per_level_pa, table));
  return {{"face_angle_deg", setup.face_angle_rad * 180 / std::numbers::pi},
          {"load_n_per_m", setup.load_n_per_m},
          {"effective_modulus_pa", study.effective_modulus_pa},
          {"half_width_m", study.half_width_m},
          {"half_contact_pressure_pa", study.half_contact_pressure_pa},
          {"apex_growth_per_level_pa", study.apex_growth_per_level_pa},
          {"apex_pressure_converged", false},
          {"apex_pressure_coarsest_pa", study.levels.front().apex_pressure_pa},
          {"apex_pressure_finest_pa", study.levels.back().apex_pressure_pa},
          {"apex_mean_growth_over_theory",
           (study.levels.back().apex_pressure_pa - study.levels.front().apex_pressure_pa)
               / static_cast<double>(study.levels.size() - 1) / study.apex_growth_per_level_pa},
          {"finest_half_contact_pressure_error",
           study.levels.back().half_contact_pressure_pa / study.half_contact_pressure_pa - 1},
          {"levels", study.levels}};
}
} // namespace

void add_crease_command(CLI::App& app) { add_scene_command(app, crease_schema(), run_crease); }
} // namespace rollcheck::cli
