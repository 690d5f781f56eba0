#pragma once
// Wing of the study layer (study/life): the stress-volume life integral of
// one surface element under one pass of a line contact, and the constants of
// the life models.
//
// A body survives N stress cycles with probability S where (G. Lundberg,
// A. Palmgren, "Dynamic capacity of rolling bearings", Acta Polytechnica,
// Mech. Eng. Series 1(3), 1947; "Dynamic capacity of roller bearings", 2(4),
// 1952; E. Ioannides, T. A. Harris, "A new fatigue life model for rolling
// bearings", J. Tribology 107, 1985, 367-378)
//     ln(1 / S) = A N^e  integral_V (tau - tau_u)_+^c / z^h dV,
// tau the criterion's stress at a point (contact/subsurface_pass.h), z its
// depth, tau_u the fatigue limit (Ioannides-Harris; tau_u = 0 is
// Lundberg-Palmgren's integral in stress-volume form). Under a pass of
// line contact (half-width b, peak p0) tau = k p0 f(z / b), k the FEM's
// measured ratio to the closed form, so an element dA contributes
//     dA (k p0)^c b^(1 - h) H(tau_u / (k p0)),
//     H(t) = integral_0^inf (f(zeta) - t)_+^c zeta^(-h) dzeta.
// The L10 life (S = 0.9) in passes is (ln(1 / 0.9) / (A I))^(1 / e) for the
// body's integral I; A cancels from a ratio of lives: L_1 / L_2 = (I_2 / I_1)^(1 / e).
//
// Load-life exponent (line contact): p0 and b both grow as sqrt(q), so
// I ~ q^(c / 2) q^((1 - h) / 2) and L ~ F^(-p) with p = (c + 1 - h) / (2 e);
// Lundberg-Palmgren's e = 9/8, c = 31/3, h = 7/3 give p = 4.
//
// Quadrature: f on 2000 depths, uniform in ln(zeta) over [1e-3, 10] (at its
// ends (f^c zeta^-h) is under 1e-5 and 1e-10 of its peak, for both shears);
// H(t) on 400 equal steps of t in [0, max f], the trapezoid rule in ln(zeta),
// interpolated as H^(1/c), which is nearly linear in t up to max f.
#include "contact/subsurface_pass.h"
#include <vector>

namespace rollcheck::study::life
{
/// Bearing-steel constants of the life models (the references above; the
/// fatigue limit from ISO 281:2007's fatigue load limit, a Hertz contact
/// stress of 1500 MPa: tau_u is the criterion's stress at that p0).
struct LifeConstants
{
  double weibull_slope = 9.0 / 8;           ///< e (line contact, Lundberg-Palmgren 1952)
  double stress_exponent = 31.0 / 3;        ///< c
  double depth_exponent = 7.0 / 3;          ///< h
  double fatigue_limit_contact_pa = 1.5e9;  ///< p0 at which tau reaches tau_u (ISO 281:2007)
  double dang_van_alpha = 0.3;              ///< Dang Van's hydrostatic coefficient (a hardened steel's order)
  double poisson_ratio = 0.3;               ///< of the body (steel)
};

/// p = (c + 1 - h) / (2 e).
double derived_load_life_exponent(const LifeConstants& constants);

/// A criterion's depth profile f(zeta) and its integrals H(t).
class DepthIntegrals
{
public:
  DepthIntegrals(contact::FatigueCriterion criterion, const LifeConstants& constants);
  /// f(zeta) by linear interpolation in ln(zeta); 0 outside the table.
  double profile(double zeta) const;
  /// H(t), t >= 0 (c the constants' stress exponent, as constructed); 0 from max f on.
  double integral(double threshold_over_p0, double stress_exponent) const;
  double peak() const { return peak_; }            ///< max f
  double peak_depth() const { return peak_depth_; } ///< its zeta
private:
  std::vector<double> f_;
  std::vector<double> h_;
  double log_lo_ = 0, log_step_ = 0, peak_ = 0, peak_depth_ = 0;
};
} // namespace rollcheck::study::life
