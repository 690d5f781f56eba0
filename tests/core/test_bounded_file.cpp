// core::read_bounded_file: regular files only, within their cap; every special
// file is refused by name before a byte is read, so none can take unbounded
// memory or time (each of these ran for minutes or blocked before the reader).
#include "core/bounded_file.h"
#include "core/error.h"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rollcheck;

namespace
{
fs::path scratch()
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / ("bounded_file_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

/// The InputError's message for reading `path` with a cap of `cap` bytes ("" if none).
std::string refusal(const fs::path& path, std::size_t cap = 1 << 20)
{
  try
  {
    core::read_bounded_file(path, "mesh file", cap);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST(BoundedFile, ReadsARegularFileWhole)
{
  const fs::path file = scratch() / "a.txt";
  std::ofstream(file) << "abc\n";
  EXPECT_EQ(core::read_bounded_file(file, "mesh file", 4), "abc\n");
}

TEST(BoundedFile, RefusesAFileAboveItsCap)
{
  const fs::path file = scratch() / "big.txt";
  std::ofstream(file) << std::string(100, 'x');
  EXPECT_NE(refusal(file, 99).find("big.txt': holds 100 bytes, more than the 99"), std::string::npos);
  EXPECT_EQ(core::read_bounded_file(file, "mesh file", 100).size(), 100u);
}

TEST(BoundedFile, RefusesSpecialFilesByName)
{
  const fs::path dir = scratch();
  EXPECT_NE(refusal("/dev/zero").find("'/dev/zero': is a character device"), std::string::npos);
  EXPECT_NE(refusal("/dev/urandom").find("character device"), std::string::npos);
  EXPECT_NE(refusal(dir).find("is a directory"), std::string::npos);
  const fs::path fifo = dir / "fifo.obj";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(refusal(fifo).find("is a fifo"), std::string::npos);
  const fs::path loop = dir / "loop.obj";
  fs::remove(loop);
  fs::create_symlink(loop, loop);
  EXPECT_NE(refusal(loop).find("symbolic link loop"), std::string::npos);
  const fs::path to_zero = dir / "z.stl";
  fs::remove(to_zero);
  fs::create_symlink("/dev/zero", to_zero);
  EXPECT_NE(refusal(to_zero).find("z.stl': is a character device"), std::string::npos);
  EXPECT_NE(refusal("/proc/self/mem").find("'/proc/self/mem': cannot be read"), std::string::npos);
  EXPECT_NE(refusal(dir / "missing.obj").find("does not exist"), std::string::npos);
  EXPECT_NE(refusal("").find("the path is empty"), std::string::npos);
}

TEST(BoundedFile, ProcFilesAreCappedToo)
{
  // /proc reports size 0 whatever it holds: the cap holds while reading.
  EXPECT_NE(refusal("/proc/self/maps", 8).find("more than the 8 bytes"), std::string::npos);
}

TEST(BoundedFile, LineCaps)
{
  EXPECT_NO_THROW(core::check_line_caps("a\nb\n", "x.toml", "case file", 2, 1));
  EXPECT_THROW(core::check_line_caps("a\nb\nc", "x.toml", "case file", 2, 1), InputError);
  EXPECT_THROW(core::check_line_caps("a\nbb\n", "x.toml", "case file", 2, 1), InputError);
}
