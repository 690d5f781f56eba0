// The [[check]] tables of case files (io/case_checks.h): parsed, validated,
// and evaluated against a scene's summary.
#include "core/error.h"
#include "io/case_checks.h"
#include "io/parameters.h"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rollcheck;

namespace
{
fs::path case_file(const std::string& name, const std::string& text)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / ("case_checks_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

const std::string scene = "[scene]\nkind = \"hertz\"\n";
} // namespace

TEST(CaseChecks, ParsedAndEvaluated)
{
  const io::CaseFile file = io::read_case_file(case_file("ok.toml", scene + R"(
[[check]]
pointer = "/p0_error"
max_abs = 0.003
reference = "Hertz p0"
[[check]]
pointer = "/area_m2"
value = 12.566370614359172
rel_tol = 0.001
reference = "4 pi r^2"
[[check]]
pointer = "/apex_pressure_converged"
expect = false
reference = "singular apex"
[[check]]
pointer = "/levels/0/dofs"
max_abs = 10
reference = "a missing key fails"
)"));
  ASSERT_EQ(file.checks.size(), 4u);
  const nlohmann::json summary = {{"p0_error", -0.0029}, {"area_m2", 12.57}, {"apex_pressure_converged", false}};
  const auto outcomes = io::evaluate_checks(file.checks, summary);
  EXPECT_TRUE(outcomes[0].passed);
  EXPECT_TRUE(outcomes[1].passed);  // 12.57 is within 0.1 % of 4 pi
  EXPECT_TRUE(outcomes[2].passed);
  EXPECT_FALSE(outcomes[3].passed);
  EXPECT_EQ(outcomes[3].measured, "missing");

  const nlohmann::json broken = {{"p0_error", 0.0031}, {"area_m2", 12.6}, {"apex_pressure_converged", true}};
  for (const auto& o : io::evaluate_checks(file.checks, broken))
    EXPECT_FALSE(o.passed) << o.check.pointer;
  const nlohmann::json wrong_type = {{"p0_error", "small"}};
  EXPECT_FALSE(io::evaluate_checks({file.checks[0]}, wrong_type)[0].passed);
}

TEST(CaseChecks, MalformedChecksNameTheFileAndCheck)
{
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"no_pointer", "[[check]]\nmax_abs = 1\nreference = \"r\"\n"},
      {"no_reference", "[[check]]\npointer = \"/a\"\nmax_abs = 1\n"},
      {"two_criteria", "[[check]]\npointer = \"/a\"\nmax_abs = 1\nexpect = true\nreference = \"r\"\n"},
      {"no_tolerance", "[[check]]\npointer = \"/a\"\nvalue = 2\nreference = \"r\"\n"},
      {"negative", "[[check]]\npointer = \"/a\"\nmax_abs = -1\nreference = \"r\"\n"},
      {"unknown_key", "[[check]]\npointer = \"/a\"\nmax_abs = 1\nreference = \"r\"\ntolerance = 2\n"},
      {"not_array", "check = 3\n"},
  };
  for (const auto& [name, text] : bad)
  {
    // A top-level key must come before the first table.
    const fs::path path = case_file(name + ".toml", name == "not_array" ? text + scene : scene + text);
    try
    {
      io::read_case_file(path);
      ADD_FAILURE() << name << " was accepted";
    }
    catch (const InputError& e)
    {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}
