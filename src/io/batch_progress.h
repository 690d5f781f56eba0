#pragma once
// What a batch shows while it runs and when it ends. On a terminal: one
// status line per finished case above a progress bar with the running cases,
// the elapsed time and an ETA. Otherwise (a log file, a pipe, mpirun's
// forwarding): the status lines, and while cases run, a line of the running
// cases and their elapsed times whenever nothing was printed for
// progress_interval, so that a batch is never silent for longer.
#include "io/batch_run.h"
#include <chrono>
#include <cstdio>
#include <map>
#include <string>

namespace rollcheck::io
{
/// The longest a batch stays silent while cases run (issue: every long phase
/// shows progress at least every 10 s).
inline constexpr std::chrono::seconds progress_interval{5};

class BatchProgress
{
public:
  /// `to_run`: cases this batch computes; `stream`: where to write (stderr).
  BatchProgress(std::size_t to_run, std::FILE* stream);
  void started(const std::string& name);
  /// A computed case ended (ok, failed or interrupted).
  void finished(const CaseOutcome& outcome);
  /// A line that is not a computed case (a skipped or unresolvable case).
  void note(const std::string& line);
  /// Redraws the bar, at most 4 times a second; not on a terminal, prints
  /// the running cases after progress_interval of silence.
  void refresh();
  /// Clears the bar.
  void close();

private:
  void draw();
  void clear();
  /// "a (0:42), b (0:03)", or "-".
  std::string running_cases(std::chrono::steady_clock::time_point now) const;
  std::FILE* stream_;
  bool interactive_;
  std::size_t to_run_, done_ = 0, failed_ = 0;
  std::map<std::string, std::chrono::steady_clock::time_point> running_; ///< name, start
  std::chrono::steady_clock::time_point start_, drawn_{}, printed_;
};

/// The table of every case (name, kind, status, wall time, message) and a
/// totals line.
void print_batch_table(const BatchResult& result, std::FILE* stream);

/// 75 -> "1:15", 3725 -> "1:02:05".
std::string clock_text(double seconds);
} // namespace rollcheck::io
