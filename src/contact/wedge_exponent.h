#pragma once
// The stress singularity at the apex of a linear-elastic wedge whose two
// faces are free of traction, symmetric loading (M. L. Williams, "Stress
// singularities resulting from various boundary conditions in angular corners
// of plates in extension", J. Appl. Mech. 19, 526-528, 1952): near the apex
// the stresses grow as r^(lambda - 1), lambda the least root in (0, 1) of
//     sin(lambda w) + lambda sin(w) = 0,
// w the wedge's full angle. A body's edge of interior angle theta standing on
// a rigid frictionless plane is, mirrored in the plane (the plane is a line
// of symmetry of the mirrored body), the free-free wedge of w = 2 theta: it is
// singular only for theta > 90 deg (an obtuse rim; the square rim of a
// cylinder is not). Known values: w = 360 deg (a crack) lambda = 1/2;
// w = 270 deg lambda = 0.5445; w = 240 deg lambda = 0.6157.
namespace rollcheck::contact
{
/// lambda - 1 for the free-free wedge of full angle `wedge_angle_rad` in
/// (0, 2 pi]: negative where the apex is singular (w > pi), 0 where it is not.
/// InputError outside (0, 2 pi].
double wedge_stress_exponent(double wedge_angle_rad);

/// wedge_stress_exponent(2 theta) for an edge of interior angle theta on a rigid plane.
double edge_on_rigid_plane_exponent(double interior_angle_rad);
} // namespace rollcheck::contact
