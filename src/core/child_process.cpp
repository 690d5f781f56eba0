#include "core/child_process.h"
#include "core/error.h"
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <utility>

extern char** environ;

namespace rollcheck::process
{
namespace
{
bool started_by_mpirun()
{
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
}

/// The environment a child gets (see ChildProcess).
std::vector<std::string> child_environment()
{
  const bool scrub = started_by_mpirun();
  std::vector<std::string> env;
  for (char** entry = environ; *entry; ++entry)
  {
    const std::string_view var(*entry);
    const bool launcher = var.starts_with("OMPI_") || var.starts_with("PMIX_") || var.starts_with("PMI_");
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

/// What a child reports through its report pipe when it cannot start.
struct StartFailure
{
  enum Step
  {
    enter_folder,
    set_up_streams,
    execute
  } step = execute;
  int error = 0;
};

/// Everything a child needs between fork and exec, prepared before fork: in
/// between, only async-signal-safe calls are allowed. Every descriptor is
/// close-on-exec, so that children started by other threads at the same time
/// do not hold this child's pipes open; all are closed with this object
/// (the parent takes the read ends of the captured streams out first).
struct ChildStart
{
  std::vector<std::string> args, env = child_environment();
  std::vector<char*> arg_pointers = pointers(args), env_pointers = pointers(env);
  std::string cwd;
  int null = -1, log = -1, report[2] = {-1, -1};
  int capture[2][2] = {{-1, -1}, {-1, -1}}; ///< pipes of the captured stdout, stderr
  int target[2] = {-1, -1};                 ///< the child's stdout, stderr
  pid_t parent = getpid();

  ChildStart(const std::vector<std::string>& argv, const ChildSettings& options)
      : args(argv), cwd(options.cwd.string())
  {
    if (options.out == Sink::log || options.err == Sink::log)
    {
      log = open(options.log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
      if (log < 0)
        throw InputError(fmt::format("cannot open log '{}': {}", options.log.string(), strerror(errno)));
    }
    const Sink sinks[2] = {options.out, options.err};
    for (int stream = 0; stream < 2; ++stream)
    {
      if (sinks[stream] == Sink::capture && pipe2(capture[stream], O_CLOEXEC) != 0)
        throw ComputationError(fmt::format("cannot create a pipe: {}", strerror(errno)));
      target[stream] = sinks[stream] == Sink::log ? log : capture[stream][1];
    }
    null = open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (null < 0 || pipe2(report, O_CLOEXEC) != 0)
      throw ComputationError(fmt::format("cannot prepare a process: {}", strerror(errno)));
  }
  ChildStart(const ChildStart&) = delete;
  ChildStart& operator=(const ChildStart&) = delete;
  ~ChildStart()
  {
    for (int fd : {null, log, report[0], report[1], capture[0][0], capture[0][1], capture[1][0], capture[1][1]})
      if (fd >= 0)
        close(fd);
  }

  /// In the child: becomes the program, or reports why not and exits 127.
  [[noreturn]] void exec_in_child() const
  {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) // the parent died before prctl took effect
      _exit(127);
    StartFailure failure;
    if (!cwd.empty() && chdir(cwd.c_str()) != 0)
      failure = {StartFailure::enter_folder, errno};
    else if (dup2(null, 0) < 0 || dup2(target[0], 1) < 0 || dup2(target[1], 2) < 0)
      failure = {StartFailure::set_up_streams, errno};
    else
    {
      execve(arg_pointers[0], arg_pointers.data(), env_pointers.data());
      failure = {StartFailure::execute, errno};
    }
    [[maybe_unused]] ssize_t ignored = write(report[1], &failure, sizeof failure);
    _exit(127);
  }

  /// In the parent: waits until the child has become the program (its report
  /// pipe closes on exec) or reported why it could not.
  std::optional<StartFailure> await_exec()
  {
    close(report[1]);
    report[1] = -1;
    StartFailure failure;
    ssize_t got = 0;
    do
      got = read(report[0], &failure, sizeof failure);
    while (got < 0 && errno == EINTR);
    if (got != static_cast<ssize_t>(sizeof failure))
      return std::nullopt;
    return failure;
  }
};

std::string describe(const StartFailure& failure, const std::string& program, const std::string& cwd)
{
  switch (failure.step)
  {
  case StartFailure::enter_folder:
    return fmt::format("cannot start '{}' in '{}': {}", program, cwd, strerror(failure.error));
  case StartFailure::set_up_streams:
    return fmt::format("cannot start '{}': cannot set up its streams: {}", program, strerror(failure.error));
  case StartFailure::execute: break;
  }
  return fmt::format("cannot start '{}': {}", program, strerror(failure.error));
}
} // namespace

std::string ExitStatus::describe() const
{
  if (signal)
    return fmt::format("killed by signal {} ({})", signal, strsignal(signal));
  return fmt::format("exit code {}", code);
}

std::filesystem::path own_executable() { return std::filesystem::read_symlink("/proc/self/exe"); }

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const ChildSettings& options)
{
  if (argv.empty())
    throw ComputationError("cannot start a process without a program");
  ChildStart start(argv, options);
  start_ = std::chrono::steady_clock::now();
  pid_ = fork();
  if (pid_ == 0)
    start.exec_in_child();
  if (pid_ < 0)
    throw ComputationError(fmt::format("cannot start '{}': {}", argv[0], strerror(errno)));
  setpgid(pid_, pid_); // also here, so that terminate() never races the child's own call
  if (const std::optional<StartFailure> failure = start.await_exec())
  {
    wait();
    throw ComputationError(describe(*failure, argv[0], start.cwd));
  }
  for (int stream = 0; stream < 2; ++stream)
    if (start.capture[stream][0] >= 0)
    {
      pipes_[stream] = std::exchange(start.capture[stream][0], -1);
      fcntl(pipes_[stream], F_SETFL, fcntl(pipes_[stream], F_GETFL) | O_NONBLOCK);
    }
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : pid_(other.pid_), status_(other.status_), start_(other.start_), pipes_{other.pipes_[0], other.pipes_[1]},
      captured_{std::move(other.captured_[0]), std::move(other.captured_[1])}
{
  other.pid_ = -1;
  other.pipes_[0] = other.pipes_[1] = -1;
}

ChildProcess::~ChildProcess()
{
  if (pid_ > 0 && !status_)
    terminate();
  close_pipes();
}

void ChildProcess::close_pipes()
{
  for (int& fd : pipes_)
    if (fd >= 0)
    {
      close(fd);
      fd = -1;
    }
}

void ChildProcess::drain(std::chrono::milliseconds wait)
{
  pollfd watched[2];
  int n = 0;
  for (int fd : pipes_)
    if (fd >= 0)
      watched[n++] = {fd, POLLIN, 0};
  if (n == 0 || ::poll(watched, n, static_cast<int>(wait.count())) <= 0)
    return;
  for (int stream = 0; stream < 2; ++stream)
  {
    char buffer[65536];
    ssize_t got = 0;
    while (pipes_[stream] >= 0 && (got = read(pipes_[stream], buffer, sizeof buffer)) > 0)
      captured_[stream].append(buffer, static_cast<std::size_t>(got));
    if (got == 0 && pipes_[stream] >= 0) // end of file: the child closed it
    {
      close(pipes_[stream]);
      pipes_[stream] = -1;
    }
  }
}

std::optional<ExitStatus> ChildProcess::poll()
{
  if (status_ || pid_ <= 0)
    return status_;
  drain(std::chrono::milliseconds(0));
  int wait_status = 0;
  const pid_t r = waitpid(pid_, &wait_status, WNOHANG);
  if (r == pid_)
    status_ = decode(wait_status);
  else if (r < 0 && errno != EINTR)
    status_ = ExitStatus{127, 0};
  if (status_)
  {
    drain(std::chrono::milliseconds(0)); // what it wrote last
    close_pipes();
  }
  return status_;
}

std::optional<ExitStatus> ChildProcess::wait_for(std::chrono::milliseconds timeout)
{
  while (!poll())
  {
    if (timeout.count() > 0 && std::chrono::steady_clock::now() - start_ >= timeout)
      return std::nullopt;
    if (pipes_[0] >= 0 || pipes_[1] >= 0)
      drain(std::chrono::milliseconds(20));
    else
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return status_;
}

ExitStatus ChildProcess::wait() { return *wait_for(std::chrono::milliseconds(0)); }

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

RunResult run(const std::vector<std::string>& argv, std::chrono::milliseconds timeout,
              const std::filesystem::path& cwd)
{
  ChildProcess child(argv, {cwd, {}, Sink::capture, Sink::capture});
  std::optional<ExitStatus> status = child.wait_for(timeout);
  const bool timed_out = !status;
  if (timed_out)
    status = child.terminate();
  return {*status, timed_out, child.captured_stdout(), child.captured_stderr(), child.elapsed_s()};
}
} // namespace rollcheck::process
