#pragma once
// The structured grid of the sharp square end (build_square_end_grid_mesh),
// built without gmsh on rank 0 and distributed by DOLFINx: an independent
// discretisation of the rim end scene (fem/mesh/rim_end_mesh.h) where a
// Delaunay mesh could share an error with it.
//
// Geometry: build_rim_end_mesh's block x in [-L, 0], y and z in [0, H] with
// the flat sheet and the sharp end (a = 90 deg). A near-square end (|a - 90
// deg| <= max_grid_end_lean_rad) is the same grid sheared,
// x -> x + z tan(a - 90 deg) (1 + x / L): its end face leans as the other
// face, its far side stays.
//
// Grading: the grid's nodes are the tensor product of 1D spacings
// h(d) = min(far, h_0 + growth d) from the edge (x and z, h_0 = edge_m) and
// from the strip (y, contact_m within contact_zone_m), each box cut into
// Kuhn's six tetrahedra. Its elements at the edge are h_e across it and
// contact_m along it.
//
// Tags as build_rim_end_mesh's: contact, the sheet z = 0 and the end face
// where it faces the plane; top, z = H; symmetry_x, x = -L; symmetry_y,
// y = 0. Symmetry multiplicity 2.
#include "fem/mesh/rim_end_mesh.h"
#include <numbers>

namespace rollcheck::fem
{
/// The largest |a - 90 deg| of build_square_end_grid_mesh: 15 deg, near-square
/// ends (the oloid's at its symmetric orientations lean 3 deg), where the
/// sheared boxes' Kuhn tetrahedra stay well shaped.
inline constexpr double max_grid_end_lean_rad = std::numbers::pi / 12;

/// InputError for any other end than a sharp one within
/// max_grid_end_lean_rad of square on the flat sheet, or sizes that are not
/// positive and finite.
SceneMesh build_square_end_grid_mesh(MPI_Comm comm, const RimEndGeometry& geometry, const RimEndSizes& sizes);
} // namespace rollcheck::fem
