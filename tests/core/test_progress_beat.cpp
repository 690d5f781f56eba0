// A long phase's progress (core/progress_beat.h): the step is logged
// when it is set, repeated on the beat's own thread while it lasts, and the
// thread stops with the beat; an inactive beat says nothing.
#include "core/progress_beat.h"
#include <chrono>
#include <gtest/gtest.h>
#include <memory>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <string>
#include <thread>

using namespace rollcheck;

namespace
{
/// The default logger into a ring buffer (thread-safe to read) for the test's life.
class CapturedLog
{
public:
  CapturedLog() : sink_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(10000))
  {
    sink_->set_pattern("%v");
    spdlog::set_default_logger(std::make_shared<spdlog::logger>("captured", sink_));
  }
  ~CapturedLog() { spdlog::set_default_logger(std::make_shared<spdlog::logger>("none")); }
  std::string text() const
  {
    std::string all;
    for (const std::string& line : sink_->last_formatted())
      all += line;
    return all;
  }
  /// Lines containing `what`.
  int count(const std::string& what) const
  {
    int n = 0;
    for (const std::string& line : sink_->last_formatted())
      n += line.find(what) != std::string::npos;
    return n;
  }

private:
  std::shared_ptr<spdlog::sinks::ringbuffer_sink_mt> sink_;
};
} // namespace

TEST(ProgressBeat, LogsTheStepNowAndAgainOnEveryBeat)
{
  CapturedLog log;
  {
    ProgressBeat beat("rim loop", true, std::chrono::milliseconds(1));
    beat.step("end table node 3 of 17");
    EXPECT_GE(log.count("rim loop: end table node 3 of 17 ("), 1);
    // Without another step the beat repeats it: wait (without a deadline
    // on the result) until it has.
    while (log.count("end table node 3 of 17") < 3)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    beat.step("the end-aware scores");
    EXPECT_GE(log.count("rim loop: the end-aware scores ("), 1);
  }
  // Stopped with the beat: nothing more after it is gone.
  const int after = log.count("rim loop:");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(log.count("rim loop:"), after);
}

TEST(ProgressBeat, AnInactiveBeatIsSilent)
{
  CapturedLog log;
  {
    ProgressBeat beat("rim loop", false, std::chrono::milliseconds(1));
    beat.step("direct end 1 of 4");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(log.text(), "");
}

TEST(ProgressBeat, AStepTheCallerLogsItselfWaitsForTheBeat)
{
  CapturedLog log;
  {
    ProgressBeat beat("audit", true, std::chrono::hours(1));
    beat.step("[3/64] running c17", false);
    EXPECT_EQ(log.count("running c17"), 0);
    beat.step("[4/64] running c63");
    EXPECT_EQ(log.count("audit: [4/64] running c63 ("), 1);
  }
}
