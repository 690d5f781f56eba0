#pragma once
// The stress singularity at a body's sharp edge pressed on an ELASTIC block:
// the companion of edge_on_rigid_plane_exponent (contact/wedge_exponent.h).
// Body 1, a linear-elastic wedge of interior angle theta in (0, pi] (E1, nu1),
// touches with one face, frictionlessly and without separation near the
// apex, the flat surface of an elastic half-plane (E2, nu2); the wedge's other
// face and the block's surface beyond the apex are free of traction. Plane
// strain. Near the apex the stresses grow as r^(lambda - 1), lambda the least
// root in (0, 1) of (the problem of Dundurs and Lee, "Stress concentration at
// a sharp edge in contact problems", J. Elasticity 2, 109-112, 1972; the
// equation as derived below)
//     (1 - alpha) (sin 2 lambda theta + lambda sin 2 theta) sin lambda pi
//   - 2 (1 + alpha) (lambda^2 sin^2 theta - sin^2 lambda theta) cos lambda pi = 0,
// with Dundurs' alpha = (E1* - E2*) / (E1* + E2*), E* = E / (1 - nu^2).
// Derivation (Williams' Airy function r^(lambda+1) [A cos (lambda+1) phi +
// B sin (lambda+1) phi + C cos (lambda-1) phi + D sin (lambda-1) phi] in each
// body, the wedge on 0 <= phi <= theta, the block on -pi <= phi <= 0): a wedge
// whose face phi = 0 carries the compressive pressure p r^(lambda-1) and no
// shear, its other face free, moves that face along its inward normal by
//     u = p r^lambda (kappa + 1) / (8 mu lambda) S / Q,
//     S = sin 2 lambda theta + lambda sin 2 theta,  Q = lambda^2 sin^2 theta - sin^2 lambda theta,
// (kappa = 3 - 4 nu, (kappa + 1) / (8 mu) = 1 / E*). The block is the mirrored
// wedge of angle pi, S / Q = -2 cot lambda pi; the inward normals being
// opposite, continuity of u_y makes the two u sum to zero:
// S / (Q E1*) = 2 cot(lambda pi) / E2*, the equation above. That is the full
// problem's 8 x 8 determinant (4 unknowns a body, 8 conditions) reduced by
// solving each body for its face pressure, possible in (0, 1) for theta <= pi:
// Q = 0 is the free-free wedge of angle theta, with roots in (0, 1) only for
// theta > pi. (tests/contact/test_edge_on_elastic_block_exponent.cpp finds the roots
// of the 8 x 8 determinant independently, with complex potentials.)
// S = 0 is Williams' free-free wedge of 2 theta.
// The result depends on the materials only through Dundurs' alpha, not on
// beta: both faces carry no shear, and the normal displacement gradient of a
// shear-free face is (kappa + 1) / (2 mu) Im phi'(z), phi Kolosov-
// Muskhelishvili's potential, so each body enters only by (kappa + 1) / mu =
// 8 / E*. (With friction beta enters: Gdoutos and Theocaris 1975; M. Comninou,
// "Stress singularity at a sharp edge in contact problems with friction", ZAMP
// 27, 1976. Bogy, J. Appl. Mech. 38, 377-386, 1971, treats bonded wedges.)
// Limits: alpha = -1 (rigid block) gives Williams' free-free wedge of 2 theta,
// i.e. edge_on_rigid_plane_exponent(theta); alpha = +1 (rigid body) gives
// lambda = 1/2 for every theta, the flat punch's edge. (A sweep of theta and
// alpha found never more than one root in (0, 1).) The root leaves lambda = 1
// where (1 + alpha) (sin theta - theta cos theta) = (1 - alpha) pi cos theta:
// the edge is singular for every theta > 90 deg (alpha > -1) and, below 90 deg,
// for tan theta > theta + pi (1 - alpha) / (1 + alpha): for like materials
// (alpha = 0) from theta = 77.45 deg on, so the square (90 deg) rim of a steel
// roller on a steel block is singular (lambda = 0.7740) where the rigid plane
// is not. At theta = pi (no edge: two half-planes touching along a half-line,
// free along the other) lambda = 1/2 for all materials, the mode-I crack field,
// as for edge_on_rigid_plane_exponent(pi); it is an eigen-solution the
// contact's load need not excite (a smooth contact's edge moves until its
// coefficient vanishes), but it is what the eigenproblem admits.
namespace rollcheck::contact
{
/// Dundurs' alpha = (E1* - E2*) / (E1* + E2*) in plane strain, E* = E / (1 - nu^2),
/// body 1 the edged body, body 2 the block. InputError as for edge_on_elastic_block_exponent.
double dundurs_alpha_plane_strain(double youngs_modulus_body_pa, double poisson_ratio_body,
                                  double youngs_modulus_block_pa, double poisson_ratio_block);

/// lambda - 1 for an edge of interior angle `interior_angle_rad` in (0, pi]
/// on an elastic block, given Dundurs' `alpha` in [-1, 1] (-1: rigid block,
/// +1: rigid body): negative where the apex is singular, 0 where the
/// equation has no root in (0, 1). InputError outside those ranges or for NaN.
double edge_on_elastic_block_exponent_for_alpha(double interior_angle_rad, double alpha);

/// lambda - 1 for an edge of interior angle `interior_angle_rad` in (0, pi] of
/// a body (E, nu) on a block (E, nu), plane strain, frictionless. InputError
/// for an angle outside (0, pi], a modulus not positive and finite, a Poisson
/// ratio outside [0, 0.5), or NaN.
double edge_on_elastic_block_exponent(double interior_angle_rad, double youngs_modulus_body_pa,
                                      double poisson_ratio_body, double youngs_modulus_block_pa,
                                      double poisson_ratio_block);
} // namespace rollcheck::contact
