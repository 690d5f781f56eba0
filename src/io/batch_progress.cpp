#include "io/batch_progress.h"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace rollcheck::io
{
namespace
{
int terminal_width(std::FILE* stream)
{
  winsize size{};
  if (ioctl(fileno(stream), TIOCGWINSZ, &size) == 0 && size.ws_col > 20)
    return size.ws_col;
  return 80;
}

std::string first_line(const std::string& text)
{
  return text.substr(0, text.find('\n'));
}
} // namespace

std::string clock_text(double seconds)
{
  const long s = std::lround(std::max(0.0, seconds));
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60) : fmt::format("{}:{:02}", s / 60, s % 60);
}

BatchProgress::BatchProgress(std::size_t to_run, std::FILE* stream)
    : stream_(stream), interactive_(isatty(fileno(stream))), to_run_(to_run), start_(std::chrono::steady_clock::now()),
      printed_(start_)
{
}

void BatchProgress::started(const std::string& name)
{
  running_[name] = std::chrono::steady_clock::now();
  draw();
}

void BatchProgress::finished(const CaseOutcome& outcome)
{
  running_.erase(outcome.name);
  ++done_;
  if (outcome.status == CaseStatus::failed)
    ++failed_;
  std::string line = fmt::format("[{}/{}] {:<11} {} ({:.1f} s)", done_, to_run_, status_name(outcome.status),
                                 outcome.name, outcome.wall_s);
  if (!outcome.message.empty())
    line += ": " + first_line(outcome.message);
  note(line);
}

void BatchProgress::note(const std::string& line)
{
  clear();
  fmt::print(stream_, "{}\n", line);
  std::fflush(stream_);
  printed_ = std::chrono::steady_clock::now();
  draw();
}

void BatchProgress::refresh()
{
  const auto now = std::chrono::steady_clock::now();
  if (interactive_ && now - drawn_ > std::chrono::milliseconds(250))
    draw();
  if (!interactive_ && !running_.empty() && now - printed_ >= progress_interval)
    note(fmt::format("[{}/{}] running     {}; {} elapsed", done_, to_run_, running_cases(now),
                     clock_text(std::chrono::duration<double>(now - start_).count())));
}

std::string BatchProgress::running_cases(std::chrono::steady_clock::time_point now) const
{
  std::string text;
  for (const auto& [name, started] : running_)
    text += fmt::format("{}{} ({})", text.empty() ? "" : ", ", name,
                        clock_text(std::chrono::duration<double>(now - started).count()));
  return text.empty() ? "-" : text;
}

void BatchProgress::close()
{
  clear();
  interactive_ = false;
}

void BatchProgress::clear()
{
  if (interactive_)
    fmt::print(stream_, "\r\033[K");
}

void BatchProgress::draw()
{
  if (!interactive_ || to_run_ == 0)
    return;
  drawn_ = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(drawn_ - start_).count();
  // The ETA assumes the cases left cost what the finished ones did.
  const std::string eta = done_ == 0 ? "--" : clock_text(elapsed / done_ * (to_run_ - done_));
  constexpr int bar_width = 24;
  const int filled = static_cast<int>(bar_width * done_ / to_run_);
  std::string line = fmt::format("[{}{}] {}/{}{}  {} elapsed, ETA {}  running: {}", std::string(filled, '#'),
                                 std::string(bar_width - filled, '.'), done_, to_run_,
                                 failed_ ? fmt::format(" ({} failed)", failed_) : "", clock_text(elapsed), eta,
                                 running_cases(drawn_));
  const std::size_t width = static_cast<std::size_t>(terminal_width(stream_) - 1);
  if (line.size() > width)
    line = line.substr(0, width - 3) + "...";
  fmt::print(stream_, "\r\033[K{}", line);
  std::fflush(stream_);
}

void print_batch_table(const BatchResult& result, std::FILE* stream)
{
  std::size_t name_width = 4, kind_width = 4;
  for (const CaseOutcome& c : result.outcomes)
  {
    name_width = std::max(name_width, c.name.size());
    kind_width = std::max(kind_width, c.kind.size());
  }
  fmt::print(stream, "{:<{}}  {:<{}}  {:<11}  {:>8}  {}\n", "case", name_width, "kind", kind_width, "status", "wall s",
             "message");
  for (const CaseOutcome& c : result.outcomes)
  {
    const bool timed = c.status == CaseStatus::ok || c.status == CaseStatus::skipped || c.wall_s > 0;
    fmt::print(stream, "{:<{}}  {:<{}}  {:<11}  {:>8}  {}\n", c.name, name_width, c.kind.empty() ? "-" : c.kind,
               kind_width, status_name(c.status), timed ? fmt::format("{:.2f}", c.wall_s) : "-",
               first_line(c.message));
  }
  fmt::print(stream, "{} case(s): {} computed, {} skipped (done earlier), {} failed{}{}; {} rank(s) x {} worker(s), "
                     "{:.1f} s\n",
             result.outcomes.size(), result.count(CaseStatus::ok), result.count(CaseStatus::skipped),
             result.count(CaseStatus::failed),
             result.count(CaseStatus::interrupted) ? fmt::format(", {} interrupted", result.count(CaseStatus::interrupted)) : "",
             result.count(CaseStatus::not_run) ? fmt::format(", {} not run", result.count(CaseStatus::not_run)) : "",
             result.ranks, result.jobs, result.wall_s);
  if (!result.store.empty())
    fmt::print(stream, "store: {}\n", result.store.string());
}
} // namespace rollcheck::io
