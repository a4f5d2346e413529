#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "common/parallel_for.hpp"

using aloft::host::parallel_for;
using aloft::host::ParallelProgress;

TEST_CASE("parallel_for runs every index exactly once", "[common][parallel_for]") {
  for (unsigned threads : {1u, 2u, 4u, 16u}) {
    INFO(threads << " threads");
    std::vector<std::atomic<int>> runs(1000);
    parallel_for(runs.size(), threads, [&](std::size_t i) { ++runs[i]; });
    for (const auto& r : runs) CHECK(r.load() == 1);
  }
  int calls = 0;
  parallel_for(0, 4, [&](std::size_t) { ++calls; });
  CHECK(calls == 0);
}

TEST_CASE("a worker's exception reaches the caller", "[common][parallel_for]") {
  for (bool with_progress : {false, true}) {
    INFO("progress " << with_progress);
    std::atomic<int> calls{0};
    ParallelProgress progress;
    if (with_progress) progress.report = [](std::size_t, std::size_t) {};
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<bool> thrown_off_caller{false};
    const auto body = [&](std::size_t i) {
      ++calls;
      // Work that takes a little time, so that a hand-out that went on after the throw
      // (slow under the sanitizers) would run every index rather than stop.
      if (i > 17) std::this_thread::sleep_for(std::chrono::microseconds(20));
      if (i == 17) {
        thrown_off_caller = std::this_thread::get_id() != caller;
        throw std::runtime_error("flight 17: bad sample");
      }
    };
    CHECK_THROWS_WITH(parallel_for(100000, 4, body, progress), "flight 17: bad sample");
    // The failure stops the hand-out: far fewer than all indices ran.
    CHECK(calls.load() < 100000);
    if (with_progress) CHECK(thrown_off_caller.load());  // thrown on a worker thread
  }
}

TEST_CASE("progress is reported and ends at the total", "[common][parallel_for]") {
  std::size_t last_done = 0, last_total = 0;
  ParallelProgress progress;
  progress.report = [&](std::size_t done, std::size_t total) {
    CHECK(done <= total);
    last_done = done;
    last_total = total;
  };
  parallel_for(
      64, 2, [](std::size_t) { std::this_thread::sleep_for(std::chrono::milliseconds(2)); }, progress);
  CHECK(last_done == 64);
  CHECK(last_total == 64);
}
