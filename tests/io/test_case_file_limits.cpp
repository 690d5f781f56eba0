// Case files under hostile input (issue 58) and the rules of issue 59: deep
// nesting refused before the TOML parser recurses, special files refused by
// name, infinite tolerances refused, every bad key named at once, integers
// compared exactly with their bounds, the work budget's ranges and ratio caps,
// and the commented template of a kind.
#include "core/error.h"
#include "io/bound_schema.h"
#include "io/case_template.h"
#include "io/parameters.h"
#include "io/toml_nesting.h"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rollcheck;

namespace
{
fs::path case_file(const std::string& name, const std::string& text)
{
  static const fs::path folder = [] {
    fs::path d = fs::path(ROLLCHECK_TEST_TMP) / ("case_limits_" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
  }();
  std::ofstream(folder / name) << text;
  return folder / name;
}

/// The InputError's message of `run` ("" if none).
template <class Run>
std::string refusal(Run run)
{
  try
  {
    run();
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

struct Toy
{
  std::string mesh_file;
  double radius_m = 1;
  std::int64_t seed = 0;
  double duration_s = 10;
  int threads = 0;
  double dt_s = 0.002;
};

const io::BoundSchema<Toy>& toy_schema()
{
  static const io::BoundSchema<Toy> s = [] {
    io::BoundSchema<Toy> t("toy");
    t.real("radius_m", "--radius", &Toy::radius_m, "m", "Radius", io::positive)
        .real("duration_s", "--duration", &Toy::duration_s, "s", "Duration", io::positive)
        .real("dt_s", "--dt", &Toy::dt_s, "s", "Time step", io::positive)
        .integer("seed", "--seed", &Toy::seed, "", "Seed", io::non_negative)
        .integer("threads", "--threads", &Toy::threads, "", "Threads", io::thread_count)
        .path("mesh_file", "--mesh", &Toy::mesh_file, "Mesh")
        .ratio_cap("duration_s", "dt_s", io::max_rigid_steps, "rigid-body time steps");
    return t;
  }();
  return s;
}

std::string nested_tables(int depth)
{
  std::string header = "[a";
  for (int i = 1; i < depth; ++i)
    header += ".a";
  return "[scene]\nkind = \"toy\"\n" + header + "]\nx = 1\n";
}
} // namespace

TEST(CaseFileLimits, DeepNestingRefusedBeforeParsing)
{
  // 50,000 nested tables or dotted keys overflowed toml++'s recursion (SIGSEGV);
  // 2,000 fit the line cap and are refused by the nesting check, naming the line.
  std::string dotted = "[scene]\nkind = \"toy\"\nb";
  for (int i = 0; i < 2000; ++i)
    dotted += ".b";
  dotted += " = 1\n";
  std::string arrays = "[scene]\nkind = \"toy\"\nc = " + std::string(2000, '[') + std::string(2000, ']') + "\n";
  for (const auto& [name, text] : {std::pair{"tables.toml", nested_tables(2000)}, std::pair{"dotted.toml", dotted},
                                   std::pair{"arrays.toml", arrays}})
  {
    const std::string message = refusal([&] { io::read_case_file(case_file(name, text)); });
    EXPECT_NE(message.find(std::string(name) + "': line 3 nests"), std::string::npos) << message;
  }
}

TEST(CaseFileLimits, NestingCountsNeitherStringsNorNumbers)
{
  // Dots in strings, comments and numbers are not keys.
  const std::string text = "[scene]\nkind = \"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r\" # x.y.z.x.y.z.x.y.z.x.y.z.x.y.z.x.y\n"
                           "r = 1.5\ns = '''\n[[[[[[[[[[[[[[[[[[\n'''\n[[check]]\npointer = \"/a\"\n";
  EXPECT_NO_THROW(io::check_toml_nesting(text, "ok.toml", io::max_case_nesting));
  EXPECT_THROW(io::check_toml_nesting("[scene]\n" + std::string("a") + std::string(17, '.') + " = 1\n", "x.toml", 16),
               InputError);
}

TEST(CaseFileLimits, EveryRepositoryCaseIsWithinTheBounds)
{
  // The bounds refuse only what is not a case file: every case of cases/ reads.
  for (const auto& entry : fs::recursive_directory_iterator((fs::path(ROLLCHECK_REFERENCE_MESH_DIR) / ".." / ".." / "cases").lexically_normal()))
    if (entry.path().extension() == ".toml")
      EXPECT_NO_THROW(io::read_case_file(entry.path())) << entry.path();
}

TEST(CaseFileLimits, SpecialFilesRefusedByName)
{
  EXPECT_NE(refusal([] { io::read_case_file("/dev/zero"); }).find("case file '/dev/zero': is a character device"),
            std::string::npos);
  EXPECT_NE(refusal([] { io::read_case_file(fs::path(ROLLCHECK_TEST_TMP)); }).find("is a directory"), std::string::npos);
  EXPECT_NE(refusal([] { io::read_case_file("/proc/self/mem"); }).find("cannot be read"), std::string::npos);
  const std::string big = "[scene]\nkind = \"toy\"\n" + std::string(io::max_case_file_bytes, '#');
  EXPECT_NE(refusal([&] { io::read_case_file(case_file("big.toml", big)); }).find("bytes"), std::string::npos);
}

TEST(CaseFileLimits, InfiniteToleranceRefused)
{
  for (const std::string criterion : {"value = 1.0\nrel_tol = inf", "max_abs = inf", "value = 1.0\nrel_tol = nan"})
  {
    const std::string text = "[scene]\nkind = \"toy\"\n[[check]]\npointer = \"/x\"\nreference = \"r\"\n" + criterion;
    const std::string message = refusal([&] { io::read_case_file(case_file("inf.toml", text)); });
    EXPECT_NE(message.find("must be finite"), std::string::npos) << criterion << ": " << message;
  }
}

TEST(CaseFileLimits, EveryBadKeyNamedAtOnce)
{
  const io::CaseFile file = io::read_case_file(case_file(
      "bad.toml", "[scene]\nkind = \"toy\"\nwibble = 1\nwobble = 2\nradius_m = -1.0\nseed = \"x\"\n"));
  const std::string message = refusal([&] { io::resolve_case(file, toy_schema().schema(), {}, "case file 'bad.toml'"); });
  for (const char* named : {"unknown key 'wibble'; unknown key 'wobble'", "'radius_m' must be > 0", "'seed' must be an integer"})
    EXPECT_NE(message.find(named), std::string::npos) << named << " in: " << message;
}

TEST(CaseFileLimits, IntegersComparedExactly)
{
  // 2^53 + 1 rounds to 2^53 as a double, the old bound let it through.
  io::Parameters p(toy_schema().schema());
  EXPECT_NO_THROW(p.set_text("seed", "9007199254740992", "option --seed"));
  EXPECT_NE(refusal([&] { p.set_text("seed", "9007199254740993", "option --seed"); }).find("9007199254740993"),
            std::string::npos);
}

TEST(CaseFileLimits, WorkBudget)
{
  io::Parameters p(toy_schema().schema());
  EXPECT_NO_THROW(p.set("threads", std::int64_t{0}, "t"));   // 0: one per core
  EXPECT_NO_THROW(p.set("threads", std::int64_t{256}, "t"));
  EXPECT_NE(refusal([&] { p.set("threads", std::int64_t{100000}, "option --threads"); }).find("0 or in [1, 256]"),
            std::string::npos);
  p.set("duration_s", 1e6, "option --duration");
  p.set("dt_s", 1e-3, "option --dt");
  const std::string message = refusal([&] { toy_schema().bind(p); });
  EXPECT_NE(message.find("'duration_s' / 'dt_s' asks for 1e+09 rigid-body time steps"), std::string::npos)
      << message;
  p.set("duration_s", 1000.0, "option --duration");
  EXPECT_NO_THROW(toy_schema().bind(p));
}

TEST(CaseTemplate, EveryKeyAtItsDefaultAndTheTemplateReads)
{
  const std::string text = io::case_template(toy_schema().schema());
  for (const char* line : {"kind = \"toy\"", "# radius_m = 1.0", "# seed = 0", "# mesh_file = \"\"", "(option --dt)",
                           "0 or in [1, 256]"})
    EXPECT_NE(text.find(line), std::string::npos) << line << " in:\n" << text;
  // As printed, it is a case file of that kind with no override.
  const io::CaseFile file = io::read_case_file(case_file("template.toml", text));
  EXPECT_EQ(file.kind, "toy");
  EXPECT_TRUE(file.values.empty());
  // Uncommented, every line is a valid key at its default.
  std::string uncommented;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    uncommented += (line.find(" = ") != std::string::npos && line.starts_with("# ") ? line.substr(2) : line) + "\n";
  const io::CaseFile all = io::read_case_file(case_file("uncommented.toml", uncommented));
  EXPECT_EQ(all.values.size(), toy_schema().schema().parameters.size());
  EXPECT_NO_THROW(io::resolve_case(all, toy_schema().schema(), {}, "template"));
}

TEST(CaseKeys, OneRuleAndFormerKeysNamed)
{
  EXPECT_EQ(io::case_key("--load", "N", false), "load_n");
  EXPECT_EQ(io::case_key("--load-per-length", "N/m", false), "load_per_length_n_per_m");
  EXPECT_EQ(io::case_key("--youngs-modulus", "Pa", false), "youngs_modulus_pa");
  EXPECT_EQ(io::case_key("--samples", "", false), "samples");
  EXPECT_EQ(io::case_key("--mesh", "", true), "mesh_file");
  EXPECT_THROW(io::case_key("--x", "furlong", false), std::logic_error);
  struct Load
  {
    double force_n = 1;
    std::string mesh;
  };
  io::BoundSchema<Load> s("load");
  s.real("force_n", "--load", &Load::force_n, "N", "Force", io::positive).path("mesh", "--mesh", &Load::mesh, "Mesh");
  EXPECT_EQ(s.schema().parameters[0].key, "load_n");
  EXPECT_EQ(s.schema().parameters[1].key, "mesh_file");
  const io::CaseFile file
      = io::read_case_file(case_file("former.toml", "[scene]\nkind = \"load\"\nforce_n = 2.0\nmesh = \"m.obj\"\n"));
  const std::string message = refusal([&] { io::resolve_case(file, s.schema(), {}, "case file 'former.toml'"); });
  EXPECT_NE(message.find("key 'force_n' is now 'load_n'"), std::string::npos) << message;
  EXPECT_NE(message.find("key 'mesh' is now 'mesh_file'"), std::string::npos) << message;
  // A quantity renamed: its former key is declared with former().
  struct Margin
  {
    double end_margin = 0.05;
  };
  io::BoundSchema<Margin> m("margin");
  m.real("end_margin", "--end-margin", &Margin::end_margin, "", "Margin", io::non_negative).former("crease_margin");
  const io::CaseFile renamed
      = io::read_case_file(case_file("renamed.toml", "[scene]\nkind = \"margin\"\ncrease_margin = 0.1\n"));
  const std::string said = refusal([&] { io::resolve_case(renamed, m.schema(), {}, "case file 'renamed.toml'"); });
  EXPECT_NE(said.find("key 'crease_margin' is now 'end_margin'"), std::string::npos) << said;
}
