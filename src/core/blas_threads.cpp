// One BLAS thread per process (core/blas_threads.h).
#include "core/blas_threads.h"
#include <cstdlib>
#include <dlfcn.h>

namespace rollcheck
{
bool prefer_one_blas_thread()
{
  for (const char* name : {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"})
    if (std::getenv(name))
      return false;
  using SetThreads = void (*)(int);
  using Parallel = int (*)();
  const auto set_threads = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  const auto parallel = reinterpret_cast<Parallel>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
  // OpenMP builds (2) set OpenMP's own count, which every later OpenMP region would follow.
  if (!set_threads || !parallel || parallel() != 1)
    return false;
  set_threads(1);
  return true;
}
} // namespace rollcheck
