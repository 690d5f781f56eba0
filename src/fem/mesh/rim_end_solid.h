#pragma once
// For the rim end's builders (fem/mesh/rim_end_mesh.h, rim_block_mesh.h,
// square_end_grid_mesh.h): the rim end's solid meshed by gmsh, alone or on
// its block, and the scene's planes of symmetry.
#include "fem/mesh/gmsh_raw_mesh.h"
#include "fem/mesh/rim_end_geometry.h"
#include "fem/mesh/scene_parts.h"
#include "fem/mesh/volume_mesher.h"

namespace rollcheck::fem::scene_build
{
/// The rim end built and meshed in units of H (`unit`: its geometry with
/// H = 1), graded by rim_end_element_size, scaled back to metres; with the
/// block x in [-L, H], y in [0, H], z in [-H, 0] below it, fragmented with
/// the body (a conforming shared face), graded as the body mirrored in the
/// interface z = 0. The volumes by `mesher`.
RawMesh mesh_rim_end(const RimEndGeometry& unit, const RimEndSizes& sizes, double H, bool with_block,
                     VolumeMesher mesher);

/// InputError for a geometry outside build_rim_end_mesh's ranges
/// (fem/mesh/rim_end_mesh.h) or sizes that are not positive and finite.
void check_rim_end_input(const RimEndGeometry& geometry, const RimEndSizes& sizes);

/// The block's planes x = -L, x = H, y = 0, y = H and z = H (within 1e-9 H):
/// the rim end's faces that are not its sheet, fillet or other face.
Predicate rim_end_block_planes(double H, double L);

/// The rim end's planes of symmetry: the far side x = -L and y = 0.
SceneParts rim_end_planes(double L, double tol);

/// Tags the rim end alone (fem/mesh/rim_end_mesh.h): its planes of symmetry,
/// the top z = H, and as contact the facets on `curved` off `in_plane` that
/// face the plane; symmetry multiplicity 2, or 1 for an oblique end's
/// `full_width` (both sides of the ruling, no face at y = 0).
void tag_rim_end(SceneMesh& scene, double H, double L, const Predicate& curved, const Predicate& in_plane,
                 bool full_width = false);
} // namespace rollcheck::fem::scene_build
