#pragma once
// The schema the case-file and option fuzzers resolve against: one parameter
// of every kind (a real with a range and a scale, integers of two widths, one
// of them 0-or-a-range, a flag, free text, a path, a choice) and a ratio cap.
#include "io/bound_schema.h"
#include <cstdint>
#include <string>

namespace rollcheck::fuzz
{
enum class Shape
{
  disc,
  ring
};

struct Settings
{
  double radius_m = 1.0;
  double angle_rad = 0.5;
  int points = 400;
  std::uint8_t level = 2;
  int threads = 0;
  bool verbose = false;
  std::string out;
  std::string mesh_file;
  Shape shape = Shape::disc;
};

inline const io::BoundSchema<Settings>& schema()
{
  using namespace rollcheck::io;
  static const BoundSchema<Settings> s = [] {
    BoundSchema<Settings> b("fuzz");
    b.real("radius_m", "--radius", &Settings::radius_m, "m", "radius", positive)
        .real("angle_deg", "--angle", &Settings::angle_rad, "deg", "angle", Bounds{-90, 90}, 3.141592653589793 / 180)
        .integer("points", "--points", &Settings::points, "", "samples", Bounds{3, 1e9})
        .integer("level", "--level", &Settings::level, "", "refinement level")
        .integer("threads", "--threads", &Settings::threads, "", "threads", thread_count)
        .flag("verbose", "--verbose", &Settings::verbose, "verbose")
        .text("out", "--out", &Settings::out, "output file")
        .path("mesh_file", "--mesh", &Settings::mesh_file, "mesh file")
        .choice("shape", "--shape", &Settings::shape, "shape", {{"disc", Shape::disc}, {"ring", Shape::ring}})
        .ratio_cap("points", "radius_m", 1e12, "points per metre");
    return b;
  }();
  return s;
}
} // namespace rollcheck::fuzz
