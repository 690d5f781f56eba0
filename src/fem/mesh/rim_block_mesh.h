#pragma once
// The rim end on a block (build_rim_block_mesh,
// fem/scenes/rim_end_contact.h with the steel counter-face), built with the
// gmsh C++ API (OpenCASCADE) on rank 0 and distributed by DOLFINx.
//
// Geometry: the body above z = 0 as build_rim_end_mesh's
// (fem/mesh/rim_end_mesh.h, flat sheet), and the block x in [-L, H],
// y in [0, H], z in [-H, 0] below, meshed together (their shared face
// conforming; each volume tetrahedralised alone on that surface mesh) as two
// separate bodies: each interface node has a twin of the block's at the same
// place (PenaltyContact::set_node_pairs). A rounded edge's fillet leaves the
// interface at x = -x_t and lifts off the block's top, which stays one flat
// face: conforming with the body up to x = -x_t, free beyond it.
//
// Grading: the body's (rim_end_element_size), the block graded under the
// fillet's start as the body is (the sizes mirrored in z = 0), for the mortar
// pairs there.
//
// Tags (SceneMesh, Model::solid conventions): top, the body's top z = H and
// the block's bottom z = -H; symmetry_x, x = -L, and symmetry_y, y = 0,
// through both bodies; contact, the body's facets on the interface and its
// fillet (not the side planes y = 0, H). Symmetry multiplicity 2.
#include "fem/mesh/rim_end_mesh.h"

namespace rollcheck::fem
{
/// InputError unless the sheet is flat. The volumes tetrahedralised by `mesher`.
SceneMesh build_rim_block_mesh(MPI_Comm comm, const RimEndGeometry& geometry, const RimEndSizes& sizes,
                               VolumeMesher mesher = VolumeMesher::delaunay);
} // namespace rollcheck::fem
