#pragma once
// Layer: geometry. Owns the bodies (two-circle rollers, oloid, cylinder,
// spheres), triangle surface meshes and their checks, mass properties, discrete
// curvatures, and gmsh volume meshes of a body. Knows nothing of rolling,
// contact or FEM; every other layer builds on it.
#include "core/error.h"
#include "geometry/surface_mesh.h"
