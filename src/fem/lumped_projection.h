#pragma once
// The loads of the lumped L2 projection onto the P1 nodes (fem/nodal_fields.h):
//   f_i = int f phi_i d(Omega)      (phi_i the P1 basis functions)
// of one of the recovery forms of forms/hertz.py (pressure_load, stress_load,
// volume_mass, contact_mass), assembled on a problem's mesh with its
// coefficients and constants, and summed over the processes sharing a node.
// The contact surface's lumped weight w_i = int_contact phi_i dS is each
// node's tributary area (length in 2D): the recovered pressure divides by
// it, and the node pairs weigh their gaps by it (fem/node_pairs.h).
#include "fem/contact_forms.h"
#include <dolfinx/fem/Constant.h>
#include <dolfinx/fem/Form.h>
#include <dolfinx/fem/Function.h>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/la/Vector.h>
#include <dolfinx/mesh/MeshTags.h>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rollcheck::fem
{
/// A problem's compiled forms and what their integrals are bound to: the
/// mesh, the coefficients and constants by their UFL names, the contact
/// surface's facet tags (PenaltyContact::form_bindings).
struct FormBindings
{
  const ContactForms& forms;
  std::shared_ptr<const dolfinx::mesh::Mesh> mesh;
  const std::map<std::string, std::shared_ptr<const dolfinx::fem::Function<double>>>& coefficients;
  const std::map<std::string, std::shared_ptr<const dolfinx::fem::Constant<double>>>& constants;
  const std::map<dolfinx::fem::IntegralType, const dolfinx::mesh::MeshTags<int>*>& subdomains;
};

/// The P1 space of `element` (argument "v_0" of its form) on the mesh.
std::shared_ptr<dolfinx::fem::FunctionSpace> p1_space(const FormBindings& bound,
                                                      ContactForms::SpaceFactory element);

/// The assembled, ghost-summed load of `form` (one of the recovery forms) on
/// `space`.
dolfinx::la::Vector<double> recovery_load(const FormBindings& bound, ufcx_form* form,
                                          std::shared_ptr<const dolfinx::fem::FunctionSpace> space);

/// w_i of each owned node of the scalar P1 space Q (0 off the contact
/// surface).
std::vector<double> contact_surface_weight(const FormBindings& bound,
                                           std::shared_ptr<const dolfinx::fem::FunctionSpace> Q);
} // namespace rollcheck::fem
