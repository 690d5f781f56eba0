#pragma once
// The rim end's section extruded (build_rim_end_extruded_mesh): the scene of
// build_rim_end_mesh (fem/mesh/rim_end_mesh.h) on the flat sheet with the
// edge square to the ruling, where the body does not vary along the edge,
// meshed in 2D by gmsh and extruded along it in layers. gmsh's 3D Delaunay
// mesh of the same block is isotropic: h_e along the edge over the whole
// edge zone, and b / contact_elements along the ruling over its whole length
// L (the loop's rounded ends: a block 10.5 r_e deep, hundreds of b, meshed
// for minutes a level). The fields are not isotropic, and the extruded mesh
// follows them:
// - Near the edge the field varies across it (in x and z) on the scale of
//   the elements there (h_e about the fillet's start) and along it (y) on
//   the scale b: elements h_e across, b / (2 contact_elements) along, as
//   the structured grid of the square end has them (b / contact_elements;
//   fem/mesh/square_end_grid_mesh.h).
// - Along the strip away from the edge the section is in plane strain: its
//   field varies in y and z on the scale b and along x only on the scale of
//   the distance d from the edge. There the section's elements are 0.3 d
//   long (growth d) and, across the sheet, b / (4 contact_elements) at it,
//   growing from it: the first layer under the sheet sets the P1 section's
//   peak pressure (rim_end_extruded_mesh.cpp, sheet_refinement).
//
// Section (x, z), in units of H while meshed: the near part, x from x_s =
// -x_t - 2 contact_zone_m to the block's end (and left of the other face's
// top for an acute rim), gmsh's Frontal-Delaunay triangles graded by
// rim_end_element_size at y = 0: the sheet, the fillet of radius r_e from
// (-x_t, 0) to its tangent point on the other face, the other face up to the
// top z = H or the end x = H; the far part, the quadrilateral from x = -L to
// the near part's left side, transfinite: along x from b / contact_elements
// at that side growing by `growth` up to far_m, across z from b / (4
// contact_elements) at the sheet growing by `growth`. Extruded along y
// through the layers of the structured grid (graded_nodes from the strip: b
// / (2 contact_elements) over contact_zone_m, growing by `growth` to far_m)
// without gmsh: each prism cut into three tetrahedra by the least node of
// each face (J. Dompierre et al., 8th International Meshing Roundtable,
// 1999), conformingly, the nodes ordered so that the cuts of the far part's
// (y, z) rectangles alternate as a union jack and every tetrahedron projects
// onto one triangle of its rectangle's cut: a plane-strain field P1 on the
// (y, z) triangulation is P1 on the tetrahedra (Kuhn's cut of a box has
// that property too). Cut all one way, the section's pressure leans with the
// cut (docs/methods/rims.md, "Where a rounded loop's time goes").
//
// Tags as build_rim_end_mesh's: contact, the sheet, fillet and other face
// where they face the plane; top, z = H; symmetry_x, x = -L; symmetry_y,
// y = 0. Symmetry multiplicity 2.
#include "fem/mesh/rim_end_mesh.h"

namespace rollcheck::fem
{
/// InputError unless the sheet is flat and the edge square to the ruling,
/// and for what build_rim_end_mesh refuses.
SceneMesh build_rim_end_extruded_mesh(MPI_Comm comm, const RimEndGeometry& geometry, const RimEndSizes& sizes);
} // namespace rollcheck::fem
