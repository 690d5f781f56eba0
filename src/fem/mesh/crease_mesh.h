#pragma once
// The crease scene's mesh (build_crease_mesh), built with the gmsh C++ API
// on rank 0 and distributed by DOLFINx.
//
// Geometry: a crease in contact, in plane strain: the half x >= 0 (symmetry
// about x = 0) of a body whose lower surface is the straight face
// z = x tan(beta) from the apex (0, 0) to x = W, closed by the side x = W
// and the top z = H. Mirrored, the surface has a kink of 180 deg - 2 beta at
// the apex, which touches the plane first.
//
// Grading: as the Hertz scenes' (fem/mesh/hertz_mesh.h) about the apex;
// see MeshGrading.
//
// Tags (SceneMesh, Model::plane_strain conventions: the vertical is the
// second coordinate): contact, the face off the planes x = 0 and x = W;
// top, z = H; symmetry_x, x = 0. Symmetry multiplicity 2.
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/scene_facets.h"
#include <mpi.h>

namespace rollcheck::fem
{
struct CreaseGeometry
{
  double width_m = 0;          ///< W
  double height_m = 0;         ///< H, above the apex
  double face_angle_rad = 0;   ///< beta, between the face and the plane, in (0, pi / 4]
};

/// InputError unless W > 0, 0 < beta <= 45 deg and H > 2 W tan(beta).
SceneMesh build_crease_mesh(MPI_Comm comm, const CreaseGeometry& crease, const MeshGrading& grading);
} // namespace rollcheck::fem
