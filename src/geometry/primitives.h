#pragma once
// Reference bodies. Sizes in metres; each raises InputError for a non-finite
// or non-positive size.
#include "geometry/surface_mesh.h"

namespace rollcheck::geometry
{
/// Closed cylinder about z, z in [-h/2, h/2], `sections` sides, caps fanned
/// from a centre vertex (the layout of trimesh.creation.cylinder).
SurfaceMesh cylinder(double radius, double height, int sections);
/// Icosahedron subdivided `subdivisions` times, vertices projected to the sphere.
SurfaceMesh icosphere(double radius, int subdivisions);
/// Latitude-longitude sphere with poles, n_lat bands and n_lon sectors.
SurfaceMesh uv_sphere(double radius, int n_lat, int n_lon);
/// Closed hemisphere z <= 0 (flat disc on top), n_lat bands, n_lon sectors.
SurfaceMesh hemisphere(double radius, int n_lat, int n_lon);
} // namespace rollcheck::geometry
