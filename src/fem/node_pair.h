#pragma once
// A node pair: the contact of two elastic bodies meshed together, read at one
// node of the upper body's contact face (fem/penalty_contact.h
// set_node_pairs solves with them; fem/node_pairs.h finds them), and what
// the pairing reads of one process's part of a problem.
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace rollcheck::fem
{
/// Frictionless contact between two elastic bodies meshed together, the
/// mesh carrying the interface flattened at height 0 and the bodies' profile
/// in the initial gap. A pair reads the pressure at one node of the upper
/// body's contact face from a gap that is a weighted sum over nodes of both
/// sides: g = g0 + sum_k a_k u_z(upper_k) - sum_j w_j u_z(lower_j), the a_k
/// and the w_j each summing to 1; p = kappa <-g>_+, energy kappa <-g>_+^2 A / 2,
/// so the force p A acts down on the upper nodes (shared by a_k) and up on
/// the lower ones (by w_j).
/// - Node to node, where the two faces are conforming: the node and its twin,
///   weights 1 (P. Wriggers, Computational Contact Mechanics, 2nd ed., 2006,
///   sec. 4.1: exact for matching meshes and small slip).
/// - Mortar, wherever the faces do not match (a fillet lifted off the
///   interface) and beside it: the gap is the pointwise gap over the upper
///   face, projected onto the interface, weighed by the node's dual shape
///   function psi_i = 4 N_i - 1 on each linear triangle (int psi_i N_k dA =
///   delta_ik int N_i dA), g_i = int psi_i g dA / A_i, so a_k = delta_ik,
///   w_j = int psi_i phi_j dA / A_i (phi_j the lower face's shape
///   functions), g0 = int psi_i g0(x) dA / A_i and A = A_i = int N_i dA
///   (B. I. Wohlmuth, SIAM J. Numer. Anal. 38, 2000, 989: the dual space;
///   A. Popp, M. Gitterle, M. W. Gee, W. A. Wall, Int. J. Numer. Meth.
///   Engng 83, 2010, 1428: dual mortar contact in 3D; B. Yang, T. A.
///   Laursen, X. Meng, Int. J. Numer. Meth. Engng 62, 2005, 1183: the
///   weighted gap under a penalty; M. A. Puso, T. A. Laursen, Comput.
///   Methods Appl. Mech. Engrg 193, 2004, 601: the segments in 3D). A
///   uniform traction then reaches both faces' nodes as its consistent
///   loads, whatever the meshes (the contact patch test; test_mortar_pairs),
///   and where the faces match the pair is node to node. The standard weights N_i (a_k = int N_i N_k dA / A_i)
///   pass the patch test too but couple each node's gap to its neighbours'
///   even where the faces match: on the preprint's 60 deg end on steel they
///   converged to the same ratio (3.4628 against the dual's 3.4716) with
///   the far side's nodes scattering by 4.0-4.5 % instead of 2.5-2.8 % and
///   up to 1.5 times the Newton and Krylov iterations (docs/methods/rims.md).
///   The node paired with the point of the lower facet below it (node to
///   segment, Wriggers sec. 4.2), which this replaces on the rim's fillet,
///   fails the patch test: there its pressures scattered by +-10 % from
///   node to node. So does a node-to-node pair beside a mortar pair: each
///   lumps the other's share of the facets they share (its test: a node's
///   load 21 % off its consistent load).
/// Indices are global dof blocks, so a pair may join nodes of different
/// processes; a pair lives on the process that owns its node.
struct WeightedBlock
{
  std::int64_t block = -1; ///< global dof block
  double weight = 0;
};

struct NodePair
{
  /// Global dof block of the upper node: the pair's only upper block, with
  /// a_k = delta_ik (node to node and the dual mortar alike).
  std::int64_t node = -1;
  std::vector<WeightedBlock> lower; ///< w_j (node to node: the twin, 1)
  std::array<double, 3> x{0.0, 0.0, 0.0}; ///< the node's position
  double area_m2 = 0;            ///< A (length in 2D)
  double initial_gap_m = 0;      ///< g0
  double stiffness_pa_per_m = 0; ///< kappa
};

/// One process's part of a problem, as the pairing reads it.
struct PairingInput
{
  /// Its communicator, geometric dimension and (3D mortar) the facet-cell
  /// connectivity.
  const dolfinx::mesh::Mesh& mesh;
  /// The displacement space's: the pairs' blocks are its blocks.
  const dolfinx::fem::DofMap& dofmap;
  /// (x, y, z) of each local block: owned blocks, then ghosts.
  std::span<const double> x;
  /// Each owned block's contact area: its lumped contact-surface weight
  /// (fem/lumped_projection.h), 0 off the upper body's contact face.
  std::span<const double> contact_area;
  /// The upper body's contact facets (local indices).
  std::span<const std::int32_t> contact_facets;

  std::int32_t owned_blocks() const { return dofmap.index_map->size_local(); }
  std::int64_t first_block() const { return dofmap.index_map->local_range()[0]; }
  bool owns(std::int64_t block) const { return block >= first_block() && block < first_block() + owned_blocks(); }
  /// The global index of a local block (owned or ghost).
  std::int64_t global_block(std::int32_t local) const
  {
    const std::int32_t owned = owned_blocks();
    return local < owned ? first_block() + local : dofmap.index_map->ghosts()[local - owned];
  }
};
} // namespace rollcheck::fem
