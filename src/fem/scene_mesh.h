#pragma once
// Scene meshes for the Hertz models, built with the gmsh C++ API on rank 0 and
// distributed by DOLFINx.
//
// Geometry (z is vertical, the rigid plane is z = 0, the body touches it at
// the origin):
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
#include "fem/hertz_setup.h"
#include <dolfinx/mesh/Mesh.h>
#include <memory>
#include <mpi.h>
#include <vector>

namespace rollcheck::fem
{
struct SceneMesh
{
  std::shared_ptr<dolfinx::mesh::Mesh> mesh;
  /// Local facet indices (sorted) of the curved surface that may touch the plane.
  std::vector<std::int32_t> contact_facets;
  /// Loaded face z = R, where the prescribed approach acts.
  std::vector<std::int32_t> top_facets;
  /// Symmetry planes: x = 0 (all models; the axis in the axisymmetric one)
  /// and y = 0 (solid only).
  std::vector<std::int32_t> symmetry_x_facets;
  std::vector<std::int32_t> symmetry_y_facets;
  /// The model covers 1 / multiplicity of the body (plane strain 2, solid 4).
  int symmetry_multiplicity = 1;
  double wall_s = 0; ///< gmsh and mesh distribution
};

SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double radius_m, const MeshGrading& grading);
} // namespace rollcheck::fem
