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
// - slab (build_slab_mesh): the neighbourhood of a contact ruling of length L
//   along x in [0, L], the y >= 0 half by symmetry: the quarter disc of the
//   plane-strain scene, of radius R(x) = R_0 + (R_L - R_0) x / L in each
//   section x = const, stacked along the ruling. It is a cone (a cylinder if
//   R_0 = R_L) touching z = 0 along the ruling, whose sections across the
//   ruling are exactly the slices of fem/scenes/slice_contact.h. Its end faces are
//   free; they are the planes x = 0 and x = L, meeting the curved surface at a
//   right-angled edge, or, with an overhang t, sheared so that the end face
//   leans out by t from the vertical (an edge of interior angle 90 deg + t):
//   x = a + z s(a), s linear from -tan t_0 at a = 0 to tan t_L at a = L.
// - crease (build_crease_mesh): a crease in contact, in plane strain: the half
//   x >= 0 (symmetry about x = 0) of a body whose lower surface is the
//   straight face z = x tan(beta) from the apex (0, 0) to x = W, closed by the
//   side x = W and the top z = H. Mirrored, the surface has a kink of
//   180 deg - 2 beta at the apex, which touches the plane first.
//
// - rim end (build_rim_end_mesh): the neighbourhood of one end of a loaded
//   ruling, the y >= 0 half by symmetry. The ruling runs along x and ends at
//   the origin, on the body's rim (the edge, along y). The contacting sheet is
//   the cylinder of radius R about (x, 0, R) (its curvature across the
//   ruling); beyond the edge the other face is the plane through the y axis
//   at the interior angle a from the sheet, measured through the body in the
//   ruling's vertical plane (90 deg: a square end, the face x = 0; below, an
//   acute rim whose other face leans back over the sheet; towards
//   180 deg the other face rises gently beyond x = 0). The block is cut at
//   x = -L (the far side, a plane of symmetry: plane strain), x = H (beyond
//   the edge), y = H and z = H (the loaded top); the edge may be rounded
//   with a fillet of radius r_e (OpenCASCADE).
//
// Grading: element size h(d) = min(h_far, h_c + g max(0, d - r_fine)) with d
// the distance from the first point of contact (gmsh Distance + Threshold
// fields, linear in between); see MeshGrading. The slab is the plane-strain
// section meshed at unit radius and extruded in layers (gmsh structured
// extrusion, each prism split into tetrahedra), then scaled by R(x).
#include "fem/mesh/mesh_grading.h"
#include "fem/model.h"
#include <dolfinx/mesh/Mesh.h>
#include <array>
#include <memory>
#include <numbers>
#include <span>
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
  /// Symmetry planes: x = 0 (the Hertz scenes; the axis in the axisymmetric
  /// one) and y = 0 (solid and slab).
  std::vector<std::int32_t> symmetry_x_facets;
  std::vector<std::int32_t> symmetry_y_facets;
  /// The model covers 1 / multiplicity of the body (plane strain 2, solid 4).
  int symmetry_multiplicity = 1;
  double wall_s = 0; ///< gmsh and mesh distribution
};

SceneMesh build_scene_mesh(MPI_Comm comm, Model model, double radius_m, const MeshGrading& grading);

/// The unit outward normals' z components of the given boundary facets (3D,
/// triangles): outward is away from the midpoint of the facet's cell.
std::vector<double> outward_normal_z(const dolfinx::mesh::Mesh& mesh, std::span<const std::int32_t> facets);

struct SlabGeometry
{
  double length_m = 0;        ///< L, along the ruling
  double start_radius_m = 0;  ///< R_0, at x = 0
  double end_radius_m = 0;    ///< R_L, at x = L
  /// Layer boundaries along the ruling as fractions of L, increasing, ending at 1.
  std::vector<double> layer_fractions;
  /// Lean of the end faces at x = 0 and x = L from the vertical, outwards
  /// positive, within +-60 deg.
  std::array<double, 2> end_overhang_rad{0.0, 0.0};
};

/// The position a along the ruling of a point x of the slab (the inverse of
/// its shear; x[0] itself without overhang).
double slab_along(const SlabGeometry& slab, const double* x);

struct CreaseGeometry
{
  double width_m = 0;          ///< W
  double height_m = 0;         ///< H, above the apex
  double face_angle_rad = 0;   ///< beta, between the face and the plane, in (0, pi / 4]
};

/// Model::plane_strain conventions (the vertical is the second coordinate);
/// symmetry multiplicity 2.
SceneMesh build_crease_mesh(MPI_Comm comm, const CreaseGeometry& crease, const MeshGrading& grading);

/// The largest fillet against the rim end's block, r_e / H: the fillet (at
/// most 1.5 r_e high, at 60 deg) inside the block with room below it. Whether
/// a block is deep enough for the end's pressure is a question of the end:
/// docs/rims.md, "The block's depth" (an acute rounded end's ratio still
/// falls between 4 and 10.5 r_e).
inline constexpr double largest_edge_radius_over_depth = 0.25;

