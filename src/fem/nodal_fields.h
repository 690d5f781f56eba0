#pragma once
// Post-processing fields on the P1 nodes of the scene mesh, recovered by
// lumped L2 projection (nodal averages weighted by the P1 basis functions):
//   contact pressure  p_i = int p phi_i dS / int phi_i dS   (contact surface)
//   stress            sigma_i = int sigma phi_i dV / int phi_i dV
// with the axisymmetric weight 2 pi r in both integrals. The pressure is thus
// the nodal contact force over the node's tributary area, which smooths the
// penalty's quadrature-point pressure and conserves the total force (the
// loads and the contact surface's weight: fem/lumped_projection.h).
// von Mises and the maximum shear (Tresca, (sigma_1 - sigma_3) / 2) are
// evaluated from the recovered nodal stress. A scene that reads only the
// contact face takes the pressure alone (two surface assemblies, not the
// volume's stress load, its eigenvalues and the P2 -> P1 interpolation).
#include "fem/penalty_contact.h"
#include <array>
#include <mpi.h>
#include <vector>

namespace rollcheck::fem
{
struct ContactPressure
{
  std::shared_ptr<dolfinx::fem::Function<double>> pressure; ///< P1 "contact_pressure", 0 off the surface
  /// Per owned P1 node: lumped contact-surface weight (0 off the contact surface).
  std::vector<double> contact_weight;
};

struct NodalFields : ContactPressure
{
  std::shared_ptr<dolfinx::fem::Function<double>> displacement; ///< P1 "displacement" (interpolated from P2)
  std::shared_ptr<dolfinx::fem::Function<double>> stress;       ///< P1 3x3 "stress", (x|r, y|theta, z)
  std::shared_ptr<dolfinx::fem::Function<double>> von_mises;    ///< P1 "von_mises"
  std::shared_ptr<dolfinx::fem::Function<double>> max_shear;    ///< P1 "max_shear"
};

ContactPressure recover_contact_pressure(const PenaltyContact& problem);
NodalFields recover_nodal_fields(const PenaltyContact& problem);

/// A P1 node of the contact surface: position, recovered pressure and lumped
/// contact-surface weight (its tributary area, or length in 2D).
struct SurfacePressureNode
{
  std::array<double, 3> x;
  double pressure_pa;
  double weight;
};

/// Every rank's contact-surface nodes, on every rank.
std::vector<SurfacePressureNode> gather_surface_pressure(MPI_Comm comm, const ContactPressure& fields);
} // namespace rollcheck::fem
