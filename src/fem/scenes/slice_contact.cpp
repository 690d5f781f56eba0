#include "fem/scenes/slice_contact.h"
#include "fem/scenes/hertz_solve.h"
#include "fem/petsc_session.h"
#include "fem/share_out.h"
#include "contact/hertz.h"
#include "core/error.h"
#include "fem/contact_measures.h"
#include "fem/load_control.h"
#include "fem/mesh/hertz_mesh.h"
#include "fem/nodal_fields.h"
#include <Eigen/Dense>
#include <array>
#include <chrono>
#include <cmath>
#include <fmt/format.h>

namespace rollcheck::fem
{
namespace
{
// A slice's result travels between ranks as these doubles.
constexpr std::size_t packed_size = 11;

std::vector<double> pack(const SliceFem& r)
{
  return {r.peak_pressure_pa,
          r.refined_peak_pressure_pa,
          r.half_width_m,
          r.hertz_peak_pressure_pa,
          r.hertz_half_width_m,
          static_cast<double>(r.dofs),
          static_cast<double>(r.refined_dofs),
          static_cast<double>(r.newton_iterations),
          static_cast<double>(r.krylov_iterations),
          r.wall_s,
          r.approach_m};
}

void unpack(const double* v, SliceFem& r)
{
  r.peak_pressure_pa = v[0];
  r.refined_peak_pressure_pa = v[1];
  r.half_width_m = v[2];
  r.hertz_peak_pressure_pa = v[3];
  r.hertz_half_width_m = v[4];
  r.dofs = static_cast<std::int64_t>(v[5]);
  r.refined_dofs = static_cast<std::int64_t>(v[6]);
  r.newton_iterations = static_cast<int>(v[7]);
  r.krylov_iterations = static_cast<int>(v[8]);
  r.wall_s = v[9];
  r.approach_m = v[10];
}

/// x > 0 to `digits` significant digits.
double rounded_to_significant_digits(double x, int digits)
{
  const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(x)));
  return std::round(x * scale) / scale;
}

SliceFem solve_slice(const SliceLoad& load, const SliceSettings& settings)
{
  SliceFem r;
  r.load = load;
  HertzSettings setup;
  setup.model = Model::plane_strain;
  setup.radius_m = load.radius_m;
  setup.youngs_modulus_pa = settings.youngs_modulus_pa;
  setup.poisson_ratio = settings.poisson_ratio;
  // gmsh's nodes follow the mesh sizes' last digits, and the sizes follow
  // b, so loads equal but for their last bits (a whole body's q through
  // MUMPS's parallel sums) meshed apart and their peaks differed by up to
  // 0.18 %. Solved at q to 9 significant digits (a change of at most 5e-10
  // in q, 2.5e-10 in p0) they share one mesh, unless q lies on a rounding
  // boundary.
  setup.force_n = rounded_to_significant_digits(load.load_n_per_m, 9); // per unit length
  setup.length_m = 1.0;
  setup.penalty_c = settings.penalty_c;
  setup.elastic_plane = settings.elastic_plane;
  setup.petsc_options = settings.petsc_options;
  setup.log_progress = false;
  setup.refine = settings.refine < 0 ? default_refine(Model::plane_strain, 1) : settings.refine;
  const HertzResult coarse = solve_hertz(MPI_COMM_SELF, setup);
  ++setup.refine;
  const HertzResult fine = solve_hertz(MPI_COMM_SELF, setup);
  r.peak_pressure_pa = coarse.max_nodal_pressure_pa;
  r.refined_peak_pressure_pa = fine.max_nodal_pressure_pa;
  r.half_width_m = coarse.contact_size_m;
  r.hertz_peak_pressure_pa = coarse.hertz.peak_pressure_pa;
  r.hertz_half_width_m = coarse.hertz.contact_size_m;
  r.approach_m = coarse.approach_m;
  r.dofs = coarse.dofs;
  r.refined_dofs = fine.dofs;
  r.newton_iterations = coarse.newton_iterations + fine.newton_iterations;
  r.krylov_iterations = coarse.krylov_iterations + fine.krylov_iterations;
  r.wall_s = coarse.wall_s + fine.wall_s;
  return r;
}
} // namespace

std::vector<SliceFem> solve_slices(MPI_Comm comm, std::span<const SliceLoad> slices, const SliceSettings& settings)
{
  ensure_petsc();
  const std::vector<double> packed = share_out(
      comm, slices.size(), packed_size, [&](std::size_t i) { return pack(solve_slice(slices[i], settings)); },
      [&](std::size_t i) {
        return fmt::format("slice at {:.6g} m (R = {:.6g} m, q = {:.6g} N/m)", slices[i].position_m,
                           slices[i].radius_m, slices[i].load_n_per_m);
      },
      "plane-strain slice solve", [&](std::size_t i) { return !(slices[i].load_n_per_m > 0); });
  std::vector<SliceFem> results(slices.size());
  for (std::size_t i = 0; i < slices.size(); ++i)
  {
    results[i].load = slices[i];
    unpack(&packed[i * packed_size], results[i]);
  }
  return results;
}
} // namespace rollcheck::fem

