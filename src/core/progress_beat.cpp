// A long phase's progress on a thread of its own (core/progress_beat.h).
#include "core/progress_beat.h"
#include <spdlog/spdlog.h>

namespace rollcheck
{
ProgressBeat::ProgressBeat(std::string phase, bool active, std::chrono::milliseconds period)
    : phase_(std::move(phase)), active_(active), period_(period)
{
  if (!active_)
    return;
  thread_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, period_, [this] { return stop_; }))
      log_locked();
  });
}

ProgressBeat::~ProgressBeat()
{
  if (!thread_.joinable())
    return;
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ProgressBeat::step(std::string what, bool log_now)
{
  if (!active_)
    return;
  const std::lock_guard lock(mutex_);
  step_ = std::move(what);
  if (log_now)
    log_locked();
}

double ProgressBeat::elapsed_s() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBeat::log_locked() const
{
  spdlog::info("{}: {} ({:.0f} s)", phase_, step_.empty() ? "running" : step_, elapsed_s());
}
} // namespace rollcheck
