#pragma once
// The stress history of one point of a body under one rolling pass of a line
// contact: a point at depth z sees the closed-form field
// (subsurface_line_contact.h) at every x as the contact rolls over it, and a
// fatigue criterion turns that history into one stress, over p0, per depth:
//
//  - orthogonal shear: the amplitude of tau_xz, max_x |tau_xz| (half its
//    range, the field being odd in x): Lundberg-Palmgren's tau_0, 0.250 p0
//    at z = 0.5 b (G. Lundberg, A. Palmgren, Acta Polytechnica, Mech. Eng.
//    Series 1(3), 1947; 2(4), 1952);
//  - largest shear: max_x of the in-plane principal shear, 0.300 p0 at
//    z = 0.786 b (the 3D Tresca shear would add sigma_y, which at the
//    surface leaves 0.2 p0 and makes the depth-weighted life integrals
//    diverge; the in-plane shear is the classical one);
//  - Dang Van: max_x (tau_meso(x) + alpha p_h(x)), tau_meso the Tresca shear
//    of the deviator less its shakedown centre, the centre approximated by
//    the mid-range of each deviator component over the pass, p_h the mean
//    stress (K. Dang Van, B. Griveau, O. Message, "On a new multiaxial
//    fatigue limit criterion", in: Biaxial and Multiaxial Fatigue, EGF 3,
//    1989, 479-496; for rolling contact M. Ciavarella, F. Monno, G. Demelio,
//    Int. J. Fatigue 28, 2006, 852-863).
//
// Each maximum over x is taken on a grid of 801 points over [-4 b, 4 b]
// refined by golden-section search about the best grid point.
#include <vector>

namespace rollcheck::contact
{
enum class FatigueCriterion
{
  orthogonal_shear,
  largest_shear,
  dang_van
};

struct PassStress
{
  double value_over_p0 = 0; ///< the criterion's stress over p0
  double x_over_b = 0;      ///< where along the pass it is reached
};

/// The criterion of one pass at depth z / b > 0 (nu the body's Poisson
/// ratio, alpha Dang Van's hydrostatic coefficient, used by dang_van only).
PassStress pass_stress(FatigueCriterion criterion, double z_over_b, double poisson_ratio, double dang_van_alpha);

/// The criterion's largest value over depth (golden section about the best
/// of 400 depths in (0, 3 b]) and its depth.
struct DepthExtremum
{
  double value_over_p0 = 0;
  double z_over_b = 0;
  double x_over_b = 0;
};
DepthExtremum largest_over_depth(FatigueCriterion criterion, double poisson_ratio, double dang_van_alpha);
} // namespace rollcheck::contact
