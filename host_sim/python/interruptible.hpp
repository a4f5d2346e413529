// A long call off the GIL that Ctrl-C stops. The work runs on a thread of its own with a
// stop flag installed (common/stop_request.hpp: checked before each index of every
// parallel loop of the study and the diagnosis); the calling thread waits without the
// GIL and, every kSignalPoll, takes it to run Python's signal handlers. When one raises
// (KeyboardInterrupt), the flag is set, the work is waited for, and the handler's
// exception is raised: nothing has been written, since the commands write only once all
// is computed. Otherwise the work's result is returned, or its exception rethrown here.
// The work's warnings are raised as Python warnings once it is done (python_warnings.hpp).
// The work must not touch Python objects.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <string>
#include <utility>
#include <vector>

#include "common/stop_request.hpp"
#include "common/warning.hpp"
#include "python/python_warnings.hpp"

namespace aloft::host::python {

// How often the waiting thread looks at signals: Ctrl-C is answered within this plus the
// rest of the index in progress, and the checks cost nothing next to the work.
constexpr std::chrono::milliseconds kSignalPoll{50};

template <typename Work>
auto run_interruptible(Work&& work) -> decltype(work()) {
  using Result = decltype(work());
  std::atomic<bool> stop{false};
  std::optional<Result> result;
  std::exception_ptr failure;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::vector<std::string> warnings;
  std::thread worker([&] {
    const StopScope scope(&stop);
    {
      const WarningCapture capture;
      try {
        result.emplace(work());
      } catch (...) {
        failure = std::current_exception();
      }
      warnings = capture.messages();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    done = true;
    finished.notify_one();
  });

  std::optional<pybind11::error_already_set> interrupt;
  {
    const pybind11::gil_scoped_release without_gil;
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, kSignalPoll, [&] { return done; })) {
      if (interrupt) continue;
      lock.unlock();
      {
        const pybind11::gil_scoped_acquire with_gil;
        if (PyErr_CheckSignals() != 0) {
          interrupt.emplace();  // takes the handler's exception
          stop = true;
        }
      }
      lock.lock();
    }
  }
  worker.join();
  if (interrupt) throw std::move(*interrupt);
  raise_python_warnings(warnings);
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

}  // namespace aloft::host::python
