#pragma once
// Layer: contact. Owns the physics evaluated on a rolling trajectory: Hertz
// point-contact pressure per face from discrete curvatures (SDS and the peak
// pressure statistics), fatigue damage by Basquin's law with Miner's rule and an
// endurance limit (FDS), frictional heat mu p v_slide (TDS), Archard wear
// volume and depth (WDS_vol, WDS_depth), each a distribution score on the
// oracle layer's template; and the analytic Hertz formulas (hertz.h). Every
// material and load parameter is a named option whose default is the
// preprint's value. Also the contact loci of sampled orientations of bodies
// that are hulls of circles (contact_locus.h: support set, load, creases) and
// the rims at a ruling's ends (rim_overhang.h; their dihedral angles,
// rim_dihedral_angle.h), which the FEM layer is given,
// and the stress singularity of a rim's edge on the rigid plane
// (wedge_exponent.h) or on a block of elastic material
// (edge_on_elastic_block_exponent.h), and frictionless contact of two
// half-spaces across a gap on a grid (half_space_contact.h: boundary
// elements by FFT), and the rounded ruling end solved on it (rounded_end.h:
// its surface, the line load along the ruling, the window and whole-ruling
// levels); the load ratio of a line contact (load_ratio.h); and the
// resolution-free scores of a rolling loop on the body's exact surface
// (continuum_loop_scores.h). Knows nothing of how the trajectory was produced.
#include "contact/ball_rounded_surface.h"
#include "contact/contact_locus.h"
#include "contact/contact_parameters.h"
#include "contact/continuum_loop_scores.h"
#include "contact/edge_on_elastic_block_exponent.h"
#include "contact/exact_curvature.h"
#include "contact/face_curvature.h"
#include "contact/face_pressure.h"
#include "contact/fatigue.h"
#include "contact/half_space_contact.h"
#include "contact/hertz.h"
#include "contact/line_contact.h"
#include "contact/line_hertz_beyond.h"
#include "contact/load_ratio.h"
#include "contact/rim_dihedral_angle.h"
#include "contact/rim_overhang.h"
#include "contact/rounded_end.h"
#include "contact/rounded_end_level.h"
#include "contact/rounded_end_problem.h"
#include "contact/rounded_end_whole_ruling.h"
#include "contact/rounded_end_window.h"
#include "contact/ruling_end_surface.h"
#include "contact/ruling_line_load.h"
#include "contact/sliding_speed.h"
#include "contact/straight_rim_end.h"
#include "contact/trajectory_scores.h"
#include "contact/wear.h"
#include "contact/wedge_exponent.h"
