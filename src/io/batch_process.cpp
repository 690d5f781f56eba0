#include "io/batch_process.h"
#include "core/error.h"
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace rollcheck::io
{
namespace
{
bool started_by_mpirun() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

/// The environment a child gets (see ChildProcess).
std::vector<std::string> child_environment()
{
  const bool scrub = started_by_mpirun();
  std::vector<std::string> env;
  for (char** entry = environ; *entry; ++entry)
  {
    const std::string_view var(*entry);
    const bool launcher = var.starts_with("OMPI_") || var.starts_with("PMIX_");
    if (!scrub || !launcher || var.starts_with("OMPI_ALLOW_RUN_AS_ROOT"))
      env.emplace_back(var);
  }
  return env;
}

ExitStatus decode(int wait_status)
{
  if (WIFSIGNALED(wait_status))
    return {128 + WTERMSIG(wait_status), WTERMSIG(wait_status)};
  return {WEXITSTATUS(wait_status), 0};
}

std::vector<char*> pointers(std::vector<std::string>& strings)
{
  std::vector<char*> p;
  for (std::string& s : strings)
    p.push_back(s.data());
  p.push_back(nullptr);
  return p;
}
} // namespace

std::string ExitStatus::describe() const
{
  if (signal)
    return fmt::format("killed by signal {} ({})", signal, strsignal(signal));
  return fmt::format("exit code {}", code);
}

std::filesystem::path own_executable() { return std::filesystem::read_symlink("/proc/self/exe"); }

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                           const std::filesystem::path& log)
{
  // Everything the child needs is prepared before fork: between fork and
  // exec only async-signal-safe calls are allowed.
  std::vector<std::string> args = argv, env = child_environment();
  std::vector<char*> arg_pointers = pointers(args), env_pointers = pointers(env);
  const std::string cwd_text = cwd.string(), log_text = log.string();
  const int log_fd = open(log_text.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_fd < 0)
    throw InputError(fmt::format("batch: cannot open log '{}': {}", log_text, strerror(errno)));
  const int null_fd = open("/dev/null", O_RDONLY | O_CLOEXEC);
  const pid_t parent = getpid();
  start_ = std::chrono::steady_clock::now();
  pid_ = fork();
  if (pid_ == 0)
  {
    setpgid(0, 0); // Ctrl-C on the terminal reaches the batch, which decides
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) // the batch died before prctl took effect
      _exit(127);
    if (chdir(cwd_text.c_str()) != 0 || dup2(null_fd, 0) < 0 || dup2(log_fd, 1) < 0 || dup2(log_fd, 2) < 0)
      _exit(127);
    execve(arg_pointers[0], arg_pointers.data(), env_pointers.data());
    const char message[] = "batch: exec of the case command failed\n";
    [[maybe_unused]] ssize_t ignored = write(2, message, sizeof message - 1);
    _exit(127);
  }
  const int fork_error = errno;
  close(log_fd);
  if (null_fd >= 0)
    close(null_fd);
  if (pid_ < 0)
    throw ComputationError(fmt::format("batch: cannot start a process: {}", strerror(fork_error)));
  setpgid(pid_, pid_); // also here, so that terminate() never races the child's own call
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : pid_(other.pid_), status_(other.status_), start_(other.start_)
{
  other.pid_ = -1;
}

ChildProcess::~ChildProcess()
{
  if (pid_ > 0 && !status_)
    terminate();
}

std::optional<ExitStatus> ChildProcess::poll()
{
  if (status_ || pid_ <= 0)
    return status_;
  int wait_status = 0;
  const pid_t r = waitpid(pid_, &wait_status, WNOHANG);
  if (r == pid_)
    status_ = decode(wait_status);
  return status_;
}

ExitStatus ChildProcess::wait()
{
  while (!status_)
  {
    int wait_status = 0;
    const pid_t r = waitpid(pid_, &wait_status, 0);
    if (r == pid_)
      status_ = decode(wait_status);
    else if (r < 0 && errno != EINTR)
      status_ = ExitStatus{127, 0};
  }
  return *status_;
}

ExitStatus ChildProcess::terminate(std::chrono::milliseconds grace)
{
  if (poll())
    return *status_;
  kill(-pid_, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + grace;
  while (!poll() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (!status_)
    kill(-pid_, SIGKILL);
  return wait();
}

double ChildProcess::elapsed_s() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}
} // namespace rollcheck::io
