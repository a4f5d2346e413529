#include "common/stop_request.hpp"

namespace aloft::host {
namespace {
thread_local const std::atomic<bool>* t_stop_flag = nullptr;
}

StopScope::StopScope(const std::atomic<bool>* flag) : previous_(t_stop_flag) { t_stop_flag = flag; }
StopScope::~StopScope() { t_stop_flag = previous_; }

const std::atomic<bool>* stop_flag() { return t_stop_flag; }

void stop_if_requested() {
  if (t_stop_flag != nullptr && t_stop_flag->load(std::memory_order_relaxed)) throw Stopped();
}

}  // namespace aloft::host
