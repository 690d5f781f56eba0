#pragma once
// Layer: geometry. Owns the bodies (two-circle rollers, oloid, cylinder,
// spheres), triangle surface meshes and their checks, mass properties, discrete
// curvatures, gmsh volume meshes of a body, and the surface a finished part
// presents to the ground near a rim: the lower surface of the hull of two
// circles (two_circle_hull_height.h) and its rounding by a rolling ball
// (rolling_ball_opening.h). Knows nothing of rolling,
// contact or FEM; every other layer builds on it.
#include "core/error.h"
#include "geometry/surface_mesh.h"
