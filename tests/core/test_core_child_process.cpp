// The process runner (core/child_process.h): exit codes, signals, timeouts,
// captured and logged output, the environment a child inherits, and programs
// that cannot be started. Children are /bin/sh one-liners whose effect is
// known exactly.
#include "core/child_process.h"
#include "core/error.h"
#include <cstdlib>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace rollcheck;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace
{
process::RunResult shell(const std::string& script, std::chrono::milliseconds timeout = {})
{
  return process::run({"/bin/sh", "-c", script}, timeout);
}

fs::path fresh_folder(const std::string& name)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / "child_process" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_file(const fs::path& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
} // namespace

TEST(ChildProcess, ReportsTheExitCode)
{
  const process::RunResult r = shell("exit 3");
  EXPECT_EQ(r.status.code, 3);
  EXPECT_EQ(r.status.signal, 0);
  EXPECT_FALSE(r.status.success());
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.status.describe(), "exit code 3");
  EXPECT_TRUE(shell("true").status.success());
}

TEST(ChildProcess, ReportsTheSignalThatKilledIt)
{
  const process::RunResult r = shell("kill -KILL $$");
  EXPECT_EQ(r.status.signal, SIGKILL);
  EXPECT_EQ(r.status.code, 128 + SIGKILL);
  EXPECT_EQ(r.status.describe().rfind("killed by signal 9", 0), 0u) << r.status.describe();
}

TEST(ChildProcess, TerminatesARunPastItsTimeout)
{
  const process::RunResult r = shell("echo started; exec sleep 30", 300ms);
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.status.signal, SIGTERM);
  EXPECT_EQ(r.out, "started\n"); // what it printed before the timeout is kept
  EXPECT_GE(r.wall_s, 0.3);
  EXPECT_LT(r.wall_s, 10.0);
  EXPECT_FALSE(shell("exit 0", 10s).timed_out);
}

TEST(ChildProcess, CapturesStdoutAndStderrApart)
{
  const process::RunResult r = shell("printf 'out\\nput'; printf err >&2; exit 1");
  EXPECT_EQ(r.out, "out\nput");
  EXPECT_EQ(r.err, "err");
  EXPECT_EQ(r.status.code, 1);
}

TEST(ChildProcess, CapturesOutputLargerThanAPipe)
{
  // 1 MB on each stream: a parent that did not read while waiting would
  // deadlock with the child blocked on a full pipe.
  const process::RunResult r =
      shell("head -c 1000000 /dev/zero | tr '\\0' o; head -c 1000000 /dev/zero | tr '\\0' e >&2", 60s);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.out, std::string(1000000, 'o'));
  EXPECT_EQ(r.err, std::string(1000000, 'e'));
}

TEST(ChildProcess, AppendsBothStreamsToTheLogInItsFolder)
{
  const fs::path dir = fresh_folder("log");
  const process::ChildSettings options{dir, dir / "log.txt", process::Sink::log, process::Sink::log};
  for (const char* word : {"first", "second"})
  {
    process::ChildProcess child({"/bin/sh", "-c", std::string("pwd; echo ") + word + " >&2"}, options);
    EXPECT_TRUE(child.wait().success());
    EXPECT_EQ(child.captured_stdout(), "");
  }
  const std::string here = fs::canonical(dir).string();
  EXPECT_EQ(read_file(dir / "log.txt"), here + "\nfirst\n" + here + "\nsecond\n");
}

TEST(ChildProcess, TerminateStopsARunningChild)
{
  process::ChildProcess child({"/bin/sleep", "30"}, {});
  EXPECT_FALSE(child.poll().has_value());
  EXPECT_FALSE(child.wait_for(100ms).has_value());
  const process::ExitStatus status = child.terminate();
  EXPECT_EQ(status.signal, SIGTERM);
  EXPECT_LT(child.elapsed_s(), 10.0);
}

TEST(ChildProcess, InheritsTheEnvironment)
{
  setenv("ROLLCHECK_CHILD_TEST", "inherited", 1);
  EXPECT_EQ(shell("printf %s \"$ROLLCHECK_CHILD_TEST\"").out, "inherited");
  unsetenv("ROLLCHECK_CHILD_TEST");
}

TEST(ChildProcess, LeavesOutTheMpiLauncherVariablesOfARank)
{
  const std::string show = "printf '%s|%s|%s' \"$OMPI_MCA_child_test\" \"$OMPI_ALLOW_RUN_AS_ROOT\" \"$PMIX_RANK\"";
  setenv("OMPI_MCA_child_test", "launcher", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  unsetenv("OMPI_COMM_WORLD_SIZE");
  unsetenv("PMIX_RANK");
  unsetenv("PMI_RANK");
  EXPECT_EQ(shell(show).out, "launcher|1|"); // not a rank: everything inherited
  setenv("PMIX_RANK", "0", 1);               // now a rank of mpirun
  EXPECT_EQ(shell(show).out, "|1|");
  unsetenv("PMIX_RANK");
  unsetenv("OMPI_MCA_child_test");
}

TEST(ChildProcess, AMissingExecutableIsAnErrorNamingIt)
{
  try
  {
    process::run({"/no/such/program", "--flag"});
    FAIL() << "no error";
  }
  catch (const ComputationError& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("/no/such/program"), std::string::npos) << message;
    EXPECT_NE(message.find("No such file"), std::string::npos) << message;
  }
  try
  {
    process::run({"/bin/true"}, {}, "/no/such/folder");
    FAIL() << "no error";
  }
  catch (const ComputationError& e)
  {
    EXPECT_NE(std::string(e.what()).find("/no/such/folder"), std::string::npos) << e.what();
  }
}
