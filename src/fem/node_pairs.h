#pragma once
// Finding the node pairs (fem/node_pair.h) of two bodies meshed together,
// across processes, in stages:
// 1. node to node (here): every process's interface nodes gathered, grouped
//    by place into twins (interface_twins), each upper node outside the
//    mortar zone paired with its twin;
// 2. mortar (fem/mortar_pairs.h, 3D only): the upper contact facets in the
//    zone and the lower interface facets beneath them gathered, the lower
//    facets bucketed, each upper facet's projection clipped by them
//    (fem/clip_to_triangle.h) and integrated, the sums of nodes on other
//    processes sent to their owners.
#include "fem/node_pair.h"
#include <functional>
#include <span>
#include <utility>
#include <vector>

namespace rollcheck::fem
{
/// Interface nodes grouped by place: `nodes` holds (x, y, global index,
/// contact area) per node; each group is the nodes within `tol` of one
/// place (a twin pair, or a lone node).
std::vector<std::vector<std::pair<std::int64_t, double>>> interface_twins(std::span<const double> nodes, double tol);

/// The upper body's contact nodes owned by this process (those with contact
/// area, on its contact facets), paired with the lower body: in
/// `mortar_zone(x)` (none without it; 3D only) by the mortar's weighted gap
/// against the lower body's interface facets beneath their contact facets
/// (each facet's projection cut by them exactly, Sutherland-Hodgman, the
/// pieces integrated by Dunavant's 6-point rule, exact for the shape
/// functions' products), elsewhere at the interface (height within `tol` of
/// 0) node to node with their twins at the same place (coordinates equal to
/// `tol`). g0 is `initial_gap` at the node (node to node) or its mean
/// (mortar); the stiffness is left for the caller. The node-to-node pairs
/// come first, then the mortar pairs by node. Twins and facets are found
/// across processes. Collective; ComputationError where an interface node
/// has no twin or a contact facet in the zone is not wholly over the lower
/// body's interface.
std::vector<NodePair> interface_node_pairs(const PairingInput& input, double tol,
                                           const std::function<double(const double* x)>& initial_gap,
                                           const std::function<bool(const double* x)>& mortar_zone = {});
} // namespace rollcheck::fem
