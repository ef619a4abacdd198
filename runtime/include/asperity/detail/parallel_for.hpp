// Jobs on a few threads, for the offline work (table generation, bootstraps, scene tables):
// never on the hot path. Internal: the one pool the generator and the surface analysis share.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "asperity/interrupt.hpp"

namespace asperity::detail {

// Runs job(i) for every i < count on up to `threads` threads (0 or less: the hardware's), the
// calling thread among them. Jobs are handed out one at a time, so any number of threads gives
// the same results when each job writes only its own output. A thread the system refuses (a
// memory or process limit: `--threads 4096`) is not an error: the threads that did start do its
// share. The first exception a job throws stops the hand-out and is rethrown once every thread
// has stopped. The workers see the caller's InterruptScope (asperity/interrupt.hpp), and each
// job starts with poll_interrupt(): a stop asked ends the hand-out like an exception.
template <class Job>
void parallel_for(std::size_t count, int threads, Job&& job) {
  if (count == 0) return;
  std::size_t wanted = threads > 0 ? static_cast<std::size_t>(threads) : std::max(1u, std::thread::hardware_concurrency());
  wanted = std::min(wanted, count);
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  InterruptScope::State* const interrupt = current_interrupt_state();
  std::size_t running = 0;  // pool threads not yet out of their loop (under finished_mutex)
  std::mutex finished_mutex;
  std::condition_variable finished;
  const auto worker = [&] {
    const InheritInterrupt inherit(interrupt);
    for (;;) {
      const std::size_t index = next.fetch_add(1);
      if (index >= count) break;
      try {
        poll_interrupt();
        job(index);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next.store(count);
        break;
      }
    }
  };
  const auto pool_worker = [&] {
    worker();
    {
      std::lock_guard<std::mutex> lock(finished_mutex);
      --running;
    }
    finished.notify_all();
  };
  std::vector<std::thread> pool;
  try {
    pool.reserve(wanted - 1);
    for (std::size_t t = 1; t < wanted; ++t) {
      {
        std::lock_guard<std::mutex> lock(finished_mutex);
        ++running;
      }
      try {
        pool.emplace_back(pool_worker);
      } catch (...) {
        std::lock_guard<std::mutex> lock(finished_mutex);
        --running;
        throw;
      }
    }
  } catch (const std::system_error&) {  // no more threads: those started and this one suffice
  } catch (const std::bad_alloc&) {
  }
  worker();
  // Only the scope's own thread may ask its check: while the pool finishes its last jobs, this
  // thread keeps asking, so that a stop reaches them (their next poll) within the check's interval.
  if (interrupt) {
    std::unique_lock<std::mutex> lock(finished_mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(5), [&] { return running == 0; })) {
      lock.unlock();
      const bool stop = interrupt_requested();  // sets the flag the pool's next poll reads
      lock.lock();
      if (stop) break;
    }
  }
  for (std::thread& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace asperity::detail
