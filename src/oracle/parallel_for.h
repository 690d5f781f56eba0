#pragma once
// Runs body(i) for i in [0, n) on `threads` std::threads (0: one per core),
// items handed out one at a time so that slow items do not hold up a thread's
// share. The first exception thrown by any body is rethrown after all threads
// have stopped; items not started by then are skipped.
#include <cstddef>
#include <functional>

namespace rollcheck::oracle
{
void parallel_for(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& body);

/// The thread count parallel_for uses for `requested` (0: hardware concurrency, at least 1).
unsigned thread_count(unsigned requested);
} // namespace rollcheck::oracle
