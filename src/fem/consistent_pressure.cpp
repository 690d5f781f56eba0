#include "fem/consistent_pressure.h"
#include "core/error.h"
#include "fem/all_gather.h"
#include "fem/lumped_projection.h"
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <dolfinx/fem/assembler.h>
#include <dolfinx/fem/utils.h>
#include <fmt/format.h>
#include <stdexcept>
#include <unordered_map>
#include "hertz.h" // the mass matrix form of forms/hertz.py (fem/contact_forms.h holds the problem's own)

namespace rollcheck::fem
{
namespace
{
namespace dfem = dolfinx::fem;

/// The contact surface's P1 mass matrix form of the forms' model (their
/// suffix's tag: "axi_p1" -> axi).
ufcx_form& contact_mass_matrix(const ContactForms& forms)
{
  const std::string tag = forms.suffix.substr(0, forms.suffix.find('_'));
  if (tag == "axi")
    return *form_hertz_contact_mass_matrix_axi;
  if (tag == "plane")
    return *form_hertz_contact_mass_matrix_plane;
  if (tag == "solid")
    return *form_hertz_contact_mass_matrix_solid;
  throw std::logic_error("consistent pressure recovery: no mass matrix form for the forms " + forms.suffix);
}

/// The entries M_ij of the contact surface's mass matrix between two nodes
/// of the patch, as (global i, global j, value) triples, this process's
/// facets only (each facet is integrated on one process).
std::vector<double> patch_mass_entries(const FormBindings& bound, std::shared_ptr<const dfem::FunctionSpace> Q,
                                       std::span<const double> force)
{
  auto mesh = std::const_pointer_cast<dolfinx::mesh::Mesh>(bound.mesh);
  const dfem::Form<double> mass = dfem::create_form<double>(contact_mass_matrix(bound.forms), {Q, Q},
                                                            bound.coefficients, bound.constants, bound.subdomains, mesh);
  const auto map = Q->dofmap()->index_map;
  std::vector<std::int32_t> local;
  std::vector<std::int64_t> global;
  std::vector<double> entries;
  const auto add = [&](const std::span<const std::int32_t>& rows, const std::span<const std::int32_t>& cols,
                       const std::span<const double>& values) {
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (std::size_t c = 0; c < cols.size(); ++c)
        if (force[rows[r]] > 0 && force[cols[c]] > 0)
        {
          local = {rows[r], cols[c]};
          global.resize(2);
          map->local_to_global(local, global);
          entries.insert(entries.end(), {double(global[0]), double(global[1]), values[r * cols.size() + c]});
        }
    return 0;
  };
  dfem::assemble_matrix(add, mass, {});
  return entries;
}
} // namespace

ContactPressure consistent_contact_pressure(const PenaltyContact& problem)
{
  const FormBindings bound = problem.form_bindings();
  const auto Q = p1_space(bound, bound.forms.scalar_p1_space);
  const auto map = Q->dofmap()->index_map;
  const MPI_Comm comm = map->comm();
  ContactPressure c;
  c.contact_weight = contact_surface_weight(bound, Q);
  // F_i summed on its owner, then sent to the ghosts: every process agrees on the patch.
  dolfinx::la::Vector<double> force = recovery_load(bound, bound.forms.pressure_load, Q);
  force.scatter_fwd();
  std::span<const double> f = force.array();

  // The patch's nodes (global index, F_i) and its mass matrix, on every process.
  const std::int32_t owned = map->size_local();
  std::vector<double> loaded_local;
  for (std::int32_t i = 0; i < owned; ++i)
    if (f[i] > 0)
      loaded_local.insert(loaded_local.end(), {double(map->local_range()[0] + i), f[i]});
  const std::vector<double> loaded = all_gather(comm, loaded_local);
  const std::vector<double> entries = all_gather(comm, patch_mass_entries(bound, Q, f));
  std::unordered_map<std::int64_t, int> row;
  Eigen::VectorXd rhs(loaded.size() / 2);
  for (std::size_t k = 0; k < loaded.size(); k += 2)
  {
    row.emplace(std::int64_t(loaded[k]), int(k / 2));
    rhs[k / 2] = loaded[k + 1];
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t k = 0; k < entries.size(); k += 3)
    triplets.emplace_back(row.at(std::int64_t(entries[k])), row.at(std::int64_t(entries[k + 1])), entries[k + 2]);
  Eigen::SparseMatrix<double> M(rhs.size(), rhs.size());
  M.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(M);
  if (factor.info() != Eigen::Success)
    throw ComputationError(fmt::format("consistent pressure recovery: the contact patch's mass matrix ({} nodes) "
                                       "is not positive definite",
                                       rhs.size()));
  const Eigen::VectorXd nodal = factor.solve(rhs);

  c.pressure = std::make_shared<dfem::Function<double>>(Q);
  c.pressure->name = "contact_pressure";
  std::span<double> p = c.pressure->x()->mutable_array();
  std::fill(p.begin(), p.end(), 0.0);
  for (std::int32_t i = 0; i < owned; ++i)
    if (f[i] > 0)
      p[i] = nodal[row.at(map->local_range()[0] + i)];
  c.pressure->x()->scatter_fwd();
  return c;
}
} // namespace rollcheck::fem
