// A folder marked by a rollcheck before manifests (a plain-text
// `.rollcheck-output`) lists nothing: a user's file there is never removed,
// however old its time stamp (mv, cp -p and tar keep one), and a name the run
// would write is refused (core/output_manifest.h).
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_manifest.h"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rollcheck;

namespace
{
fs::path legacy_folder(const std::string& name)
{
  const fs::path dir = fs::path(ROLLCHECK_TEST_TMP) / ("legacy_marker_" + name + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "report");
  std::ofstream(dir / "report" / output_marker) << "rollcheck output\n";
  std::ofstream(dir / "report" / "notes.txt") << "the user's";
  // Older than the marker, as a file moved in with its time kept.
  fs::last_write_time(dir / "report" / "notes.txt", fs::last_write_time(dir / "report" / output_marker) - std::chrono::hours(24 * 365));
  return dir;
}
} // namespace

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
  std::ifstream in(dir / "report" / "notes.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "the user's");
}
