#pragma once
// A field solved on one mesh, evaluated at another mesh's degrees of freedom:
// the start of a finer level's Newton from the coarser level's solution
// (DOLFINx 0.5.2 interpolates only between functions on one mesh).
//
//   u_to(x_i) = u_from(x_i),  x_i a node of `to`, evaluated in the cell of
//   `from` that holds x_i, or, where none does, in the one that comes
//   nearest to holding it (its affine extrapolation: a node on a curved
//   face of the finer mesh lies just outside the coarser mesh's facets).
//
// The source must be of affine simplices (P1 geometry, as gmsh's linear
// tetrahedra): a cell holds x when none of x's barycentric coordinates in it
// is negative, and among the cells whose bounding boxes hold x the one whose
// most negative coordinate is largest holds it best (points beyond every
// box: DOLFINx's nearest cell, searched for them alone). On the rounded
// 120 deg rim end (cases/rim_obtuse_rounded.toml, 2 ranks, 53k-97k
// unknowns) it takes 0.20-0.27 s a level; DOLFINx's nearest-cell search for
// every node beyond a rank's own boxes took 4.6-15 s (docs/notes/rims-log.md#speed).
//
// Parts: where two bodies meet on one interface (a body and the block it
// presses on), the twin nodes there hold different values; `part(x)`, given
// a cell's midpoint, names the body it belongs to, and a node takes its
// value only from cells of its own cells' part. Runs on any number of
// processes: every rank's nodes are searched in every rank's cells (the
// nearest wins), which suits levels of up to a few million unknowns.
#include <dolfinx/fem/Function.h>
#include <functional>

namespace rollcheck::fem
{
void interpolate_between_meshes(const dolfinx::fem::Function<double>& from, dolfinx::fem::Function<double>& to,
                                const std::function<int(const double* midpoint)>& part = {});
} // namespace rollcheck::fem
