#include "fem/penalty_pressure.h"
#include "fem/lumped_projection.h"
#include <algorithm>
#include <stdexcept>

namespace rollcheck::fem
{
namespace
{
namespace dfem = dolfinx::fem;

/// The gap g_i of each owned node of the pressure's P1 space Q.
std::vector<double> nodal_gap(const FormBindings& bound, const PenaltyContact& problem,
                              std::shared_ptr<const dfem::FunctionSpace> Q)
{
  const auto V1 = p1_space(bound, bound.forms.vector_p1_space);
  const std::vector<double> x = Q->tabulate_dof_coordinates(false);
  if (x != V1->tabulate_dof_coordinates(false))
    throw std::logic_error("nodal gap: scalar and vector P1 spaces with different node numbering");
  dfem::Function<double> u1(V1), initial_gap(std::const_pointer_cast<dfem::FunctionSpace>(Q));
  u1.interpolate(*problem.displacement());
  initial_gap.interpolate(*bound.coefficients.at("initial_gap_" + bound.forms.suffix));

  const int z = bound.mesh->geometry().dim() - 1;
  const int bs = V1->dofmap()->index_map_bs();
  std::span<const double> u = u1.x()->array();
  std::span<const double> g0 = initial_gap.x()->array();
  std::vector<double> gap(Q->dofmap()->index_map->size_local());
  for (std::size_t i = 0; i < gap.size(); ++i)
    gap[i] = x[3 * i + z] + u[bs * i + z] + g0[i];
  return gap;
}

/// The lumped recovery with p_i = value(g_i, lumped p_i) on the contact
/// surface's owned nodes.
template <class Value>
ContactPressure pressure_from_gap(const PenaltyContact& problem, Value value)
{
  const FormBindings bound = problem.form_bindings();
  ContactPressure c = recover_contact_pressure(problem);
  const std::vector<double> gap = nodal_gap(bound, problem, c.pressure->function_space());
  std::span<double> p = c.pressure->x()->mutable_array();
  for (std::size_t i = 0; i < gap.size(); ++i)
    if (c.contact_weight[i] > 0)
      p[i] = value(gap[i], p[i]);
  c.pressure->x()->scatter_fwd();
  return c;
}
} // namespace

ContactPressure penalty_nodal_pressure(const PenaltyContact& problem)
{
  const FormBindings bound = problem.form_bindings();
  const std::string& suffix = bound.forms.suffix;
  std::span<const double> scale = bound.coefficients.at("penalty_scale_" + suffix)->x()->array();
  if (std::any_of(scale.begin(), scale.end(), [](double s) { return s != 1.0; }))
    throw std::logic_error("penalty nodal pressure: the penalty is graded by cell; no single kappa at a node");
  const double kappa = bound.constants.at("penalty_stiffness_" + suffix)->value.at(0);
  return pressure_from_gap(problem, [kappa](double gap, double) { return kappa * std::max(0.0, -gap); });
}

ContactPressure touching_lumped_pressure(const PenaltyContact& problem)
{
  return pressure_from_gap(problem, [](double gap, double lumped) { return gap < 0 ? lumped : 0.0; });
}
} // namespace rollcheck::fem