struct RimEndGeometry
{
  double radius_m = 0;           ///< R, of the contacting sheet across the ruling
  double interior_angle_rad = 0; ///< a, in [60, 180) deg
  double edge_radius_m = 0;      ///< r_e of the fillet; 0: a sharp edge
  double depth_m = 0;            ///< H: the block's height and half-width (R >= H for the cylinder sheet)
  double length_m = 0;           ///< L: contact modelled from the far side x = -L to the edge
  /// The sheet flattened onto z = 0 (its height, R - sqrt(R^2 - y^2), then
  /// belongs in the contact's initial gap: PenaltyContact::set_initial_gap).
  /// OpenCASCADE's cylinder surface of R >> H is too thin in its parameters
  /// for gmsh to mesh (R / H = 3400 failed); flattened, the geometry errs by
  /// H^2 / (2 R) at y = H, far from the contact.
  bool flat_sheet = false;
};

/// Element size min(far, edge + growth d_edge, contact + growth d_strip),
/// d_edge the distance from the band |x - edge_x_m| <= edge_band_m on z = 0
/// for y < edge_zone_m (the sharp edge at x = 0 with no band, or where a
/// fillet leaves the sheet with the band its peak lies in), d_strip from the
/// strip y < contact_zone_m along the ruling.
struct RimEndSizes
{
  double edge_m = 0, edge_zone_m = 0, edge_x_m = 0, edge_band_m = 0;
  double contact_m = 0, contact_zone_m = 0;
  double growth = 0.3;
  double far_m = 0;
};

/// The size at the point x (m) of the rim end scene.
double rim_end_element_size(const RimEndSizes& sizes, const double* x);

/// How far from the sharp edge, along the sheet, a fillet of radius r_e
/// leaves it (m): tangent to both faces of the interior angle a, x_t = r_e
/// tan((180 deg - a) / 2) (above r_e for an acute rim).
double fillet_start_distance(double edge_radius_m, double interior_angle_rad);

/// Model::solid conventions, symmetry_x the far side; symmetry multiplicity
/// 2. The contact facets are every face but the block's planes (the sheet,
/// the fillet, the other face). InputError for a geometry outside the
/// ranges above.
SceneMesh build_rim_end_mesh(MPI_Comm comm, const RimEndGeometry& geometry, const RimEndSizes& sizes);

/// The largest |a - 90 deg| of build_square_end_grid_mesh: 15 deg, near-square
/// ends (the oloid's at its symmetric orientations lean 3 deg), where the
/// sheared boxes' Kuhn tetrahedra stay well shaped.
inline constexpr double max_grid_end_lean_rad = std::numbers::pi / 12;

/// The sharp square end (a = 90 deg) with the flat sheet, as
/// build_rim_end_mesh's block x in [-L, 0], y and z in [0, H], on a
/// structured grid of tetrahedra built without gmsh: an independent
/// discretisation of that scene. A near-square end (|a - 90 deg| <=
/// max_grid_end_lean_rad) is the same grid sheared, x -> x + z tan(a - 90 deg)
/// (1 + x / L): its end face leans as the other face, its far side stays. The grid's nodes are the tensor product of
/// 1D spacings h(d) = min(far, h_0 + growth d) from the edge (x and z, h_0 =
/// edge_m) and from the strip (y, contact_m within contact_zone_m), each box
/// cut into Kuhn's six tetrahedra. Its elements at the edge are h_e across
/// it and contact_m along it. Tags as build_rim_end_mesh's. InputError for
/// any other end.
SceneMesh build_square_end_grid_mesh(MPI_Comm comm, const RimEndGeometry& geometry, const RimEndSizes& sizes);

/// The rim end (flat sheet) on a block: the body above z = 0 as
/// build_rim_end_mesh's, and the block x in [-L, H], y in [0, H], z in
/// [-H, 0] below, meshed together (their shared face conforming; each
/// volume tetrahedralised alone on that surface mesh) as two separate
/// bodies: each interface node has a twin of the block's at the same place
/// (PenaltyContact::set_node_pairs). Top facets: the body's top
/// z = H and the block's bottom z = -H; symmetry planes through both; the
/// contact facets are the body's on the interface and its fillet. A rounded
/// edge's fillet leaves the interface at x = -x_t and lifts off the block's
/// top, which stays one flat face: conforming with the body up to x = -x_t,
/// free beyond it and graded under the fillet's start as the body is (the
/// sizes mirrored in z = 0), for the mortar pairs there.
SceneMesh build_rim_block_mesh(MPI_Comm comm, const RimEndGeometry& geometry, const RimEndSizes& sizes);

/// Two elastic bodies pressed together in plane strain, for line Hertz
/// between them: the upper body x in [0, W], y in [0, W] and the lower
/// x in [0, W], y in [-W, 0] (the x >= 0 half by symmetry), meshed together
/// as twins along y = 0 (as build_rim_block_mesh), graded about the origin.
/// Top facets y = W and y = -W; symmetry x = 0; contact facets the upper
/// body's on y = 0.
SceneMesh build_line_block_mesh(MPI_Comm comm, double size_m, const MeshGrading& grading);

/// `section_grading` in units of the local radius (the section at unit
/// radius). Model::solid conventions; symmetry multiplicity 2.
SceneMesh build_slab_mesh(MPI_Comm comm, const SlabGeometry& slab, const MeshGrading& section_grading);
} // namespace rollcheck::fem
