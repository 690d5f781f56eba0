#pragma once
// Two elastic bodies pressed together in plane strain, for line Hertz between
// them (build_line_block_mesh, fem/scenes/line_block_contact.h), built with
// the gmsh C++ API on rank 0 and distributed by DOLFINx.
//
// Geometry: the upper body x in [0, W], y in [0, W] and the lower
// x in [0, W], y in [-W, 0] (the x >= 0 half by symmetry), meshed together
// as twins along y = 0 (as build_rim_block_mesh, fem/mesh/rim_block_mesh.h).
//
// Grading: as the Hertz scenes' (fem/mesh/hertz_mesh.h) about the origin;
// see MeshGrading.
//
// Tags (SceneMesh, Model::plane_strain conventions): top, y = W and y = -W;
// symmetry_x, x = 0; contact, the upper body's facets on y = 0. Symmetry
// multiplicity 2.
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/scene_facets.h"
#include <mpi.h>

namespace rollcheck::fem
{
SceneMesh build_line_block_mesh(MPI_Comm comm, double size_m, const MeshGrading& grading);
} // namespace rollcheck::fem
