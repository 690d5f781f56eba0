#pragma once
// A named body, as a user asks for it, turned into a checked surface mesh.
#include "geometry/surface_mesh.h"
#include "geometry/two_circle_roller.h"
#include <string>

namespace rollcheck::geometry
{
struct BodySpec
{
  /// oloid (true oloid, centre-line family (90, 1, 1)), paper-oloid (the
  /// preprint's (90, 1, 1)), roller, cylinder, sphere (icosphere), uv-sphere,
  /// hemisphere.
  std::string body = "oloid";
  RollerFamily family = RollerFamily::paper; ///< for body = roller
  RollerGenome genome;                       ///< for body = roller
  double radius_m = 1.0;  ///< r1 of rollers, radius of the others (paper: r1 = 1)
  int points = 400;       ///< samples per generating circle (reference: 400 for the oloid)
  double height_m = 2.0;  ///< cylinder height (reference: 2 r)
  int sections = 60;      ///< cylinder sides, UV-sphere sectors (reference: 60)
  int subdivisions = 3;   ///< icosphere subdivisions (reference: 3)
  /// Read the body from this surface mesh (OBJ/STL/PLY/OFF) instead, when set.
  std::string mesh_file;
};

/// Builds (or reads) the body and checks it closed, outward and convex
/// (InputError naming the body or file if not).
SurfaceMesh make_body(const BodySpec& spec);

/// What the body is called in logs and results: the file, the roller with its
/// family and genome, or the body's name.
std::string body_label(const BodySpec& spec);
} // namespace rollcheck::geometry
