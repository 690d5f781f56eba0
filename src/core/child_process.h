#pragma once
// Runs another program as a child process: the one process runner of
// rollcheck, used by the batch (a case per process, so that a crash or a hang
// of one case cannot take the batch down) and by the audit (each claim's
// number comes from a `rollcheck` command run as it is listed). It owns how a
// child starts (its environment, folder, streams, process group), how its
// output is captured, and how it is stopped.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace rollcheck::process
{
/// How a process ended: an exit code, or the signal that killed it (then
/// `code` is 128 + signal, as a shell reports it).
struct ExitStatus
{
  int code = 0;
  int signal = 0;
  bool success() const { return code == 0 && signal == 0; }
  std::string describe() const; ///< "exit code 2", "killed by signal 9 (Killed)"
};

/// Where a child's stdout or stderr goes.
enum class Sink
{
  capture, ///< into a string of the parent (ChildProcess::captured_stdout/stderr)
  log      ///< appended to ChildSettings::log
};

struct ChildSettings
{
  std::filesystem::path cwd; ///< the child's working folder; empty: this process's
  std::filesystem::path log; ///< the file of the streams sent to Sink::log
  Sink out = Sink::capture;
  Sink err = Sink::capture;
};

/// The running executable (/proc/self/exe), for starting copies of it.
std::filesystem::path own_executable();

/// A child process running argv[0] (a path: no PATH search) with arguments
/// argv, stdin /dev/null, stdout and stderr as `options` say.
///
/// Environment: the child inherits this process's environment. One exception:
/// when this process is an MPI rank (started by mpirun: OMPI_COMM_WORLD_SIZE,
/// PMIX_RANK or PMI_RANK set), the launcher's variables (OMPI_*, PMIX_*, PMI_*,
/// except OMPI_ALLOW_RUN_AS_ROOT*) are left out, so that a rollcheck child is
/// a fresh MPI job of its own instead of a confused copy of this rank.
///
/// The child runs in its own process group (Ctrl-C on the terminal reaches the
/// parent, which decides) and receives SIGTERM if the thread that started it
/// dies (PR_SET_PDEATHSIG), so a parent killed even by SIGKILL leaves no
/// orphans computing. A program that cannot be started (missing, not
/// executable, bad cwd) is a ComputationError naming it, thrown here.
class ChildProcess
{
public:
  ChildProcess(const std::vector<std::string>& argv, const ChildSettings& options);
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ChildProcess& operator=(ChildProcess&&) = delete;
  /// Terminates a child still running.
  ~ChildProcess();

  /// The exit status once the child has ended; nullopt while it runs. Reads
  /// what the child wrote to captured streams so far (it never blocks on a
  /// full pipe as long as the parent polls).
  std::optional<ExitStatus> poll();
  /// Blocks until the child ends or `timeout` has passed since it started
  /// (zero: no limit); nullopt on timeout, the child still running.
  std::optional<ExitStatus> wait_for(std::chrono::milliseconds timeout);
  /// Blocks until the child ends.
  ExitStatus wait();
  /// SIGTERM to the child's process group, SIGKILL after `grace`; waits.
  ExitStatus terminate(std::chrono::milliseconds grace = std::chrono::milliseconds(2000));
  double elapsed_s() const;

  const std::string& captured_stdout() const { return captured_[0]; }
  const std::string& captured_stderr() const { return captured_[1]; }

private:
  pid_t pid_ = -1;
  std::optional<ExitStatus> status_;
  std::chrono::steady_clock::time_point start_;
  int pipes_[2] = {-1, -1}; ///< read ends of the captured stdout, stderr
  std::string captured_[2];

  /// Reads what the captured pipes hold, waiting up to `wait` for data.
  void drain(std::chrono::milliseconds wait);
  void close_pipes();
};

/// A finished run of a command.
struct RunResult
{
  ExitStatus status;
  bool timed_out = false; ///< stopped by run()'s timeout (status: its SIGTERM)
  std::string out, err;   ///< captured stdout and stderr
  double wall_s = 0;
};

/// Runs `argv` to its end with stdout and stderr captured; a run longer than
/// `timeout` (zero: no limit) is terminated (ChildProcess::terminate).
RunResult run(const std::vector<std::string>& argv, std::chrono::milliseconds timeout = {},
              const std::filesystem::path& cwd = {});
} // namespace rollcheck::process
