#pragma once
// The load ratio of a line contact, its one nondimensional datum besides
// Poisson's ratio: a cylinder of radius R pressed onto a half-space by the
// line load q is, in small-strain linear elasticity, the same problem at every
// scale once lengths are measured in R and stresses in E*,
//     lambda = q / (E* R),
// with half-width b = R sqrt(4 lambda / pi) and peak p0 = E* sqrt(lambda / pi)
// (K. L. Johnson, "Contact Mechanics", CUP 1985, eqs. 4.43, 4.45). The FEM
// slices are tabulated over it (fem/scenes/slice_scaling.h).

namespace rollcheck::contact
{
/// lambda = q / (E* R).
double load_ratio(double load_n_per_m, double radius_m, double effective_modulus_pa);
} // namespace rollcheck::contact
