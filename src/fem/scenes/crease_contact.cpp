#include "fem/scenes/crease_contact.h"
#include "contact/hertz.h"
#include "fem/all_gather.h"
#include "fem/scenes/hertz_setup.h"
#include "fem/load_control.h"
#include "fem/nodal_fields.h"
#include "fem/petsc_session.h"
#include "fem/mesh/scene_mesh.h"
#include "core/error.h"
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace rollcheck::fem
{
namespace
{
void validate(const CreaseSettings& s)
{
  for (const auto& [value, name] : {std::pair{s.load_n_per_m, "load_n_per_m"}, std::pair{s.width_m, "width_m"},
                                    std::pair{s.youngs_modulus_pa, "youngs_modulus_pa"},
                                    std::pair{s.penalty_c, "penalty_c"}})
    if (!std::isfinite(value) || value <= 0)
      throw InputError(fmt::format("crease: {} must be positive and finite, got {}", name, value));
  if (!(s.face_angle_rad > 0 && s.face_angle_rad <= std::numbers::pi / 4))
    throw InputError(fmt::format("crease: face angle must lie in (0, 45] deg, got {} rad", s.face_angle_rad));
  if (!(s.poisson_ratio >= 0 && s.poisson_ratio < 0.5))
    throw InputError(fmt::format("crease: poisson_ratio must lie in [0, 0.5), got {}", s.poisson_ratio));
  if (s.refine < 0 || s.refine > 10 || s.levels < 2 || s.levels > 6)
    throw InputError(fmt::format("crease: refine must be 0 to 10 and levels 2 to 6, got {} and {}", s.refine,
                                 s.levels));
}

CreaseLevel solve_level(MPI_Comm comm, const CreaseStudy& study, int refine)
{
  const auto start = std::chrono::steady_clock::now();
  const CreaseSettings& s = study.setup;
  const double a = study.half_width_m, slope = std::tan(s.face_angle_rad);
  CreaseLevel level;
  level.refine = refine;
  level.contact_element_m = contact_element_size(a, refine);
  const SceneMesh scene = build_crease_mesh(comm, {s.width_m, s.width_m, s.face_angle_rad},
                                          contact_grading(a, level.contact_element_m, s.width_m));
  const double body_modulus = study.effective_modulus_pa * (1 - s.poisson_ratio * s.poisson_ratio);
  PenaltyContact problem(scene, Model::plane_strain, 1, body_modulus, s.poisson_ratio,
                         s.penalty_c * body_modulus / level.contact_element_m, s.petsc_options);
  level.dofs = problem.num_dofs();
  // Start: the face's height at the contact edge as the shift, and that plus
  // a line contact's approach (load_control.h) for the top; the load control
  // corrects both.
  const double first_approach
      = a * slope + line_contact_approach(s.load_n_per_m, s.width_m, a, study.effective_modulus_pa).approach_m;
  const LoadControlReport report = reach_force(problem, s.load_n_per_m, first_approach, a * slope, 1.0, 1e-6);
  level.newton_iterations = report.newton.newton_iterations;
  level.krylov_iterations = report.newton.krylov_iterations;

  std::vector<std::array<double, 2>> nodes; // (x, p)
  for (const SurfacePressureNode& node : gather_surface_pressure(comm, recover_contact_pressure(problem)))
    nodes.push_back({node.x[0], node.pressure_pa});
  std::sort(nodes.begin(), nodes.end());
  if (nodes.size() < 3 || !(nodes.front()[0] < 1e-9 * s.width_m) || !(nodes[1][1] > 0))
    throw ComputationError(fmt::format("crease: unresolved contact at level {} (element {:.3g} m, a = {:.3g} m)",
                                       refine, level.contact_element_m, a));
  level.apex_pressure_pa = nodes.front()[1];
  for (std::size_t i = 1; i < nodes.size(); ++i)
  {
    if (nodes[i][1] > 0)
      level.contact_edge_m = nodes[i][0];
    if (nodes[i - 1][0] <= a / 2 && a / 2 < nodes[i][0])
    {
      const double t = (a / 2 - nodes[i - 1][0]) / (nodes[i][0] - nodes[i - 1][0]);
      level.half_contact_pressure_pa = (1 - t) * nodes[i - 1][1] + t * nodes[i][1];
    }
  }
  level.wall_s = wall_seconds_since(comm, start);
  return level;
}
} // namespace

CreaseStudy solve_crease(MPI_Comm comm, const CreaseSettings& setup)
{
  validate(setup);
  ensure_petsc();
  CreaseStudy study;
  study.setup = setup;
  study.effective_modulus_pa = contact::effective_modulus_rigid_plane(setup.youngs_modulus_pa, setup.poisson_ratio);
  const double coefficient = study.effective_modulus_pa * std::tan(setup.face_angle_rad) / std::numbers::pi;
  study.half_width_m = setup.load_n_per_m / (study.effective_modulus_pa * std::tan(setup.face_angle_rad));
  study.half_contact_pressure_pa = coefficient * std::acosh(2.0);
  study.apex_growth_per_level_pa = coefficient * std::log(std::sqrt(2.0));
  if (study.half_width_m > setup.width_m / 20)
    throw InputError(fmt::format("crease: the contact half-width {:.3g} m is not small against the width {} m; "
                                 "lower the load or raise the face angle",
                                 study.half_width_m, setup.width_m));
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  for (int k = 0; k < setup.levels; ++k)
  {
    study.levels.push_back(solve_level(comm, study, setup.refine + k));
    if (rank == 0)
      spdlog::info("crease level {}: h = {:.3g} m, {} dofs, apex {:.5g} Pa, p(a/2) {:.5g} Pa, {:.1f} s",
                   study.levels.back().refine, study.levels.back().contact_element_m, study.levels.back().dofs,
                   study.levels.back().apex_pressure_pa, study.levels.back().half_contact_pressure_pa,
                   study.levels.back().wall_s);
  }
  return study;
}
} // namespace rollcheck::fem
