// Asking long work to stop early: the Python module's answer to Ctrl-C in the middle of
// `aloft.study` or a session's `aloft.diagnose`. The caller installs a flag for its
// thread (StopScope); parallel_for hands the flag on to the threads it starts and checks
// it before each index it hands out, so every parallel loop of the study and of a
// diagnosis is a point where the work ends, by throwing Stopped, which unwinds like any
// error: nothing is written, since the commands write only once all is computed. The
// command line installs no flag, and then nothing here ever stops.
#pragma once

#include <atomic>
#include <exception>

namespace aloft::host {

// Thrown where a stop was asked for; not an Error, so no command prints it as a message.
struct Stopped : std::exception {
  const char* what() const noexcept override { return "stopped on request"; }
};

// While it lives, `flag` (set from another thread) asks this thread's work to stop.
class StopScope {
 public:
  explicit StopScope(const std::atomic<bool>* flag);
  ~StopScope();
  StopScope(const StopScope&) = delete;
  StopScope& operator=(const StopScope&) = delete;

 private:
  const std::atomic<bool>* previous_;
};

// This thread's flag (null where none is installed).
const std::atomic<bool>* stop_flag();

// Throws Stopped if this thread's flag is set.
void stop_if_requested();

}  // namespace aloft::host
