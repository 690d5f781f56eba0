#pragma once
// Two families of convex hulls of generating circles. Both start from circle
// C1 of radius r1 in the xz-plane centred at the origin, and circle C2 of
// radius rho r1 centred at (d r1, 0, 0); they differ in how C2's plane is
// turned by theta:
//  - RollerFamily::paper: about the z axis, from the xz-plane (the preprint's
//    R(theta, d, rho) and the reference code's generate_roller). Its
//    (90, 1, 1) member, the preprint's "oloid", is not an oloid: area 12.659
//    for r1 = 1 instead of 4 pi.
//  - RollerFamily::centre_line: about the line of centres (the x axis). Its
//    (90, 1, 1) member is the true oloid (Schatz; Dirnboeck & Stachel 1997):
//    area 4 pi r^2, volume 3.0524185 r^3.
// The reference's n-circle variant (n >= 3 circles at even azimuth, each
// tilted by theta about x, offset radially by d r1) is kept for its search
// grids.
#include "geometry/surface_mesh.h"

namespace rollcheck::geometry
{
enum class RollerFamily
{
  paper,
  centre_line
};

struct RollerGenome
{
  double theta_deg = 90.0; ///< angle between the circle planes (degrees)
  double offset = 1.0;     ///< centre distance d, in units of r1
  double ratio = 1.0;      ///< rho = r2 / r1
  int n_circles = 2;
};

/// Sample points: n_points per generating circle at t = 2 pi k / n_points.
Vertices roller_points(const RollerGenome& genome, RollerFamily family, double r1, int n_points);

/// Convex hull of roller_points, validated closed and convex.
SurfaceMesh two_circle_roller(const RollerGenome& genome, RollerFamily family, double r1, int n_points);
} // namespace rollcheck::geometry
