#pragma once
// Consistent recovery of the contact pressure on the P1 nodes of the contact
// surface. The nodal contact forces of the discrete problem are, up to the
// finite element error, the pressure's loads against the hat functions,
//   F_i = int_contact p phi_i dS  (times 2 pi r axisymmetric),
// so the nodal pressures p_j of p = sum_j p_j phi_j solve
//   sum_j M_ij p_j = F_i,   M_ij = int_contact phi_i phi_j dS,
// the contact surface's consistent P1 mass matrix (forms/hertz.py,
// contact_mass_matrix). This is the L2 projection of the pressure onto the
// surface's P1 space: exact for a pressure linear over a node's patch on any
// mesh. The lumped recovery p_i = F_i / sum_j M_ij (fem/nodal_fields.h) is
// exact only for a constant: for a linear p it returns p at the phi_i-weighted
// centroid of node i's patch, off the node by O(h) on an irregular mesh, so
// its error carries a term O(h |grad p|) that scatters from node to node
// (T. J. R. Hughes, "The Finite Element Method", Dover 2000, sec. 4.4, on
// consistent and lumped mass; O. C. Zienkiewicz, R. L. Taylor, "The Finite
// Element Method", vol. 1, 5th ed. 2000, sec. 14.3, on recovery by
// projection).
//
// The support is the contact patch: the system is solved over the nodes
// that carry a contact force (F_i > 0), every other node's pressure is 0
// (where p ~ sqrt at the contact edge the projection may overshoot by a few
// per cent of p0 on the outermost nodes; docs/methods/hertz-fem.md).
//
// The patch's system (a few hundred to a few thousand nodes) is gathered on
// every process and solved there by a sparse Cholesky factorisation (Eigen);
// each process keeps its own nodes' values. Collective.
#include "fem/nodal_fields.h"

namespace rollcheck::fem
{
/// The pressure p (P1, "contact_pressure", 0 off the patch) with the lumped
/// weights beside it, as recover_contact_pressure returns them.
ContactPressure consistent_contact_pressure(const PenaltyContact& problem);
} // namespace rollcheck::fem
