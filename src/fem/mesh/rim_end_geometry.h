#pragma once
// The rim end scene's geometry and element sizes (fem/mesh/rim_end_mesh.h has
// the scene and its tags), shared by the builders of the rim end, the rim
// end on a block and the structured grid, and by the solid they cut.

#include <numbers>

namespace rollcheck::fem
{
/// The largest fillet against the rim end's block, r_e / H: the fillet (at
/// most 1.5 r_e high, at 60 deg) inside the block with room below it. Whether
/// a block is deep enough for the end's pressure is a question of the end:
/// docs/results/rim-ends.md#the-blocks-depth (an acute rounded end's ratio still
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
  /// c: the angle in the contact plane between the ruling and the edge
  /// (fem/mesh/oblique_end_angle.h), in (0, 90] deg; 90: the edge square to
  /// the ruling, the y >= 0 half by symmetry. Otherwise interior_angle_rad
  /// stays the section in the ruling's vertical plane, the other face turns
  /// about z with the edge, and the block covers both sides of the ruling
  /// (y in [-H, H]: no plane of symmetry at y = 0) and reaches H beyond the
  /// edge's farthest point, x = H (1 + cot c). A fillet of such an edge is
  /// built on the flat sheet only, its start fillet_start_distance at the
  /// dihedral D along the edge's normal.
  double crossing_angle_rad = std::numbers::pi / 2;
};

/// Element size min(far, edge + growth d_edge, contact + growth d_strip),
/// d_edge the distance from the band |x - edge_x_m| <= edge_band_m on z = 0
/// for y < edge_zone_m (the sharp edge at x = 0 with no band, or where a
/// fillet leaves the sheet with the band its peak lies in), d_strip from the
/// strip y < contact_zone_m along the ruling. An oblique edge
/// (crossing_angle_rad, RimEndGeometry's) has x measured normal to it and y
/// as |y| (fem/mesh/oblique_end_angle.h oblique_edge_frame).
struct RimEndSizes
{
  double edge_m = 0, edge_zone_m = 0, edge_x_m = 0, edge_band_m = 0;
  double contact_m = 0, contact_zone_m = 0;
  double growth = 0.3;
  double far_m = 0;
  double crossing_angle_rad = std::numbers::pi / 2;
};

/// The size at the point x (m) of the rim end scene.
double rim_end_element_size(const RimEndSizes& sizes, const double* x);

/// How far from the sharp edge, along the sheet normal to the edge, a
/// fillet of radius r_e leaves it (m): tangent to both faces of the interior
/// angle a (an oblique edge's dihedral), x_t = r_e tan((180 deg - a) / 2)
/// (above r_e for an acute rim).
double fillet_start_distance(double edge_radius_m, double interior_angle_rad);

} // namespace rollcheck::fem
