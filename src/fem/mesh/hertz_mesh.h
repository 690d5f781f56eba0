#pragma once
// The Hertz scenes' mesh (build_scene_mesh), built with the gmsh C++ API on
// rank 0 and distributed by DOLFINx. z is vertical, the rigid plane is
// z = 0, the body touches it at the origin.
//
// Geometry:
// - axisymmetric and plane strain: the quarter disc r (or x) in [0, R],
//   centre (0, R), below its centre line z = R. Axisymmetric it is the
//   meridian section of a hemisphere; plane strain it is half of the half
//   disc of a cylinder, the other half given by symmetry about x = 0.
// - solid: the quarter hemisphere x, y >= 0 of the sphere centred (0, 0, R),
//   below z = R. The sphere is turned so that its parametric poles lie on the
//   top face, far from the contact, where they cannot distort the surface mesh.
//
// Grading: element size h(d) = min(h_far, h_c + g max(0, d - r_fine)) with d
// the distance from the first point of contact (gmsh Distance + Threshold
// fields, linear in between); see MeshGrading.
//
// Refinement of the solid model's contact (ContactRefinement, optional):
// smaller elements in a ball about the first point of contact, where the
// largest nodal pressure is read, and in a tube about the circle of the
// contact's edge on the sphere (r = c, z = R - sqrt(R^2 - c^2)), where the
// pressure p ~ sqrt(c^2 - r^2) has an unbounded slope and the lumped
// recovery's average over a node's patch is off by O(p0 sqrt(h / c)). Each
// is a gmsh Threshold field (sizes growing by the grading's rate away from
// the ball or the tube), the sizes the smallest of these and the grading's
// (a Min field). The tube's distance to the circle is a MathEval field,
// sqrt((sqrt(x^2 + y^2) - c)^2 + (z - z_c)^2).
//
// Structured contact cap (ContactRefinement::cap, optional): the sphere's
// surface within s < s_cap of the axis (s = sqrt(x^2 + y^2)) is meshed by
// rings (fem/mesh/cap_rings.h), not by gmsh: ring j's node at the angle t
// lies at (s_j cos t, s_j sin t, R - sqrt(R^2 - s_j^2)), exactly on the
// sphere, and the triangles between rings j and j + 1 join their nodes in
// the order of their segments' midpoint angles (no node between rings). The
// solid is then the meridian section (x, z), its arc split at s_cap,
// revolved by 90 degrees about the z axis, so that the cap is a face of its
// own bounded by the two symmetry planes' arcs and the ring s_cap; gmsh
// meshes the rest (the rest of the sphere, the planes and the tetrahedra)
// conforming to the cap's triangles (Mesh.MeshOnlyEmpty), with the same
// size fields.
//
// Tags (SceneMesh): contact, the arc (the sphere's surface) off the planes;
// top, the face z = R (in 2D the model's z is its second coordinate);
// symmetry_x, x = 0 (the axis in the axisymmetric model); symmetry_y (solid
// only), y = 0. Symmetry multiplicity: axisymmetric 1, plane strain 2,
// solid 4.
#include "fem/mesh/cap_rings.h"
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/scene_facets.h"
#include "fem/model.h"
#include <mpi.h>

namespace rollcheck::fem
{
/// Element sizes below the grading's contact size, solid model only; a size
/// of 0 leaves that part to the grading.
struct ContactRefinement
{
  double pole_size_m = 0;   ///< in the ball of radius pole_radius_m about the first point of contact
  double pole_radius_m = 0;
  double edge_size_m = 0;   ///< within edge_half_width_m of the contact's edge circle
  double edge_half_width_m = 0;
  double edge_radius_m = 0; ///< the circle's radius c
  CapRings cap;             ///< the structured contact cap's rings; none: the cap meshed as the rest
};

SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double radius_m, const MeshGrading& grading,
                           const ContactRefinement& refinement = {});
} // namespace rollcheck::fem
