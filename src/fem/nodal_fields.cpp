#include "fem/nodal_fields.h"
#include "fem/all_gather.h"
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <dolfinx/fem/assembler.h>
#include <dolfinx/fem/utils.h>
#include <stdexcept>

namespace rollcheck::fem
{
namespace
{
using T = double;
namespace dfem = dolfinx::fem;

/// Assembled and ghost-accumulated load vector of a linear form.
dolfinx::la::Vector<T> assemble_load(const dfem::Form<T>& form)
{
  const auto& V = *form.function_spaces()[0];
  dolfinx::la::Vector<T> b(V.dofmap()->index_map, V.dofmap()->index_map_bs());
  dfem::assemble_vector<T>(b.mutable_array(), form);
  b.scatter_rev(std::plus<T>());
  return b;
}

void require_same_layout(const dfem::FunctionSpace& a, const dfem::FunctionSpace& b)
{
  const auto& la = a.dofmap()->list().array();
  const auto& lb = b.dofmap()->list().array();
  if (!std::equal(la.begin(), la.end(), lb.begin(), lb.end()))
    throw std::logic_error("nodal recovery: P1 spaces with different node numbering");
}

/// P1 function space of `element` ("v_0" of its form) on the problem's mesh.
std::shared_ptr<dfem::FunctionSpace> p1_space(const PenaltyContact& problem, ContactForms::SpaceFactory element)
{
  auto mesh = std::const_pointer_cast<dolfinx::mesh::Mesh>(problem.mesh());
  return std::make_shared<dfem::FunctionSpace>(dfem::create_functionspace(element, "v_0", mesh));
}

/// The assembled load of `form` (one of the recovery forms) on `space`.
dolfinx::la::Vector<T> recovery_load(const PenaltyContact& problem, ufcx_form* form,
                                     std::shared_ptr<const dfem::FunctionSpace> space)
{
  auto mesh = std::const_pointer_cast<dolfinx::mesh::Mesh>(problem.mesh());
  return assemble_load(dfem::create_form<T>(*form, {space}, problem.coefficients(), problem.constants(),
                                            problem.subdomains(), mesh));
}
} // namespace

ContactPressure recover_contact_pressure(const PenaltyContact& problem)
{
  const ContactForms& forms = problem.forms();
  const auto Q = p1_space(problem, forms.scalar_p1_space);
  const auto contact_mass = recovery_load(problem, forms.contact_mass, Q);
  const auto pressure_load = recovery_load(problem, forms.pressure_load, Q);
  ContactPressure c;
  c.pressure = std::make_shared<dfem::Function<T>>(Q);
  c.pressure->name = "contact_pressure";
  const std::int32_t n = Q->dofmap()->index_map->size_local();
  c.contact_weight.assign(contact_mass.array().begin(), contact_mass.array().begin() + n);
  std::span<T> p = c.pressure->x()->mutable_array();
  for (std::int32_t i = 0; i < n; ++i)
    p[i] = c.contact_weight[i] > 0 ? pressure_load.array()[i] / c.contact_weight[i] : 0.0;
  c.pressure->x()->scatter_fwd();
  return c;
}

NodalFields recover_nodal_fields(const PenaltyContact& problem)
{
  const ContactForms& forms = problem.forms();
  NodalFields f;
  static_cast<ContactPressure&>(f) = recover_contact_pressure(problem);
  const auto Q = f.pressure->function_space();
  const auto S = p1_space(problem, forms.tensor_p1_space);
  const auto V1 = p1_space(problem, forms.vector_p1_space);
  require_same_layout(*Q, *S);
  require_same_layout(*Q, *V1);
  const auto volume_mass = recovery_load(problem, forms.volume_mass, Q);
  const auto stress_load = recovery_load(problem, forms.stress_load, S);

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
