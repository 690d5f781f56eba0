// Fuzzes the case-file path of `rollcheck run`: io::read_case_file, then
// io::resolve_case against a bound schema with one parameter of every kind
// (real with a range and a scale, integers of two widths, flag, free text,
// choice) and BoundSchema::bind. The input is the TOML file up to its first
// NUL byte; each line after it is a `--set key=value` override. Bad input must
// raise InputError; any other exception or sanitizer report is a finding.
#include "core/error.h"
#include "fuzz_input_file.h"
#include "io/bound_schema.h"
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace
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
  bool verbose = false;
  std::string out;
  Shape shape = Shape::disc;
};

const rollcheck::io::BoundSchema<Settings>& schema()
{
  using namespace rollcheck::io;
  static const BoundSchema<Settings> s = [] {
    BoundSchema<Settings> b("fuzz");
    b.real("radius_m", "--radius", &Settings::radius_m, "m", "radius", positive)
        .real("angle_deg", "--angle", &Settings::angle_rad, "deg", "angle", Bounds{-90, 90}, 3.141592653589793 / 180)
        .integer("points", "--points", &Settings::points, "", "samples", Bounds{3, 1e9})
        .integer("level", "--level", &Settings::level, "", "refinement level")
        .flag("verbose", "--verbose", &Settings::verbose, "verbose")
        .text("out", "--out", &Settings::out, "output file")
        .choice("shape", "--shape", &Settings::shape, "shape", {{"disc", Shape::disc}, {"ring", Shape::ring}});
    return b;
  }();
  return s;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = bytes.find('\0');
  std::vector<std::string> overrides;
  if (nul != std::string_view::npos)
  {
    std::istringstream lines{std::string(bytes.substr(nul + 1))};
    for (std::string line; std::getline(lines, line);)
      overrides.push_back(line);
  }
  const auto path = rollcheck::fuzz::write_input_file(bytes.substr(0, nul), ".toml");
  try
  {
    const rollcheck::io::CaseFile file = rollcheck::io::read_case_file(path);
    const rollcheck::io::Parameters params = rollcheck::io::resolve_case(file, schema().schema(), overrides, "fuzz");
    schema().bind(params);
    // `rollcheck run` prints the resolved parameters as JSON.
    params.to_json().dump();
  }
  catch (const rollcheck::InputError&)
  {
  }
  return 0;
}
