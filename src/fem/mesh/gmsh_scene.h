#pragma once
// For the scene mesh builders (fem/mesh/scene_mesh.h): gmsh run on the
// geometry a builder adds, with the options every scene meshes with
// (Frontal-Delaunay triangles, Delaunay tetrahedra, optimised; several
// volumes tetrahedralised one at a time on one surface mesh), element sizes
// refused below what gmsh meshes reliably, the grading about the point of
// contact (MeshGrading: gmsh Distance + Threshold fields) and the pieces of
// geometry two scenes share.
#include "fem/mesh/gmsh_raw_mesh.h"
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/volume_mesher.h"
#include <functional>

namespace rollcheck::fem::scene_build
{
/// Runs gmsh on the geometry `add_geometry_and_sizes` builds, whose element
/// sizes (and any other meshing option) it sets too; it returns the smallest
/// size, InputError below 1e-8 of the model (gmsh's geometric tolerance: an
/// element near it aborts the 2D mesher from inside an OpenMP region).
/// The mesh as read_gmsh_mesh(dim) reads it; 3D volumes by `mesher`.
RawMesh mesh_with_gmsh(int dim, const std::function<double()>& add_geometry_and_sizes,
                       VolumeMesher mesher = VolumeMesher::delaunay);

/// mesh_with_gmsh with the grading about the point of contact, whose tag
/// `add_geometry` returns.
RawMesh mesh_with_gmsh(int dim, const std::function<int()>& add_geometry, const MeshGrading& grading);

/// The size field of `grading` about the gmsh point `pole`, the sizes from
/// it alone.
void set_graded_size_field(int pole, const MeshGrading& grading);

/// The gmsh point entity at the origin (the first point of contact) of a
/// model of size about `size`; ComputationError if there is none.
int point_at_origin(double size);

/// Quarter disc of radius R in the xy-plane of gmsh (y is the model's z):
/// r in [0, R], below its centre (0, R); returns the tag of the point of
/// contact, the origin.
int add_quarter_disc(double R);
} // namespace rollcheck::fem::scene_build
