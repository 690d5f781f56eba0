#pragma once
// The mortar pairs of the upper contact nodes in a zone (fem/node_pair.h,
// NodePair: the dual mortar's weighted gap). For each upper node i, over the
// projection of its contact facets onto the interface (z = 0):
//   A_i  = int N_i dA,
//   g0_i = int psi_i g0 dA / A_i,
//   w_ij = int psi_i phi_j dA / A_i,
// psi_i = 4 N_i - 1 the dual shape function on each linear triangle (its
// integral against N_k is delta_ik int N_i dA), phi_j the lower face's shape
// functions. Each upper facet's projection is clipped by the lower facets
// beneath it (Sutherland-Hodgman, fem/clip_to_triangle.h) and the pieces are
// integrated by Dunavant's symmetric 6-point rule of degree 4 (D. A.
// Dunavant, Int. J. Numer. Meth. Engng 21, 1985, 1129), exact for the
// products of the shape functions.
#include "fem/node_pair.h"
#include <functional>
#include <vector>

namespace rollcheck::fem
{
/// The mortar pairs of this process's upper nodes on the contact facets with
/// a node in `mortar_zone(x)` (3D, linear elements), in the order of their
/// global blocks. The lower facets are those of lower cells (below z = 0)
/// with a whole facet within `tol` of z = 0. Collective; InputError for
/// elements that are not linear, ComputationError for a contact facet seen
/// edge-on from the interface or not wholly over the lower body's interface.
std::vector<NodePair> mortar_node_pairs(const PairingInput& input, double tol,
                                        const std::function<double(const double* x)>& initial_gap,
                                        const std::function<bool(const double* x)>& mortar_zone);
} // namespace rollcheck::fem
