// The nodal contact pressure recovered from the nodal contact forces
// (fem/consistent_pressure.h against the lumped fem/nodal_fields.h) on the
// Hertz scene meshes, for a penetration imposed by hand: the displacement
// u_z = -z - d - alpha s (s = r or x) puts every point of the curved surface
// at the gap -(d + alpha s), so the penalty pressure is kappa (d + alpha s),
// linear over the whole surface. The consistent recovery returns it at every
// node to round-off (the mass matrix and the loads are integrated exactly);
// the lumped one returns it at each node's weighted patch centroid, off by
// about kappa alpha h on the graded mesh.
#include "fem/consistent_pressure.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/nodal_fields.h"
#include "fem/petsc_session.h"
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <xtensor/xarray.hpp>
#include <xtensor/xtensor.hpp>

// DOLFINx says `using namespace dolfinx` at global scope: its fem would clash with ours.
namespace rf = rollcheck::fem;

namespace
{
constexpr double radius = 0.01, contact = 1e-4, kappa = 1e15;
constexpr double depth = 1e-6, slope = 1e-2; // p = kappa (d + alpha s): 1 GPa on the axis, 2 GPa at s = 100 um

struct LargestErrors
{
  double consistent, lumped; ///< max |p_i - p(s_i)| / p(0) over the surface nodes
};

/// The two recoveries of the linear pressure on the model's scene mesh.
LargestErrors recover_linear_pressure(rf::Model model)
{
  rf::ensure_petsc(); // MPI, before the mesh is distributed
  const rf::MeshGrading grading = rf::contact_grading(contact, contact / 10, radius);
  const rf::SceneMesh scene = rf::build_scene_mesh(MPI_COMM_WORLD, model, radius, grading);
  rf::PenaltyContact problem(scene, model, 1, 200e9, 0.3, kappa, "");
  const int z = model == rf::Model::solid ? 2 : 1;
  const int gdim = z + 1;
  auto u = std::const_pointer_cast<dolfinx::fem::Function<double>>(problem.displacement());
  u->interpolate([&](const xt::xtensor<double, 2>& x) -> xt::xarray<double> {
    xt::xarray<double> values = xt::zeros<double>({std::size_t(gdim), x.shape(1)});
    for (std::size_t i = 0; i < x.shape(1); ++i)
      values(z, i) = -x(z, i) - depth - slope * (model == rf::Model::solid ? std::hypot(x(0, i), x(1, i)) : x(0, i));
    return values;
  });
  const auto largest = [&](const rf::ContactPressure& recovered) {
    double error = 0;
    for (const rf::SurfacePressureNode& node : rf::gather_surface_pressure(MPI_COMM_WORLD, recovered))
    {
      const double s = model == rf::Model::solid ? std::hypot(node.x[0], node.x[1]) : node.x[0];
      error = std::max(error, std::abs(node.pressure_pa - kappa * (depth + slope * s)) / (kappa * depth));
    }
    return error;
  };
  return {largest(rf::consistent_contact_pressure(problem)), largest(rf::recover_contact_pressure(problem))};
}
} // namespace

TEST(HertzPressureRecovery, ConsistentIsExactForALinearPressureAxisymmetric)
{
  const LargestErrors e = recover_linear_pressure(rf::Model::axisymmetric);
  EXPECT_LT(e.consistent, 1e-9);
  EXPECT_GT(e.lumped, 1e-3); // the lumped recovery's patch-centroid error, which the consistent one removes
}

TEST(HertzPressureRecovery, ConsistentIsExactForALinearPressurePlaneStrain)
{
  const LargestErrors e = recover_linear_pressure(rf::Model::plane_strain);
  EXPECT_LT(e.consistent, 1e-9);
  EXPECT_GT(e.lumped, 1e-3);
}
