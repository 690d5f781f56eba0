// The nodal contact pressure recovered from the nodal contact forces
// (fem/consistent_pressure.h against the lumped fem/nodal_fields.h) on the
// Hertz scene meshes, for a penetration imposed by hand: the displacement
// u_z = -z - d - alpha s (s = r or x) puts every point of the curved surface
// at the gap -(d + alpha s), so the penalty pressure is kappa (d + alpha s),
// linear over the whole surface. The consistent recovery returns it at every
// node to round-off (the mass matrix and the loads are integrated exactly);
// the lumped one returns it at each node's weighted patch centroid, off by
// about kappa alpha h on the graded mesh. The penalty's own nodal pressure
// (fem/penalty_pressure.h) returns it at every node by construction; with
// the 3D P1 vertex rule the lumped one does too. With the sign of alpha
// turned, only the nodes with s < d / |alpha| touch: the touching recovery
// is 0 on the others, where the lumped one reads the straddling patches.
#include "fem/consistent_pressure.h"
#include "fem/penalty_pressure.h"
#include "fem/mesh/scene_mesh.h"
#include "fem/nodal_fields.h"
#include "fem/petsc_session.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
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

double distance_from_axis(rf::Model model, const std::array<double, 3>& x)
{
  return model == rf::Model::solid ? std::hypot(x[0], x[1]) : x[0];
}

/// The P1 problem on the model's scene mesh with the displacement
/// u_z = -z - d - alpha s imposed: the gap -(d + alpha s) on the curved surface.
std::unique_ptr<rf::PenaltyContact> imposed_penetration(rf::Model model, double alpha)
{
  rf::ensure_petsc(); // MPI, before the mesh is distributed
  const rf::MeshGrading grading = rf::contact_grading(contact, contact / 10, radius);
  const rf::SceneMesh scene = rf::build_scene_mesh(MPI_COMM_WORLD, model, radius, grading);
  auto problem = std::make_unique<rf::PenaltyContact>(scene, model, 1, 200e9, 0.3, kappa, "");
  const int z = model == rf::Model::solid ? 2 : 1;
  const int gdim = z + 1;
  auto u = std::const_pointer_cast<dolfinx::fem::Function<double>>(problem->displacement());
  u->interpolate([&](const xt::xtensor<double, 2>& x) -> xt::xarray<double> {
    xt::xarray<double> values = xt::zeros<double>({std::size_t(gdim), x.shape(1)});
    for (std::size_t i = 0; i < x.shape(1); ++i)
      values(z, i) = -x(z, i) - depth - alpha * distance_from_axis(model, {x(0, i), x(1, i), 0.0});
    return values;
  });
  return problem;
}

/// max |p_i - kappa (d + alpha s_i)| / (kappa d) over the surface nodes.
double largest_error(rf::Model model, const rf::ContactPressure& recovered)
{
  double error = 0;
  for (const rf::SurfacePressureNode& node : rf::gather_surface_pressure(MPI_COMM_WORLD, recovered))
    error = std::max(error, std::abs(node.pressure_pa - kappa * (depth + slope * distance_from_axis(model, node.x)))
                                / (kappa * depth));
  return error;
}

/// The two recoveries of the linear pressure on the model's scene mesh.
LargestErrors recover_linear_pressure(rf::Model model)
{
  const auto problem = imposed_penetration(model, slope);
  return {largest_error(model, rf::consistent_contact_pressure(*problem)),
          largest_error(model, rf::recover_contact_pressure(*problem))};
}

/// Over the surface nodes off the touching disc s < d / alpha (alpha > 0
/// there, the gap -(d - alpha s)): the largest lumped and touching
/// pressures / (kappa d); over the nodes on it, the largest difference
/// between them / (kappa d).
struct EdgeReadings
{
  double lumped_outside = 0, touching_outside = 0, difference_inside = 0;
  int outside = 0;
};

EdgeReadings read_across_the_edge(rf::Model model)
{
  // The disc s < 0.55 contact: its edge midway between the nodes of the
  // graded mesh's contact zone (spaced contact / 10), so that a patch
  // straddles it.
  const double alpha = depth / (0.55 * contact);
  const auto problem = imposed_penetration(model, -alpha);
  const auto lumped = rf::gather_surface_pressure(MPI_COMM_WORLD, rf::recover_contact_pressure(*problem));
  const auto touching = rf::gather_surface_pressure(MPI_COMM_WORLD, rf::touching_lumped_pressure(*problem));
  EdgeReadings r;
  EXPECT_EQ(lumped.size(), touching.size());
  for (std::size_t i = 0; i < std::min(lumped.size(), touching.size()); ++i)
  {
    EXPECT_EQ(lumped[i].x, touching[i].x);
    const double s = distance_from_axis(model, lumped[i].x), scale = kappa * depth;
    if (s > depth / alpha * (1 + 1e-9))
    {
      ++r.outside;
      r.lumped_outside = std::max(r.lumped_outside, lumped[i].pressure_pa / scale);
      r.touching_outside = std::max(r.touching_outside, std::abs(touching[i].pressure_pa) / scale);
    }
    else if (s < depth / alpha * (1 - 1e-9))
      r.difference_inside =
          std::max(r.difference_inside, std::abs(touching[i].pressure_pa - lumped[i].pressure_pa) / scale);
  }
  return r;
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

TEST(HertzPressureRecovery, PenaltyNodalPressureIsTheGapsAtEveryNode)
{
  for (const rf::Model model : {rf::Model::axisymmetric, rf::Model::solid})
  {
    const auto problem = imposed_penetration(model, slope);
    EXPECT_LT(largest_error(model, rf::penalty_nodal_pressure(*problem)), 1e-9) << rf::model_name(model);
    const double lumped = largest_error(model, rf::recover_contact_pressure(*problem));
    if (model == rf::Model::solid)
      EXPECT_LT(lumped, 1e-9); // the vertex rule: F_i = kappa <-g_i>_+ A_i
    else
      EXPECT_GT(lumped, 1e-3); // Gauss points: the patch average
  }
}

TEST(HertzPressureRecovery, TouchingIsZeroWhereTheGapIsOpenAndLumpedWhereClosed)
{
  const EdgeReadings r = read_across_the_edge(rf::Model::axisymmetric);
  EXPECT_GT(r.outside, 10);
  EXPECT_GT(r.lumped_outside, 1e-3); // the patch straddling the edge, which touching leaves out
  EXPECT_EQ(r.touching_outside, 0.0);
  EXPECT_LT(r.difference_inside, 1e-12);
}