namespace rollcheck::fem
{
namespace
{
/// |tau_xz| at the stationary point of the quadratic least-squares fit
/// through the nodes (x, z, tau) within `radius` of (x0, z0); lengths over `scale`.
std::array<double, 3> orthogonal_shear_extremum(const std::vector<std::array<double, 3>>& nodes, double x0, double z0,
                                                double radius, double scale)
{
  std::vector<std::array<double, 3>> near;
  for (const auto& n : nodes)
    if (std::hypot(n[0] - x0, n[1] - z0) <= radius)
      near.push_back(n);
  if (near.size() < 12)
    throw ComputationError(fmt::format("slice subsurface: only {} nodes within {:.3g} m of the orthogonal shear's "
                                       "extremum; refine the mesh",
                                       near.size(), radius));
  Eigen::MatrixXd a(near.size(), 6);
  Eigen::VectorXd v(near.size());
  for (std::size_t i = 0; i < near.size(); ++i)
  {
    const double dx = (near[i][0] - x0) / scale, dz = (near[i][1] - z0) / scale;
    a.row(i) << 1, dx, dz, dx * dx, dx * dz, dz * dz;
    v(i) = near[i][2];
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(v);
  Eigen::Matrix2d hessian;
  hessian << 2 * c(3), c(4), c(4), 2 * c(5);
  const Eigen::Vector2d at = hessian.colPivHouseholderQr().solve(Eigen::Vector2d(-c(1), -c(2)));
  const double value = c(0) + c(1) * at(0) + c(2) * at(1) + c(3) * at(0) * at(0) + c(4) * at(0) * at(1)
                       + c(5) * at(1) * at(1);
  return {std::abs(value), x0 + at(0) * scale, z0 + at(1) * scale};
}
} // namespace

SliceSubsurface solve_slice_subsurface(const SliceLoad& load, const SliceSettings& settings, int refine)
{
  const auto start = std::chrono::steady_clock::now();
  ensure_petsc();
  HertzSettings setup;
  setup.model = Model::plane_strain;
  setup.radius_m = load.radius_m;
  setup.youngs_modulus_pa = settings.youngs_modulus_pa;
  setup.poisson_ratio = settings.poisson_ratio;
  setup.force_n = load.load_n_per_m;
  setup.length_m = 1.0; // per unit length
  setup.penalty_c = settings.penalty_c;
  setup.elastic_plane = settings.elastic_plane;
  setup.refine = refine;
  validate(setup);
  const HertzReference reference = hertz_reference(setup);
  const MeshGrading grading = mesh_grading(setup, reference);
  const SceneMesh scene = build_scene_mesh(MPI_COMM_SELF, Model::plane_strain, load.radius_m, grading);
  PenaltyContact problem(scene, Model::plane_strain, 1, reference.body_modulus_pa, settings.poisson_ratio,
                         settings.penalty_c * reference.body_modulus_pa / grading.contact_size_m,
                         settings.petsc_options);
  const double b = reference.contact_size_m;
  const LineApproach first = line_contact_approach(reference.load, load.radius_m, b, reference.effective_modulus_pa);
  const LoadControlReport reached
      = reach_force(problem, reference.load, first.approach_m, b * b / (2 * load.radius_m), first.exponent, 1e-6);

  SliceSubsurface r;
  r.refine = refine;
  r.elements_across_b = b / grading.contact_size_m;
  r.load_n_per_m = reached.force;
  const contact::LineHertz at_reaction = contact::line_contact(
      reached.force, load.radius_m, reference.effective_modulus_pa, settings.poisson_ratio);
  r.hertz_half_width_m = at_reaction.half_width_m;
  r.hertz_peak_pressure_pa = at_reaction.peak_pressure_pa;
  const NodalFields fields = recover_nodal_fields(problem);
  const std::vector<double> xq = fields.stress->function_space()->tabulate_dof_coordinates(false);
  std::span<const double> sigma = fields.stress->x()->array(), tau = fields.max_shear->x()->array();
  std::vector<AxisNode> axis;
  std::vector<std::array<double, 3>> shear_nodes; // (x, depth, tau_xz)
  for (std::size_t i = 0; i < tau.size(); ++i)
  {
    const double x = xq[3 * i], depth = xq[3 * i + 1];
    if (x < 2 * grading.contact_size_m)
      axis.push_back({depth, x, tau[i]});
    shear_nodes.push_back({x, depth, sigma[9 * i + 2]}); // (x, z) component, fem/nodal_fields.h's order
  }
  const DepthMaximum shear = maximum_along_axis(axis, 1e-9 * load.radius_m);
  r.max_shear_pa = shear.value;
  r.max_shear_depth_m = shear.depth_m;
  const auto [orthogonal, x, depth] = orthogonal_shear_extremum(shear_nodes, std::sqrt(3.0) / 2 * b, b / 2, 0.15 * b, b);
  r.orthogonal_shear_pa = orthogonal;
  r.orthogonal_shear_offset_m = x;
  r.orthogonal_shear_depth_m = depth;
  r.dofs = problem.num_dofs();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}
} // namespace rollcheck::fem
