#pragma once
// The rim end's mesh (build_rim_end_mesh, fem/scenes/rim_end_contact.h),
// built with the gmsh C++ API (OpenCASCADE) on rank 0 and distributed by
// DOLFINx; its geometry and sizes are those of the rim end on a block
// (fem/mesh/rim_block_mesh.h) and of the structured grid
// (fem/mesh/square_end_grid_mesh.h) too.
//
// Geometry: the neighbourhood of one end of a loaded ruling, the y >= 0 half
// by symmetry. The ruling runs along x and ends at the origin, on the body's
// rim (the edge, along y). The contacting sheet is the cylinder of radius R
// about (x, 0, R) (its curvature across the ruling); beyond the edge the
// other face is the plane through the y axis at the interior angle a from
// the sheet, measured through the body in the ruling's vertical plane
// (90 deg: a square end, the face x = 0; below, an acute rim whose other face
// leans back over the sheet; towards 180 deg the other face rises gently
// beyond x = 0). The block is cut at x = -L (the far side, a plane of
// symmetry: plane strain), x = H (beyond the edge), y = H and z = H (the
// loaded top); the edge may be rounded with a fillet of radius r_e. Built in
// units of H (OpenCASCADE's tolerances are absolute) and scaled back.
//
// Grading: rim_end_element_size (RimEndSizes) as gmsh's size callback.
//
// Tags (SceneMesh, Model::solid conventions): contact, every face but the
// block's planes (the sheet, the fillet, the other face) where it faces the
// plane z = 0; top, z = H; symmetry_x, the far side x = -L; symmetry_y,
// y = 0. Symmetry multiplicity 2.
#include "fem/mesh/rim_end_geometry.h"
#include "fem/mesh/scene_facets.h"
#include "fem/mesh/volume_mesher.h"
#include <mpi.h>

namespace rollcheck::fem
{
/// InputError for a geometry outside the ranges above (R, H, L and the sizes
/// positive and finite, a in [60, 180) deg, 0 <= r_e <
/// largest_edge_radius_over_depth H, R >= H for the cylinder sheet). The
/// volume tetrahedralised by `mesher`.
SceneMesh build_rim_end_mesh(MPI_Comm comm, const RimEndGeometry& geometry, const RimEndSizes& sizes,
                             VolumeMesher mesher = VolumeMesher::delaunay);
} // namespace rollcheck::fem
