#pragma once
// Hertz stresses of a developable body on the plane: slice-by-slice
// plane-strain line contact along the contact ruling, beside the point-contact
// formula the preprint applies with R = 1 / sqrt(kappa_1 kappa_2).
//
// A developable surface touches the plane along a ruling of length L whose
// radius of normal curvature across it varies linearly, R(s) = (1 - s) R_1 +
// s R_2 (contact/exact_curvature.h), and whose other principal curvature is 0.
// The slicing technique of roller-bearing analysis (T. A. Harris, M. N.
// Kotzalas, "Rolling Bearing Analysis", 5th ed., 2007, ch. 6; ISO/TS 16281)
// treats each slice ds as a plane-strain Hertz contact of a cylinder of radius
// R(s) under the local line load p(s) (contact/hertz.h line_contact,
// K. L. Johnson, "Contact Mechanics", 1985, sec. 4.3):
//   b(s) = sqrt(4 p(s) R(s) / (pi E*)),  p0(s) = 2 p(s) / (pi b(s)) = sqrt(p(s) E* / (pi R(s))).
// The load along the ruling is the normal force N with its centre of pressure
// c from the rolling dynamics, spread by the no-tension linear rule
// (oracle/contact_density.h line_load): linear if 1/3 <= c <= 2/3, otherwise
// triangular over the loaded 3c (or 3(1 - c)). This neglects the elastic
// interaction between slices (valid while b << L) and the end effects of a
// finite line contact.
//
// Point contact with R = 1/sqrt(kappa_1 kappa_2): on a developable surface
// kappa_1 kappa_2 = K = 0 exactly, so R is infinite and the formula gives no
// pressure at all; the preprint's finite radii come from its discrete K, which
// measures the rims' crease (exact_curvature.h), not the surface in contact.
#include "contact/hertz.h"
#include <vector>

namespace rollcheck::contact
{
struct LineContactSlice
{
  double position_m;           ///< of the slice centre along the ruling, from its start
  double radius_m;             ///< R(s)
  double load_n_per_m;         ///< p(s)
  LineHertz hertz;             ///< plane-strain Hertz of the slice (zeros where unloaded)
};

struct SlicedLineContact
{
  std::vector<LineContactSlice> slices;
  double force_n = 0;           ///< sum of p ds, equal to the normal force
  double loaded_length_m = 0;   ///< length of the slices carrying load
  double max_peak_pressure_pa = 0;
  double max_von_mises_pa = 0;
  double max_shear_pa = 0;
};

/// InputError for non-positive force, length, radii, modulus or slice count,
/// or a Poisson ratio outside [0, 0.5).
SlicedLineContact sliced_line_contact(double force_n, double centre_of_pressure, double length_m,
                                      double start_radius_m, double end_radius_m, double effective_modulus_pa,
                                      double poisson_ratio, int slices = 64);

/// R = 1 / sqrt(kappa_1 kappa_2), +infinity when kappa_1 kappa_2 <= 0 (a
/// developable or saddle surface: no point contact).
double point_contact_radius(double kappa_1_per_m, double kappa_2_per_m);
} // namespace rollcheck::contact
