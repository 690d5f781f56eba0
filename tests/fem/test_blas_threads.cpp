// The BLAS behind PETSc runs one thread unless the user set a number
// (core/blas_threads.h): an environment that names a count is left alone,
// one that names none gets one thread, read back from OpenBLAS itself.
#include "core/blas_threads.h"
#include <cstdlib>
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <optional>
#include <string>

namespace
{
/// An environment variable unset for the test's scope and restored after it.
struct UnsetVariable
{
  explicit UnsetVariable(const char* n) : name(n)
  {
    if (const char* v = std::getenv(n))
      saved = v;
    ::unsetenv(n);
  }
  ~UnsetVariable()
  {
    if (saved)
      ::setenv(name, saved->c_str(), 1);
    else
      ::unsetenv(name);
  }
  const char* name;
  std::optional<std::string> saved;
};
} // namespace

TEST(BlasThreads, OneThreadUnlessTheEnvironmentNamesACount)
{
  using Get = int (*)();
  using Set = void (*)(int);
  const auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  using Parallel = int (*)();
  const auto parallel = reinterpret_cast<Parallel>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
  ASSERT_TRUE(get && set && parallel) << "the FEM's BLAS (PETSc's, Debian's stack) is OpenBLAS";
  ASSERT_EQ(parallel(), 1) << "Debian's stack: OpenBLAS's pthreads build";
  const UnsetVariable a("OPENBLAS_NUM_THREADS"), b("GOTO_NUM_THREADS"), c("OMP_NUM_THREADS");

  set(2);
  const int chosen = get();
  ASSERT_GT(chosen, 1) << "needs 2 CPUs, so that one thread differs from the count chosen";
  ::setenv("OMP_NUM_THREADS", "2", 1);
  EXPECT_FALSE(rollcheck::prefer_one_blas_thread());
  EXPECT_EQ(get(), chosen);
  ::unsetenv("OMP_NUM_THREADS");

  EXPECT_TRUE(rollcheck::prefer_one_blas_thread());
  EXPECT_EQ(get(), 1);
}
