// core/mpi_launch.h: a process no launcher started asks Open MPI for the
// isolated singleton (no orted daemon); a user's setting and a launcher's
// process are left as they are.
#include "core/mpi_launch.h"
#include <cstdlib>
#include <gtest/gtest.h>
#include <string>

using namespace rollcheck;

namespace
{
constexpr const char* isolated = "OMPI_MCA_ess_singleton_isolated";

/// Clears the variables the contract reads, and restores none: each test
/// sets up its own environment.
void clear_launch_environment()
{
  for (const char* name : {isolated, "OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    ::unsetenv(name);
}

std::string value_of(const char* name)
{
  const char* value = std::getenv(name);
  return value ? value : "(unset)";
}
} // namespace

TEST(MpiLaunch, AProcessNoLauncherStartedAsksForTheIsolatedSingleton)
{
  clear_launch_environment();
  EXPECT_FALSE(launched_by_mpi());
  prefer_isolated_mpi_singleton();
  EXPECT_EQ(value_of(isolated), "1");
}

TEST(MpiLaunch, AUsersSettingWins)
{
  clear_launch_environment();
  ::setenv(isolated, "0", 1);
  prefer_isolated_mpi_singleton();
  EXPECT_EQ(value_of(isolated), "0");
}

TEST(MpiLaunch, ALaunchersProcessIsLeftAlone)
{
  for (const char* launcher : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
  {
    clear_launch_environment();
    ::setenv(launcher, "2", 1);
    EXPECT_TRUE(launched_by_mpi()) << launcher;
    prefer_isolated_mpi_singleton();
    EXPECT_EQ(value_of(isolated), "(unset)") << launcher;
  }
  clear_launch_environment();
}
