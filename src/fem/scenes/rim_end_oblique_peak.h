#pragma once
// The end peak of a rounded edge crossing the ruling obliquely
// (fem/scenes/rim_end_contact.h, RimEndSettings::crossing_angle_rad below
// 90 deg with edge_radius_m > 0): the largest contact pressure near the
// fillet, wherever across the ruling it lies.
//
// A square end's peak lies on the ruling's centre line y = 0 by symmetry,
// and is read there (the largest centre-line pressure near the edge, each
// node the mean over +-w along the ruling, w = min(b / 4, s / 2), s the
// fillet's boundary layer). An oblique edge has no such symmetry: the fillet
// leaves the sheet along the line x' = -x_t, x' = x sin c - y cos c the
// distance beyond the edge along its normal in the contact plane
// (fem/mesh/oblique_end_angle.h oblique_edge_frame), x_t =
// fillet_start_distance(r_e, D) at the dihedral D, and the contact strip
// |y| <= b crosses it at the angle c. So each contact node near the edge
// (x' in (-(2 b + max(r_e, x_t)), r_e], |y| <= 1.5 b: the square end's zone
// along the ruling, the edge's zone of fine elements across it) is read as
// the mean of the nodes within +-w of it along the edge's normal, as the
// square end's, and within +-b / 8 along the edge, where the pressure
// varies on the scale b (across the line-Hertz profile sqrt(1 - y^2 / b^2)
// that mean lies 0.26 % below the centre's), and the largest such mean is
// the end's peak.
#include "fem/nodal_fields.h"
#include "fem/scenes/rim_end_contact.h"
#include <span>

namespace rollcheck::fem
{
struct ObliqueEndPeak
{
  double pressure_pa = 0;
  double x_m = 0, y_m = 0; ///< the node it is read about
};

/// The peak over the contact face's nodes `nodes` (every rank's), for line
/// Hertz's b, the fillet's radius r_e, its start x_t (along the edge's
/// normal), its boundary layer s and the crossing angle c. ComputationError
/// if no node near the edge carries pressure.
ObliqueEndPeak oblique_end_peak(std::span<const SurfacePressureNode> nodes, double half_width_m, double edge_radius_m,
                                double fillet_start_m, double boundary_layer_m, double crossing_angle_rad);

/// The level's end peak (end_peak_pa, its x and y) from the contact face
/// `nodes` by oblique_end_peak, with the study's b, r_e, x_t, s and c.
void read_oblique_end_peak(const RimEndStudy& study, std::span<const SurfacePressureNode> nodes, RimEndLevel& level);
} // namespace rollcheck::fem
