// Fuzzes the case-file path of `rollcheck run`: io::read_case_file (its
// bounded read and nesting check before the TOML parser), then
// io::resolve_case against the schema of fuzz_schema.h and BoundSchema::bind. The input is the TOML file up to its first
// NUL byte; each line after it is a `--set key=value` override. Bad input must
// raise InputError; any other exception or sanitizer report is a finding.
#include "core/error.h"
#include "fuzz_input_file.h"
#include "fuzz_schema.h"
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>


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
    const rollcheck::io::Parameters params = rollcheck::io::resolve_case(file, rollcheck::fuzz::schema().schema(), overrides, "fuzz");
    rollcheck::fuzz::schema().bind(params);
    // `rollcheck run` prints the resolved parameters as JSON.
    params.to_json().dump();
  }
  catch (const rollcheck::InputError&)
  {
  }
  return 0;
}
