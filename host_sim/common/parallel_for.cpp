#include "common/parallel_for.hpp"

#include "common/stop_request.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace aloft::host {

void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                  const ParallelProgress& progress) {
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  // The caller's stop flag (common/stop_request.hpp) holds in every worker too, so that
  // loops nested in body stop as well.
  const std::atomic<bool>* const stop = stop_flag();
  const auto worker = [&] {
    const StopScope scope(stop);
    try {
      for (std::size_t i = next++; i < count; i = next++) {
        stop_if_requested();
        body(i);
        ++done;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next.store(count);  // hand out nothing more
    }
  };

  const std::size_t wanted = std::max<std::size_t>(1, std::min<std::size_t>(threads, count));
  std::vector<std::thread> pool;
  // With progress to report, the calling thread watches and every worker is a thread.
  const std::size_t spawned = progress.report ? wanted : wanted - 1;
  for (std::size_t t = 0; t < spawned; ++t) pool.emplace_back(worker);
  if (progress.report) {
    while (done.load() < count && next.load() < count) {
      progress.report(done.load(), count);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  } else {
    worker();
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (progress.report) progress.report(count, count);
}

}  // namespace aloft::host
