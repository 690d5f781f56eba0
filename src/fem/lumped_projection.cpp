#include "fem/lumped_projection.h"
#include <dolfinx/fem/assembler.h>
#include <dolfinx/fem/utils.h>
#include <functional>

namespace rollcheck::fem
{
namespace dfem = dolfinx::fem;

std::shared_ptr<dfem::FunctionSpace> p1_space(const FormBindings& bound, ContactForms::SpaceFactory element)
{
  auto mesh = std::const_pointer_cast<dolfinx::mesh::Mesh>(bound.mesh);
  return std::make_shared<dfem::FunctionSpace>(dfem::create_functionspace(element, "v_0", mesh));
}

dolfinx::la::Vector<double> recovery_load(const FormBindings& bound, ufcx_form* form,
                                          std::shared_ptr<const dfem::FunctionSpace> space)
{
  auto mesh = std::const_pointer_cast<dolfinx::mesh::Mesh>(bound.mesh);
  const dfem::Form<double> linear_form
      = dfem::create_form<double>(*form, {space}, bound.coefficients, bound.constants, bound.subdomains, mesh);
  dolfinx::la::Vector<double> b(space->dofmap()->index_map, space->dofmap()->index_map_bs());
  dfem::assemble_vector<double>(b.mutable_array(), linear_form);
  b.scatter_rev(std::plus<double>());
  return b;
}

std::vector<double> contact_surface_weight(const FormBindings& bound, std::shared_ptr<const dfem::FunctionSpace> Q)
{
  const auto contact_mass = recovery_load(bound, bound.forms.contact_mass, Q);
  const std::int32_t n = Q->dofmap()->index_map->size_local();
  return {contact_mass.array().begin(), contact_mass.array().begin() + n};
}
} // namespace rollcheck::fem
