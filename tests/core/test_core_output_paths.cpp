// Output safety (core/atomic_file.h): a folder holding a user's file survives
// every write; results are whole or absent; bad paths are refused up front.
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_manifest.h"
#include <chrono>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <csignal>
#include <set>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rollcheck;

namespace
{
fs::path fresh_dir(const std::string& name)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / ("output_paths_" + name + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p)
{
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
} // namespace

TEST(OutputFolder, UserFolderIsNeverReplaced)
{
  const fs::path dir = fresh_dir("user");
  write(dir / "my_notes.txt", "precious");
  fs::create_directories(dir / "sub");
  EXPECT_THROW(check_output_folder(dir, "--out"), InputError);
  EXPECT_THROW(write_folder_atomically(dir, "--out", [](const fs::path& tmp) { write(tmp / "a.txt", "x"); }),
               InputError);
  EXPECT_EQ(read(dir / "my_notes.txt"), "precious");
  EXPECT_TRUE(fs::is_directory(dir / "sub"));
  EXPECT_FALSE(fs::exists(dir / "a.txt"));
}

TEST(OutputFolder, FileIsNotTurnedIntoAFolder)
{
  const fs::path dir = fresh_dir("file");
  write(dir / "precious.txt", "precious");
  EXPECT_THROW(write_folder_atomically(dir / "precious.txt", "--out", [](const fs::path&) {}), InputError);
  EXPECT_EQ(read(dir / "precious.txt"), "precious");
}

TEST(OutputFolder, OwnFolderIsReplacedWhole)
{
  const fs::path dir = fresh_dir("own");
  const fs::path out = dir / "result";
  write_folder_atomically(out, "--out", [](const fs::path& tmp) { write(tmp / "first.txt", "1"); });
  EXPECT_TRUE(fs::exists(out / output_marker));
  write_folder_atomically(out, "--out", [](const fs::path& tmp) { write(tmp / "second.txt", "2"); });
  EXPECT_FALSE(fs::exists(out / "first.txt"));
  EXPECT_EQ(read(out / "second.txt"), "2");
  // Nothing left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(OutputFolder, FailedFillLeavesTheOldFolderAndNoScratch)
{
  const fs::path dir = fresh_dir("fail");
  const fs::path out = dir / "result";
  write_folder_atomically(out, "--out", [](const fs::path& tmp) { write(tmp / "old.txt", "old"); });
  EXPECT_THROW(write_folder_atomically(out, "--out",
                                       [](const fs::path& tmp) {
                                         write(tmp / "half.txt", "half");
                                         throw ComputationError("solver diverged");
                                       }),
               ComputationError);
  EXPECT_EQ(read(out / "old.txt"), "old");
  EXPECT_FALSE(fs::exists(out / "half.txt"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(OutputFile, RefusedUpFront)
{
  const fs::path dir = fresh_dir("file_checks");
  EXPECT_THROW(check_output_file(dir / "missing" / "x.json", "--json"), InputError);
  EXPECT_THROW(check_output_file(dir, "--json"), InputError);
  EXPECT_NO_THROW(check_output_file(dir / "x.json", "--json"));
  try
  {
    check_output_file(dir / "missing" / "x.json", "--json");
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("--json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos);
  }
}

TEST(OutputFile, WriterThatMakesAFolderLeavesNoScratch)
{
  const fs::path dir = fresh_dir("scratch");
  EXPECT_THROW(write_atomically(dir / "f.h5",
                                [](const fs::path& tmp) {
                                  fs::create_directories(tmp / "inner");
                                  throw ComputationError("writer failed");
                                }),
               ComputationError);
  EXPECT_TRUE(fs::is_empty(dir));
}

// The manifest rule (core/output_manifest.h): a folder output removes or
// replaces only what its manifest lists.
namespace
{
/// A process id that runs nothing: a child that has exited and been reaped.
long dead_pid()
{
  const pid_t child = fork();
  if (child == 0)
    _exit(0);
  int status = 0;
  waitpid(child, &status, 0);
  return child;
}
} // namespace

TEST(OutputFolder, UserFilesAddedToAnOwnFolderSurviveTheNextRun)
{
  const fs::path dir = fresh_dir("added");
  const fs::path out = dir / "result";
  write_folder_atomically(out, "--out", [](const fs::path& tmp) { write(tmp / "first.txt", "1"); });
  write(out / "notes.txt", "the user's");
  fs::create_directories(out / "mine");
  write(out / "mine" / "draft.md", "the user's too");
  write_folder_atomically(out, "--out", [](const fs::path& tmp) { write(tmp / "second.txt", "2"); });
  EXPECT_FALSE(fs::exists(out / "first.txt")); // listed by the first run: replaced
  EXPECT_EQ(read(out / "second.txt"), "2");
  EXPECT_EQ(read(out / "notes.txt"), "the user's");
  EXPECT_EQ(read(out / "mine" / "draft.md"), "the user's too");
  EXPECT_EQ(read_output_manifest(out)->entries, std::set<std::string>{"second.txt"});
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(OutputFolder, AUserFileWhereTheRunWritesIsRefusedAndKept)
{
  const fs::path dir = fresh_dir("collide");
  const fs::path out = dir / "result";
  write_folder_atomically(out, "--out", [](const fs::path& tmp) { write(tmp / "a.txt", "a"); });
  write(out / "b.txt", "the user's b");
  EXPECT_THROW(write_folder_atomically(out, "--out", [](const fs::path& tmp) { write(tmp / "b.txt", "ours"); }),
               InputError);
  EXPECT_EQ(read(out / "b.txt"), "the user's b");
  EXPECT_EQ(read(out / "a.txt"), "a");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(OutputFolder, ADrawingOfAKilledRunIsRemovedAndNothingElse)
{
  const fs::path dir = fresh_dir("stale");
  const long dead = dead_pid();
  const fs::path stale = dir / (".result.tmp" + std::to_string(dead));
  fs::create_directories(stale);
  write(stale / output_marker, "{}");
  write(stale / "half.txt", "half");
  const fs::path users = dir / (".result.tmp" + std::to_string(dead + 1)); // no manifest: not rollcheck's
  fs::create_directories(users);
  write(users / "data.csv", "the user's");
  const fs::path running = dir / (".result.tmp" + std::to_string(getppid())); // its process runs
  fs::create_directories(running);
  write(running / output_marker, "{}");
  write_folder_atomically(dir / "result", "--out", [](const fs::path& tmp) { write(tmp / "a.txt", "a"); });
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_EQ(read(users / "data.csv"), "the user's");
  EXPECT_TRUE(fs::exists(running / output_marker));
}

TEST(OutputManifest, OnlyListedEntriesAndTheirWorkAreRollchecks)
{
  const fs::path dir = fresh_dir("manifest");
  claim_outputs(dir, {"results.h5", "cases/abc"});
  const OutputManifest m = *read_output_manifest(dir);
  EXPECT_TRUE(m.lists("cases/abc/result.json"));
  EXPECT_FALSE(m.lists("cases/abd"));
  EXPECT_FALSE(m.lists("cases"));
  EXPECT_TRUE(is_stale_work(m, "cases/abc.part"));
  EXPECT_TRUE(is_stale_work(m, "cases/abc.old"));
  EXPECT_FALSE(is_stale_work(m, "cases/r.part"));
  EXPECT_FALSE(is_stale_work(m, "cases/plan.old"));
  EXPECT_FALSE(is_stale_work(m, ".draft.tmp"));
  EXPECT_FALSE(is_stale_work(m, ".env.tmpl"));
  EXPECT_TRUE(is_stale_work(m, ".results.tmp" + std::to_string(dead_pid()) + ".h5"));
  EXPECT_FALSE(is_stale_work(m, ".results.tmp" + std::to_string(getpid()) + ".h5")); // still writing
  EXPECT_FALSE(is_stale_work(m, ".notes.tmp" + std::to_string(dead_pid()) + ".h5"));
  write(dir / "results.h5", "ours");
  write(dir / "validation.json", "the user's");
  EXPECT_NO_THROW(check_output_entries(dir, {"results.h5", "cases/abc", "new.json"}, "--out"));
  try
  {
    check_output_entries(dir, {"results.h5", "validation.json"}, "validate --out");
    ADD_FAILURE() << "a user's validation.json was accepted";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("validation.json"), std::string::npos) << e.what();
  }
}

TEST(OutputFile, AFailedWriteNamesTheFileAndKeepsThePreviousOne)
{
  // A file size limit fails write(2) with EFBIG as a full disk fails it with
  // ENOSPC: the writer must notice either, whatever the stream buffered.
  const fs::path dir = fresh_dir("full");
  const fs::path target = dir / "m.json";
  write(target, "previous");
  signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  rlimit small = old;
  small.rlim_cur = 4096;
  setrlimit(RLIMIT_FSIZE, &small);
  std::string message;
  try
  {
    write_file_atomically(target, std::string(100000, 'x'));
  }
  catch (const ComputationError& e)
  {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  EXPECT_NE(message.find("m.json"), std::string::npos) << message;
  EXPECT_EQ(read(target), "previous");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1); // no temporary left
}

TEST(OutputFile, DevicesAndFifosAreRefusedUpFront)
{
  EXPECT_THROW(check_output_file("/dev/null", "--json"), InputError); // the rename would replace the device
  const fs::path dir = fresh_dir("fifo");
  ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
  EXPECT_THROW(check_output_file(dir / "pipe", "--json"), InputError);
}

namespace
{
/// A report folder with the plain-text marker of a rollcheck before manifests
/// and a user's file older than it, as a file moved in with its time kept.
fs::path legacy_folder(const std::string& name)
{
  const fs::path dir = fresh_dir(name);
  fs::create_directories(dir / "report");
  write(dir / "report" / output_marker, "rollcheck output\n");
  write(dir / "report" / "notes.txt", "the user's");
  fs::last_write_time(dir / "report" / "notes.txt",
                      fs::last_write_time(dir / "report" / output_marker) - std::chrono::hours(24 * 365));
  return dir;
}
} // namespace

// A plain-text marker lists nothing: a user's file there is never removed,
// however old its time stamp, and a name the run would write is refused.
TEST(OutputManifest, APlainTextMarkerListsNothing)
{
  const fs::path dir = legacy_folder("lists");
  const std::optional<OutputManifest> manifest = read_output_manifest(dir / "report");
  ASSERT_TRUE(manifest);
  EXPECT_TRUE(manifest->entries.empty());
}

TEST(OutputManifest, AnOldUserFileInAPlainTextMarkedFolderSurvivesAReport)
{
  const fs::path dir = legacy_folder("survives");
  write_folder_atomically(dir / "report", "report --out",
                          [](const fs::path& tmp) { std::ofstream(tmp / "report.html") << "<html/>"; });
  EXPECT_TRUE(fs::exists(dir / "report" / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "report" / "report.html"));
  // A name the run would write that the old marker cannot vouch for: refused, kept.
  EXPECT_THROW(write_folder_atomically(dir / "report", "report --out",
                                       [](const fs::path& tmp) { std::ofstream(tmp / "notes.txt") << "ours"; }),
               InputError);
  EXPECT_EQ(read(dir / "report" / "notes.txt"), "the user's");
}
