#include "oracle/parallel_for.h"
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rollcheck::oracle
{
unsigned thread_count(unsigned requested)
{
  return requested > 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

void parallel_for(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& body)
{
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  auto work = [&] {
    for (std::size_t i = next++; i < n && !failed; i = next++)
    {
      try
      {
        body(i);
      }
      catch (...)
      {
        std::lock_guard lock(error_mutex);
        if (!first_error)
          first_error = std::current_exception();
        failed = true;
      }
    }
  };
  const unsigned count = std::min<std::size_t>(thread_count(threads), std::max<std::size_t>(n, 1));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < count; ++t)
    pool.emplace_back(work);
  work();
  for (std::thread& t : pool)
    t.join();
  if (first_error)
    std::rethrow_exception(first_error);
}
} // namespace rollcheck::oracle
