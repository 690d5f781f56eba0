// fem/interpolate_between_meshes.h against fields it must carry exactly:
// a linear field (P1 holds it on any mesh) at the nodes of a finer mesh that
// reaches beyond the source's faces (affine extrapolation there), and two
// bodies meshed with twin nodes on their interface, each at its own constant
// (a node must take its own body's value, never its twin's). CTest runs it on
// 1 and 2 processes (interpolate_between_meshes_2_ranks), where a node's
// cell may lie on the other process.
#include "fem/contact_forms.h"
#include "fem/scenes/hertz_setup.h"
#include "fem/interpolate_between_meshes.h"
#include "fem/petsc_session.h"
#include "fem/mesh/scene_mesh.h"
#include <dolfinx/fem/utils.h>
#include <dolfinx/mesh/generation.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <mpi.h>


namespace
{
using Field = dolfinx::fem::Function<double>;

std::shared_ptr<Field> field_on(const std::shared_ptr<dolfinx::mesh::Mesh>& mesh, rollcheck::fem::Model model)
{
  auto V = std::make_shared<dolfinx::fem::FunctionSpace>(
      dolfinx::fem::create_functionspace(rollcheck::fem::contact_forms(model, 1).displacement_space, "v_0", mesh));
  return std::make_shared<Field>(V);
}

std::shared_ptr<dolfinx::mesh::Mesh> box(const std::array<double, 3>& upper, std::size_t cells)
{
  return std::make_shared<dolfinx::mesh::Mesh>(dolfinx::mesh::create_box(
      MPI_COMM_WORLD, {{{0, 0, 0}, upper}}, {cells, cells, cells}, dolfinx::mesh::CellType::tetrahedron,
      dolfinx::mesh::GhostMode::none));
}

/// Sets every node's block of values to value(x) (bs components).
void set_nodes(Field& u, const std::function<std::array<double, 3>(const double* x)>& value)
{
  const std::vector<double> x = u.function_space()->tabulate_dof_coordinates(false);
  const int bs = u.function_space()->dofmap()->index_map_bs();
  std::span<double> array = u.x()->mutable_array();
  for (std::size_t i = 0; i < x.size() / 3; ++i)
  {
    const std::array<double, 3> v = value(&x[3 * i]);
    std::copy_n(v.begin(), bs, &array[bs * i]);
  }
}

/// Largest |u(x_i) - value(x_i)| over every node of every process.
double largest_error(const Field& u, const std::function<std::array<double, 3>(const double* x)>& value)
{
  const std::vector<double> x = u.function_space()->tabulate_dof_coordinates(false);
  const int bs = u.function_space()->dofmap()->index_map_bs();
  std::span<const double> array = u.x()->array();
  double error = 0;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
  {
    const std::array<double, 3> v = value(&x[3 * i]);
    for (int j = 0; j < bs; ++j)
      error = std::max(error, std::abs(array[bs * i + j] - v[j]));
  }
  MPI_Allreduce(MPI_IN_PLACE, &error, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return error;
}
} // namespace

TEST(InterpolateBetweenMeshes, ALinearFieldIsCarriedExactlyInsideAndBeyondTheSourceMesh)
{
  rollcheck::fem::ensure_petsc();
  const auto linear = [](const double* x) {
    return std::array<double, 3>{1 + 2 * x[0] - x[1] + 0.5 * x[2], -3 * x[0] + x[2], 0.25 + x[1] + 4 * x[2]};
  };
  const auto coarse = field_on(box({1, 1, 1}, 3), rollcheck::fem::Model::solid);
  set_nodes(*coarse, linear);
  // Finer, and 7 % longer in x: its nodes beyond x = 1 lie outside every source cell.
  const auto fine = field_on(box({1.07, 1, 1}, 7), rollcheck::fem::Model::solid);
  rollcheck::fem::interpolate_between_meshes(*coarse, *fine);
  EXPECT_LT(largest_error(*fine, linear), 1e-12);
  // The same field's values must not come from a start of zeros: a
  // different field gives a different answer.
  const auto other = [](const double* x) { return std::array<double, 3>{x[0] * x[0], 0, 0}; };
  EXPECT_GT(largest_error(*fine, other), 0.5);
}

TEST(InterpolateBetweenMeshes, TwinNodesTakeTheirOwnBodysValue)
{
  rollcheck::fem::ensure_petsc();
  // Line Hertz's two bodies: y > 0 and y < 0, twins along y = 0.
  const double size = 1.0;
  const auto upper_body = [](const double* midpoint) { return midpoint[1] > 0 ? 1 : 0; };
  const auto coarse_scene = rollcheck::fem::build_line_block_mesh(MPI_COMM_WORLD, size, rollcheck::fem::contact_grading(0.1, 0.05, size));
  const auto fine_scene = rollcheck::fem::build_line_block_mesh(MPI_COMM_WORLD, size, rollcheck::fem::contact_grading(0.1, 0.02, size));
  const auto coarse = field_on(coarse_scene.mesh, rollcheck::fem::Model::plane_strain);
  const auto fine = field_on(fine_scene.mesh, rollcheck::fem::Model::plane_strain);

  // Each node's body from its cells (the twins on y = 0 have one each).
  const auto set_by_body = [&](Field& u) {
    const auto& mesh = *u.function_space()->mesh();
    const auto& x_dofmap = mesh.geometry().dofmap();
    std::span<const double> x = mesh.geometry().x();
    const int bs = u.function_space()->dofmap()->index_map_bs();
    std::span<double> array = u.x()->mutable_array();
    const auto cells = mesh.topology().index_map(mesh.topology().dim());
    for (std::int32_t c = 0; c < cells->size_local() + cells->num_ghosts(); ++c)
    {
      double midpoint_y = 0;
      for (std::int32_t node : x_dofmap.links(c))
        midpoint_y += x[3 * node + 1] / x_dofmap.links(c).size();
      for (std::int32_t block : u.function_space()->dofmap()->cell_dofs(c))
        array[bs * block + 1] = midpoint_y > 0 ? 1.0 : -1.0;
    }
  };
  set_by_body(*coarse);
  rollcheck::fem::interpolate_between_meshes(*coarse, *fine, upper_body);
  const auto reference = field_on(fine_scene.mesh, rollcheck::fem::Model::plane_strain); // the rule on the fine mesh
  set_by_body(*reference);
  std::span<const double> got = fine->x()->array(), want = reference->x()->array();
  double error = 0, error_without_parts = 0;
  for (std::size_t i = 0; i < got.size(); ++i)
    error = std::max(error, std::abs(got[i] - want[i]));
  MPI_Allreduce(MPI_IN_PLACE, &error, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_LT(error, 1e-12);
  // Without the parts both twins, at one place, take one cell's value, so
  // one of them is wrong: the check above can fail.
  rollcheck::fem::interpolate_between_meshes(*coarse, *fine);
  for (std::size_t i = 0; i < got.size(); ++i)
    error_without_parts = std::max(error_without_parts, std::abs(got[i] - want[i]));
  MPI_Allreduce(MPI_IN_PLACE, &error_without_parts, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(error_without_parts, 1.5);
}
