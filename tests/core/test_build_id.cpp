// The build a batch's result keys name (core/build_id.h): the executable's
// GNU build-id as readelf, an independent reader of the ELF notes, prints it.
#include "core/build_id.h"
#include "core/child_process.h"
#include <cstdio>
#include <gtest/gtest.h>
#include <string>

TEST(BuildId, IsTheNoteReadelfPrints)
{
  const std::string command = "readelf -n " + rollcheck::process::own_executable().string() + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string text;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe))
    text += buffer;
  pclose(pipe);
  const std::size_t at = text.find("Build ID: ");
  if (at == std::string::npos)
    GTEST_SKIP() << "readelf found no build-id note (binutils missing, or linked with --build-id=none)";
  const std::string expected = text.substr(at + 10, text.find('\n', at) - at - 10);
  EXPECT_EQ(rollcheck::build_id(), expected);
  EXPECT_GE(expected.size(), 40u);
}
