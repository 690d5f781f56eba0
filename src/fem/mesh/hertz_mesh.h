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
// Tags (SceneMesh): contact, the arc (the sphere's surface) off the planes;
// top, the face z = R (in 2D the model's z is its second coordinate);
// symmetry_x, x = 0 (the axis in the axisymmetric model); symmetry_y (solid
// only), y = 0. Symmetry multiplicity: axisymmetric 1, plane strain 2,
// solid 4.
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/scene_facets.h"
#include "fem/model.h"
#include <mpi.h>

namespace rollcheck::fem
{
SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double radius_m, const MeshGrading& grading);
} // namespace rollcheck::fem
