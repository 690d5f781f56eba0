#pragma once
// The nodes of the rim loop's tables (the FEM end table, study/rims/end_table.h;
// the flat-rim table, study/rims/flat_rim_table.h) and their interpolation.
//
// A table's nodes are an odd number, evenly spaced, so that every other node
// is a table too: the check of the spacing reads a table by every
// `stride`-th node (2) and compares it with the whole (1).
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace rollcheck::study::rims
{
/// Nodes evenly over [lo, hi], an odd number of them, at most `step` apart;
/// one where the range is a point.
std::vector<double> even_nodes(double lo, double hi, double step);

/// Linear interpolation over (x, value) nodes ascending in x, held at the ends.
double interpolate_held(const std::vector<std::pair<double, double>>& nodes, double x);

/// The nodes interpolate_held reads at x over every `step`-th of the nodes at
/// `positions` (ascending), as (index into positions, weight): one node held
/// (weight 1), or the two about x (1 - t, t). What a table's look-up reads,
/// so that a table can solve only the nodes its look-ups reach.
std::vector<std::pair<std::size_t, double>> held_bracket(std::span<const double> positions, std::size_t step,
                                                         double x);

/// The stride of a table of n nodes: `stride` when there are 3 or more,
/// else 1 (every node).
std::size_t own_stride(int stride, std::size_t n);
} // namespace rollcheck::study::rims
