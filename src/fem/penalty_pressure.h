#pragma once
// The contact pressure at the P1 nodes of the contact surface read from the
// penalty's gap at the node, g_i = z_i + u_z(x_i) + g_0(x_i) (forms/hertz.py),
// instead of from the nodal contact forces alone (fem/nodal_fields.h: the
// lumped recovery F_i / A_i, an average over the node's patch):
//
// - penalty_nodal_pressure: the contact law at the node, p_i = kappa <-g_i>_+.
//   With the 3D P1 vertex rule (a node-based penalty) the node's force is
//   kappa <-g_i>_+ A_i, A_i its lumped area, so this is the lumped recovery
//   there, to rounding. Where the contact integral has Gauss points (P2) the
//   nodal gap is not what the quadrature sees: a P2 facet's vertices
//   penetrate more than its midside nodes (docs/methods/hertz-fem.md measures
//   +15 % on the peak), so this is a study option, not a recovery to use.
// - touching_lumped_pressure: the lumped F_i / A_i where the node touches
//   (g_i < 0) and 0 where its gap is open: the recovery made to satisfy the
//   contact condition p_i g_i = 0 at the node (Signorini; P. Wriggers,
//   "Computational Contact Mechanics", 2nd ed., Springer 2006, sec. 2.1). At
//   the contact edge, where p ~ sqrt(a^2 - r^2), a node just outside whose
//   patch straddles the edge reads the patch's average by the lumped
//   recovery, and 0 here, as it should. Inside the contact it is the lumped
//   recovery. With the 3D P1 vertex rule F_i > 0 exactly where g_i < 0, so
//   the two agree there.
//
// Only for a uniform penalty (the penalty scale 1 everywhere): a cellwise
// graded kappa has no single value at a node (std::logic_error otherwise).
// Both collective.
#include "fem/nodal_fields.h"

namespace rollcheck::fem
{
/// p_i = kappa <-g_i>_+ (P1, "contact_pressure", 0 off the contact surface)
/// with the lumped weights beside it, as recover_contact_pressure returns them.
ContactPressure penalty_nodal_pressure(const PenaltyContact& problem);

/// The lumped pressure on the nodes with g_i < 0, 0 on the others.
ContactPressure touching_lumped_pressure(const PenaltyContact& problem);
} // namespace rollcheck::fem
