#pragma once
// Progress of a long phase at the default log level (info) while it runs:
// the rim loop's steps (the interior, each direct end, the flat-rim table,
// each node of the end table), flat-rim's levels and the audit's commands
// take from seconds to many minutes each, longer than a user should wait
// without a word. A beat
// logs the current step when it is set and, on a thread of its own, again
// every `period` while it lasts, with the time since the phase began; a
// solve that logs nothing for minutes still shows that it runs.
//
// Only the process that is to speak beats (rank 0 under MPI: `active`); the
// thread touches nothing but its own text and spdlog's thread-safe default
// logger.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace rollcheck
{
class ProgressBeat
{
public:
  /// Starts the phase `phase` (the log lines' prefix); silent when not `active`.
  ProgressBeat(std::string phase, bool active, std::chrono::milliseconds period = std::chrono::seconds(8));
  ~ProgressBeat();
  ProgressBeat(const ProgressBeat&) = delete;
  ProgressBeat& operator=(const ProgressBeat&) = delete;

  /// The phase's current step, logged on every beat until the next, and now
  /// unless the caller logs the change itself.
  void step(std::string what, bool log_now = true);
  /// Seconds since the phase began.
  double elapsed_s() const;

private:
  void log_locked() const;
  const std::string phase_;
  const bool active_;
  const std::chrono::milliseconds period_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::string step_;
  bool stop_ = false;
  std::thread thread_;
};
} // namespace rollcheck
