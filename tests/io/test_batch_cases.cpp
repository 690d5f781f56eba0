// What a batch runs: expansion of its arguments (files, folders, globs) and
// the resolution of each case file against its scene's schema.
#include "core/error.h"
#include "io/batch_cases.h"
#include "io/case_hash.h"
#include <fmt/format.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace rollcheck;
namespace fs = std::filesystem;

namespace
{
fs::path fresh_folder(const std::string& name)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / "batch_cases" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text)
{
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

const io::Schema& demo_schema()
{
  static const io::Schema schema{"demo",
                                 {{"radius_m", "--radius", 1.0, "m", "a length"},
                                  {"points", "--points", std::int64_t{400}, "", "a count"},
                                  {"shape", "--shape", std::string("round"), "", "a choice", {"round", "flat"}},
                                  {"mesh_file", "--mesh", std::string(), "", "an input file"},
                                  {"out", "--out", std::string(), "", "an output file"},
                                  {"mpi_ranks", "--ranks", std::int64_t{1}, "", "processes"}}};
  return schema;
}

const io::FindSchema find_demo = [](const std::string& kind, const std::string& origin) -> const io::Schema& {
  if (kind != "demo")
    throw InputError(origin + ": unknown scene kind '" + kind + "'");
  return demo_schema();
};

std::vector<std::string> names(const std::vector<fs::path>& files)
{
  std::vector<std::string> out;
  for (const fs::path& f : files)
    out.push_back(f.filename().string());
  return out;
}
} // namespace

TEST(BatchCases, FoldersGiveTheirTomlFilesSortedAndEachFileOnce)
{
  const fs::path dir = fresh_folder("expand");
  write(dir / "b.toml", "");
  write(dir / "a.toml", "");
  write(dir / "notes.txt", "");
  write(dir / "sub" / "c.toml", "");
  const std::vector<fs::path> files =
      io::expand_case_arguments({dir.string(), (dir / "a.toml").string(), (dir / "sub" / "*.toml").string()});
  EXPECT_EQ(names(files), (std::vector<std::string>{"a.toml", "b.toml", "c.toml"}));
}

TEST(BatchCases, AnArgumentThatNamesNothingIsAnInputError)
{
  const fs::path dir = fresh_folder("nothing");
  try
  {
    io::expand_case_arguments({(dir / "typo.toml").string()});
    FAIL() << "no error";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("typo.toml"), std::string::npos) << e.what();
  }
  EXPECT_THROW(io::expand_case_arguments({(dir / "*.toml").string()}), InputError);
  EXPECT_THROW(io::expand_case_arguments({dir.string()}), InputError); // a folder without cases
}

TEST(BatchCases, ResolvesDefaultsAndKeysEqualParametersEqually)
{
  const fs::path dir = fresh_folder("resolve");
  write(dir / "one" / "case.toml", "[scene]\nkind = \"demo\"\nradius_m = 2.0\n");
  write(dir / "two" / "case.toml", "[scene]\nkind = \"demo\"\nradius_m = 2\npoints = 400\n");
  write(dir / "other.toml", "[scene]\nkind = \"demo\"\nradius_m = 3.0\nmpi_ranks = 2\n");
  const std::vector<io::BatchCase> cases = io::resolve_batch_cases(
      {dir / "one" / "case.toml", dir / "two" / "case.toml", dir / "other.toml"}, find_demo);
  ASSERT_EQ(cases.size(), 3u);
  for (const io::BatchCase& c : cases)
    EXPECT_TRUE(c.error.empty()) << c.error;
  EXPECT_EQ(cases[0].parameters.at("points"), 400);
  EXPECT_EQ(cases[0].parameters.at("radius_m"), 2.0);
  EXPECT_EQ(cases[0].hash, cases[1].hash); // the default written out or not, 2 or 2.0: one case
  EXPECT_NE(cases[0].hash, cases[2].hash);
  EXPECT_EQ(cases[0].name, "one_case"); // two files named case.toml get distinct store groups
  EXPECT_EQ(cases[1].name, "two_case");
  EXPECT_EQ(cases[2].name, "other");
  EXPECT_EQ(cases[0].mpi_ranks, 1);
  EXPECT_EQ(cases[2].mpi_ranks, 2);
  EXPECT_TRUE(cases[2].file.is_absolute());
}

TEST(BatchCases, ACaseThatCannotBeResolvedKeepsItsMessage)
{
  const fs::path dir = fresh_folder("errors");
  write(dir / "malformed.toml", "[scene\nkind = \"demo\"\n");
  write(dir / "unknown_kind.toml", "[scene]\nkind = \"nope\"\n");
  write(dir / "bad_value.toml", "[scene]\nkind = \"demo\"\nshape = \"square\"\n");
  write(dir / "no_ranks.toml", "[scene]\nkind = \"demo\"\nmpi_ranks = 0\n");
  const std::vector<io::BatchCase> cases = io::resolve_batch_cases(
      {dir / "malformed.toml", dir / "unknown_kind.toml", dir / "bad_value.toml", dir / "no_ranks.toml"}, find_demo);
  const std::vector<std::string> expected = {"malformed TOML", "unknown scene kind 'nope'", "'shape' must be one of",
                                             "'mpi_ranks' must be at least 1"};
  for (std::size_t i = 0; i < cases.size(); ++i)
  {
    EXPECT_NE(cases[i].error.find(expected[i]), std::string::npos) << cases[i].error;
    EXPECT_NE(cases[i].error.find(cases[i].file.filename().string()), std::string::npos) << cases[i].error;
  }
}

TEST(BatchCases, ExistingRelativeInputPathsBecomeAbsoluteOutputsStayRelative)
{
  const fs::path dir = fresh_folder("paths");
  write(dir / "body.obj", "v 0 0 0\n");
  write(dir / "case.toml", "[scene]\nkind = \"demo\"\nmesh_file = \"body.obj\"\nout = \"fields.xdmf\"\n");
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  const std::vector<io::BatchCase> cases = io::resolve_batch_cases({"case.toml"}, find_demo);
  fs::current_path(before);
  ASSERT_TRUE(cases[0].error.empty()) << cases[0].error;
  EXPECT_EQ(cases[0].parameters.at("mesh_file"), (dir / "body.obj").string());
  EXPECT_EQ(cases[0].overrides, std::vector<std::string>{"mesh_file=" + (dir / "body.obj").string()});
  EXPECT_EQ(cases[0].parameters.at("out"), "fields.xdmf");
}

TEST(BatchCases, TheHashCoversTheContentOfEveryInputFile)
{
  // Issue 58 (3): a case whose mesh file was replaced kept its old result.
  const fs::path dir = fresh_folder("input_content");
  write(dir / "body.obj", "v 0 0 0\n");
  write(dir / "case.toml", fmt::format("[scene]\nkind = \"demo\"\nmesh_file = \"{}\"\n", (dir / "body.obj").string()));
  const io::BatchCase before = io::resolve_batch_cases({dir / "case.toml"}, find_demo).at(0);
  ASSERT_TRUE(before.error.empty()) << before.error;
  EXPECT_EQ(before.inputs.at("mesh_file").at("sha256"), io::sha256_hex("v 0 0 0\n"));
  EXPECT_EQ(io::resolve_batch_cases({dir / "case.toml"}, find_demo).at(0).hash, before.hash);
  write(dir / "body.obj", "v 0 0 1\n"); // the same path and parameters, another mesh
  const io::BatchCase after = io::resolve_batch_cases({dir / "case.toml"}, find_demo).at(0);
  EXPECT_EQ(after.parameters, before.parameters);
  EXPECT_NE(after.hash, before.hash);
}
