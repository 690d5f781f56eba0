#pragma once
// How the ranks of a batch talk (batch_run.h has the scheduling): text
// messages over MPI_COMM_WORLD, tagged by what they carry, and the stop
// signal that every loop of the batch checks.
#include <csignal>
#include <optional>
#include <string>

namespace rollcheck::io::batch
{
/// While an object lives, SIGINT and SIGTERM set the stop signal instead of
/// ending the process; the previous handlers come back after.
class StopSignals
{
public:
  StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  ~StopSignals();

private:
  struct sigaction old_int_{}, old_term_{};
};

/// The signal that stopped the batch (SIGINT or SIGTERM), 0 while none has.
int stop_signal();
/// Stops this rank's loops as `signal` would (rank 0 told a worker rank to).
void raise_stop(int signal);

enum Tag
{
  tag_assign = 1, ///< rank 0 -> worker: a job (JSON)
  tag_done = 2,   ///< worker -> rank 0: its outcome (JSON)
  tag_stop = 3    ///< rank 0 -> worker: "done" (no more jobs) or "interrupt"
};

int world_rank();
int world_size();

void send_text(int destination, Tag tag, const std::string& text);

struct Message
{
  int source;
  int tag;
  std::string text;
};

/// A message waiting from `source` (or any), without blocking.
std::optional<Message> receive_text(int source);
} // namespace rollcheck::io::batch
