#include "fem/nodal_fields.h"
#include "fem/all_gather.h"
#include "fem/lumped_projection.h"
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rollcheck::fem
{
namespace
{
using T = double;
namespace dfem = dolfinx::fem;

void require_same_layout(const dfem::FunctionSpace& a, const dfem::FunctionSpace& b)
{
  const auto& la = a.dofmap()->list().array();
  const auto& lb = b.dofmap()->list().array();
  if (!std::equal(la.begin(), la.end(), lb.begin(), lb.end()))
    throw std::logic_error("nodal recovery: P1 spaces with different node numbering");
}
} // namespace

ContactPressure recover_contact_pressure(const PenaltyContact& problem)
{
  const FormBindings bound = problem.form_bindings();
  const auto Q = p1_space(bound, bound.forms.scalar_p1_space);
  ContactPressure c;
  c.contact_weight = contact_surface_weight(bound, Q);
  const auto pressure_load = recovery_load(bound, bound.forms.pressure_load, Q);
  c.pressure = std::make_shared<dfem::Function<T>>(Q);
  c.pressure->name = "contact_pressure";
  const std::int32_t n = Q->dofmap()->index_map->size_local();
  std::span<T> p = c.pressure->x()->mutable_array();
  for (std::int32_t i = 0; i < n; ++i)
    p[i] = c.contact_weight[i] > 0 ? pressure_load.array()[i] / c.contact_weight[i] : 0.0;
  c.pressure->x()->scatter_fwd();
  return c;
}

NodalFields recover_nodal_fields(const PenaltyContact& problem)
{
  const FormBindings bound = problem.form_bindings();
  NodalFields f;
  static_cast<ContactPressure&>(f) = recover_contact_pressure(problem);
  const auto Q = f.pressure->function_space();
  const auto S = p1_space(bound, bound.forms.tensor_p1_space);
  const auto V1 = p1_space(bound, bound.forms.vector_p1_space);
  require_same_layout(*Q, *S);
  require_same_layout(*Q, *V1);
  const auto volume_mass = recovery_load(bound, bound.forms.volume_mass, Q);
  const auto stress_load = recovery_load(bound, bound.forms.stress_load, S);

  f.displacement = std::make_shared<dfem::Function<T>>(V1);
  f.displacement->name = "displacement";
  f.displacement->interpolate(*problem.displacement());
  f.stress = std::make_shared<dfem::Function<T>>(S);
  f.stress->name = "stress";
  f.von_mises = std::make_shared<dfem::Function<T>>(Q);
  f.von_mises->name = "von_mises";
  f.max_shear = std::make_shared<dfem::Function<T>>(Q);
  f.max_shear->name = "max_shear";

  const std::int32_t n = Q->dofmap()->index_map->size_local();
  std::span<T> sigma = f.stress->x()->mutable_array();
  std::span<T> vm = f.von_mises->x()->mutable_array();
  std::span<T> tau = f.max_shear->x()->mutable_array();
  for (std::int32_t i = 0; i < n; ++i)
  {
    Eigen::Matrix3d s;
    for (int j = 0; j < 9; ++j)
      s(j / 3, j % 3) = sigma[9 * i + j] = stress_load.array()[9 * i + j] / volume_mass.array()[i];
    const Eigen::Matrix3d dev = s - s.trace() / 3 * Eigen::Matrix3d::Identity();
    vm[i] = std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
    const Eigen::Vector3d principal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s, Eigen::EigenvaluesOnly).eigenvalues();
    tau[i] = (principal.maxCoeff() - principal.minCoeff()) / 2;
  }
  for (const auto& field : {f.stress, f.von_mises, f.max_shear})
    field->x()->scatter_fwd();
  return f;
}

std::vector<SurfacePressureNode> gather_surface_pressure(MPI_Comm comm, const ContactPressure& fields)
{
  const std::vector<double> xq = fields.pressure->function_space()->tabulate_dof_coordinates(false);
  std::span<const double> p = fields.pressure->x()->array();
  std::vector<double> local;
  for (std::size_t i = 0; i < fields.contact_weight.size(); ++i)
    if (fields.contact_weight[i] > 0)
      local.insert(local.end(), {xq[3 * i], xq[3 * i + 1], xq[3 * i + 2], p[i], fields.contact_weight[i]});
  const std::vector<double> all = all_gather(comm, local);
  std::vector<SurfacePressureNode> nodes;
  for (std::size_t i = 0; i < all.size(); i += 5)
    nodes.push_back({{all[i], all[i + 1], all[i + 2]}, all[i + 3], all[i + 4]});
  return nodes;
}
} // namespace rollcheck::fem
