// Fuzzes the command-line path of a scene's options: the input's lines are
// the arguments after the subcommand, parsed by CLI11 with the options of
// io::SchemaOptions over the schema of fuzz_schema.h, then applied
// (Parameters::set: types, ranges, empty values) and bound (ratio caps). Bad
// input must raise CLI::ParseError or InputError; any other exception or
// sanitizer report is a finding.
#include "core/error.h"
#include "fuzz_schema.h"
#include <CLI/CLI.hpp>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> args{"fuzz"};
  std::istringstream lines{std::string(reinterpret_cast<const char*>(data), size)};
  for (std::string line; std::getline(lines, line);)
    args.push_back(line);
  if (args.size() > 64)
    return 0;
  CLI::App app{"fuzz"};
  const rollcheck::io::SchemaOptions options(&app, rollcheck::fuzz::schema().schema());
  std::vector<const char*> argv;
  for (const std::string& a : args)
    argv.push_back(a.c_str());
  try
  {
    app.parse(static_cast<int>(argv.size()), argv.data());
    const rollcheck::io::Parameters params = options.apply();
    rollcheck::fuzz::schema().bind(params);
    params.to_json().dump();
  }
  catch (const CLI::ParseError&)
  {
  }
  catch (const rollcheck::InputError&)
  {
  }
  return 0;
}
