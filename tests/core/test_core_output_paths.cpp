// Output safety (core/atomic_file.h): a folder holding a user's file survives
// every write; results are whole or absent; bad paths are refused up front.
#include "core/atomic_file.h"
#include "core/error.h"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
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
