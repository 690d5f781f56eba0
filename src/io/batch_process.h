#pragma once
// A case of a batch runs in its own process (the rollcheck binary itself,
// `rollcheck run CASE --json FILE`), so that a crash, an abort or a hang of
// one case cannot take the batch down, and the batch needs no thread safety
// from the layers below.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace rollcheck::io
{
/// How a process ended: an exit code, or the signal that killed it.
struct ExitStatus
{
  int code = 0;
  int signal = 0;
  bool success() const { return code == 0 && signal == 0; }
  std::string describe() const; ///< "exit code 2", "killed by signal 9 (Killed)"
};

/// The running rollcheck binary (/proc/self/exe), for starting copies of it.
std::filesystem::path own_executable();

/// A child process started in its own process group, in folder `cwd`, with
/// stdout and stderr appended to `log`. It receives SIGTERM if the batch
/// dies (prctl PR_SET_PDEATHSIG), so killing a batch, even by SIGKILL, leaves
/// no orphans computing. When this process was started by mpirun, the MPI
/// launcher's variables (OMPI_*, PMIX_*, except OMPI_ALLOW_RUN_AS_ROOT*) are
/// left out of the child's environment: the child is then a fresh MPI job of
/// its own instead of a confused copy of this rank.
class ChildProcess
{
public:
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
               const std::filesystem::path& log);
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ChildProcess& operator=(ChildProcess&&) = delete;
  /// Terminates a child still running.
  ~ChildProcess();

  /// The exit status once the child has ended; nullopt while it runs.
  std::optional<ExitStatus> poll();
  /// SIGTERM to the child's process group, SIGKILL after `grace`; waits.
  ExitStatus terminate(std::chrono::milliseconds grace = std::chrono::milliseconds(2000));
  /// Blocks until the child ends.
  ExitStatus wait();
  double elapsed_s() const;

private:
  pid_t pid_ = -1;
  std::optional<ExitStatus> status_;
  std::chrono::steady_clock::time_point start_;
};
} // namespace rollcheck::io
