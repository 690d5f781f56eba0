#pragma once
// The scene meshes: one gmsh builder per scene, each built on rank 0 and
// distributed by DOLFINx, graded towards the contact, returning a SceneMesh
// (fem/mesh/scene_facets.h) with the boundary parts its solver needs. Each
// builder's header states its geometry, its grading and its tags:
//
// | builder | header | scene |
// |---|---|---|
// | build_scene_mesh | fem/mesh/hertz_mesh.h | Hertz: quarter disc (axisymmetric, plane strain), quarter hemisphere (solid) |
// | build_crease_mesh | fem/mesh/crease_mesh.h | a crease's half section, plane strain |
// | build_slab_mesh | fem/mesh/slab_mesh.h | the slab of a contact ruling, the plane-strain section extruded |
// | build_rim_end_mesh | fem/mesh/rim_end_mesh.h | one end of a ruling at the body's rim, sharp or filleted |
// | build_square_end_grid_mesh | fem/mesh/square_end_grid_mesh.h | the sharp square end on a structured grid, without gmsh |
// | build_rim_end_extruded_mesh | fem/mesh/rim_end_extruded_mesh.h | the rim end's section meshed in 2D and extruded along the edge |
// | build_rim_block_mesh | fem/mesh/rim_block_mesh.h | the rim end on an elastic block, twins along the interface |
// | build_line_block_mesh | fem/mesh/line_block_mesh.h | two bodies in plane strain, twins along the interface |
//
// Frame: z is vertical (the second coordinate in 2D), the rigid plane or the
// interface is z = 0, the body touches it first at the origin. The gmsh
// pieces the builders share are fem/mesh/gmsh_scene.h and
// fem/mesh/scene_parts.h; the whole body's mesh is fem/mesh/whole_body_mesh.h.
#include "fem/mesh/crease_mesh.h"
#include "fem/mesh/hertz_mesh.h"
#include "fem/mesh/line_block_mesh.h"
#include "fem/mesh/mesh_grading.h"
#include "fem/mesh/rim_block_mesh.h"
#include "fem/mesh/rim_end_mesh.h"
#include "fem/mesh/scene_facets.h"
#include "fem/mesh/slab_mesh.h"
#include "fem/mesh/square_end_grid_mesh.h"
#include "fem/model.h"
#include <dolfinx/mesh/Mesh.h>
#include <array>
#include <memory>
#include <numbers>
#include <span>
#include <mpi.h>
#include <vector>
