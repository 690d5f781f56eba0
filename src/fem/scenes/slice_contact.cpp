#include "fem/scenes/slice_contact.h"
#include "fem/scenes/hertz_solve.h"
#include "fem/petsc_session.h"
#include "fem/share_out.h"
#include "contact/hertz.h"
#include "core/error.h"
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
/// The stationary point of the cubic least-squares fit in (x, z) through the
/// nodes (x, z, value) within `radius` of (x0, z0), found by Newton's method
/// from (x0, z0): (|value|, x, z) there. Lengths over `scale` in the fit. A
/// quadratic's fit would be biased by the field's third derivatives (on the
/// closed form, by 0.02 b in depth at a radius of 0.15 b); the cubic's
/// stationary point lies within 1e-3 b of the closed form's.
std::array<double, 3> fitted_extremum(const std::vector<std::array<double, 3>>& nodes, double x0, double z0,
                                      double radius, double scale)
{
  std::vector<std::array<double, 3>> near;
  for (const auto& n : nodes)
    if (std::hypot(n[0] - x0, n[1] - z0) <= radius)
      near.push_back(n);
  if (near.size() < 20)
    throw ComputationError(fmt::format("slice subsurface: only {} nodes within {:.3g} m of ({:.3g}, {:.3g}) m; "
                                       "refine the mesh",
                                       near.size(), radius, x0, z0));
  auto basis = [](double x, double z) {
    Eigen::Matrix<double, 10, 1> row;
    row << 1, x, z, x * x, x * z, z * z, x * x * x, x * x * z, x * z * z, z * z * z;
    return row;
  };
  Eigen::MatrixXd a(near.size(), 10);
  Eigen::VectorXd v(near.size());
  for (std::size_t i = 0; i < near.size(); ++i)
  {
    a.row(i) = basis((near[i][0] - x0) / scale, (near[i][1] - z0) / scale).transpose();
    v(i) = near[i][2];
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(v);
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for (int k = 0; k < 30; ++k)
  {
    const double x = p(0), z = p(1);
    const Eigen::Vector2d gradient(c(1) + 2 * c(3) * x + c(4) * z + 3 * c(6) * x * x + 2 * c(7) * x * z + c(8) * z * z,
                                   c(2) + c(4) * x + 2 * c(5) * z + c(7) * x * x + 2 * c(8) * x * z + 3 * c(9) * z * z);
    Eigen::Matrix2d hessian;
    hessian << 2 * c(3) + 6 * c(6) * x + 2 * c(7) * z, c(4) + 2 * c(7) * x + 2 * c(8) * z,
        c(4) + 2 * c(7) * x + 2 * c(8) * z, 2 * c(5) + 2 * c(8) * x + 6 * c(9) * z;
    p -= hessian.colPivHouseholderQr().solve(gradient);
  }
  if (!(p.norm() * scale <= radius))
    throw ComputationError("slice subsurface: the fitted extremum lies outside the fitted nodes");
  return {std::abs(basis(p(0), p(1)).dot(c)), x0 + p(0) * scale, z0 + p(1) * scale};
}
} // namespace

SliceSubsurface solve_slice_subsurface(const SliceLoad& load, const SliceSettings& settings, int refine, int degree)
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
  setup.degree = degree;
  validate(setup);
  const HertzReference reference = hertz_reference(setup);
  const MeshGrading grading = mesh_grading(setup, reference);
  const SceneMesh scene = build_scene_mesh(MPI_COMM_SELF, Model::plane_strain, load.radius_m, grading);
  PenaltyContact problem(scene, Model::plane_strain, degree, reference.body_modulus_pa, settings.poisson_ratio,
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
  std::span<const double> sigma = fields.stress->x()->array();
  // (x, depth, value) of the in-plane principal shear, mirrored about the
  // axis (the quarter model's symmetry plane), and of tau_xz; components in
  // fem/nodal_fields.h's (x, y, z) order.
  std::vector<std::array<double, 3>> shear_nodes, orthogonal_nodes;
  for (std::size_t i = 0; i < sigma.size() / 9; ++i)
  {
    const double x = xq[3 * i], depth = xq[3 * i + 1];
    const double* s = &sigma[9 * i];
    const double shear = std::hypot((s[0] - s[8]) / 2, s[2]);
    shear_nodes.push_back({x, depth, shear});
    if (x > 0)
      shear_nodes.push_back({-x, depth, shear});
    orthogonal_nodes.push_back({x, depth, s[2]});
  }
  const double radius = 0.15 * b;
  const auto [shear, shear_x, shear_depth] = fitted_extremum(shear_nodes, 0, 0.786 * b, radius, b);
  if (!(std::abs(shear_x) < 0.01 * b)) // the mirrored fit is even in x: its extremum lies on the axis
    throw ComputationError(fmt::format("slice subsurface: the largest shear's fit peaks {:.3g} b off the axis", shear_x / b));
  r.max_shear_pa = shear;
  r.max_shear_depth_m = shear_depth;
  const auto [orthogonal, x, depth] = fitted_extremum(orthogonal_nodes, std::sqrt(3.0) / 2 * b, b / 2, radius, b);
  r.orthogonal_shear_pa = orthogonal;
  r.orthogonal_shear_offset_m = x;
  r.orthogonal_shear_depth_m = depth;
  r.dofs = problem.num_dofs();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}
} // namespace rollcheck::fem
