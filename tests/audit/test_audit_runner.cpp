// The audit's runner (audit/runner.h) on a stand-in for `rollcheck`: a
// shell script that appends its subcommand to a log when it starts and
// writes {"subcommand": ..., "argument": ...} as its JSON. On one thread the
// log is the start order: the long subcommands first, in the order of
// their cost, the others in the order they are cited; the outputs come
// back in the commands' order all the same, and a failing command is named.
// Each command's CPU time is its own: a command that burns 0.3 s of CPU in a
// child of its own, run beside one that sleeps until it has ended (so the
// burner is reaped while the sleeper runs), gets it, and the sleeper does not.
// --claims: the claims named, in the table's order; an unknown id refused.
#include "core/error.h"
#include "audit/runner.h"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

using namespace rollcheck;
using namespace rollcheck::audit;
namespace fs = std::filesystem;

namespace
{
/// A folder with the stand-in `rollcheck` (its log beside it).
fs::path stand_in(const std::string& name)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / ("audit_runner_" + name + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Arguments: -q SUBCOMMAND ARGUMENT --json FILE; the subcommand `fail` fails,
  // `burn` spends 0.3 s of CPU in a child, `wait` sleeps until `burn` is done.
  std::ofstream(dir / "rollcheck") << "#!/bin/sh\n"
                                   << "echo \"$2\" >> '" << (dir / "starts.log").string() << "'\n"
                                   << "[ \"$2\" = fail ] && { echo broken >&2; exit 1; }\n"
                                   << "[ \"$2\" = burn ] && /usr/bin/python3 -c 'import time\n"
                                   << "while time.process_time() < 0.3: pass' && touch '" << (dir / "burnt").string() << "'\n"
                                   << "[ \"$2\" = wait ] && while [ ! -e '" << (dir / "burnt").string()
                                   << "' ]; do sleep 0.2; done\n"
                                   << "printf '{\"subcommand\": \"%s\", \"argument\": %s}' \"$2\" \"$3\" > \"$5\"\n";
  fs::permissions(dir / "rollcheck", fs::perms::owner_all);
  return dir;
}

std::string read(const fs::path& file)
{
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}
} // namespace

TEST(AuditRunner, StartsTheLongSubcommandsFirstAndReturnsOutputsInTheCommandsOrder)
{
  const fs::path dir = stand_in("order");
  const std::vector<CommandArgs> commands = {{"oracle", "1"}, {"mesh", "2"},      {"fem-sds", "3"},
                                             {"oracle", "4"}, {"optimize", "5"}, {"rim", "6"}};
  std::vector<CommandOutput> outputs = run_commands(commands, dir / "rollcheck", 1);
  EXPECT_EQ(read(dir / "starts.log"), "optimize\nrim\nfem-sds\noracle\nmesh\noracle\n");
  ASSERT_EQ(outputs.size(), commands.size());
  for (std::size_t i = 0; i < commands.size(); ++i)
  {
    EXPECT_EQ(outputs[i].command(), command_line(commands[i]));
    EXPECT_EQ(outputs[i].at("/subcommand"), commands[i][0]);
    EXPECT_EQ(outputs[i].number("/argument"), static_cast<double>(i + 1));
  }
}

TEST(AuditRunner, AFailedCommandIsNamedWithItsIdAndStderr)
{
  const fs::path dir = stand_in("fail");
  try
  {
    run_commands({{"oracle", "1"}, {"fail", "2"}}, dir / "rollcheck", 2);
    FAIL() << "no error";
  }
  catch (const ComputationError& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("c2 `rollcheck fail 2 --json -`"), std::string::npos) << what;
    EXPECT_NE(what.find("broken"), std::string::npos) << what;
  }
}

TEST(AuditRunner, EachCommandGetsItsOwnCpuTime)
{
  const fs::path dir = stand_in("cost");
  std::vector<CommandOutput> outputs = run_commands({{"wait", "1"}, {"burn", "2"}}, dir / "rollcheck", 2);
  ASSERT_EQ(outputs.size(), 2u);
  const CommandCost &sleeper = outputs[0].cost(), &burner = outputs[1].cost();
  EXPECT_GE(burner.cpu_s, 0.3);
  EXPECT_LT(burner.cpu_s, 0.6); // the sleeper's share not added
  EXPECT_GE(burner.wall_s, burner.cpu_s); // one thread
  // The burner's >= 0.3 s, reaped while the sleeper slept, not counted here:
  // the sleeper's own start-up (0.13 s seen on a machine at load 7) stays
  // below half of the burner's, which the burner's share added would not.
  EXPECT_LT(sleeper.cpu_s, 0.5 * burner.cpu_s);
}

TEST(AuditRunner, SelectsClaimsInTheTablesOrderAndRefusesAnUnknownId)
{
  const std::vector<Claim> all = {Claim{"first"}, Claim{"second"}, Claim{"third"}};
  auto ids = [](const std::vector<Claim>& claims) {
    std::vector<std::string> out;
    for (const Claim& c : claims)
      out.push_back(c.id);
    return out;
  };
  EXPECT_EQ(ids(select_claims(all, {})), (std::vector<std::string>{"first", "second", "third"}));
  EXPECT_EQ(ids(select_claims(all, {"third", "first"})), (std::vector<std::string>{"first", "third"}));
  try
  {
    select_claims(all, {"second", "fourth"});
    FAIL() << "no error";
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(std::string(e.what()), "option --claims: no claim 'fourth'; the claims are first, second, third");
  }
}
