#include "common/warning.hpp"

#include <cstdio>

namespace aloft::host {

namespace {
thread_local WarningCapture* active_capture = nullptr;
}  // namespace

void warn(const std::string& message) {
  if (active_capture) {
    active_capture->messages_.push_back(message);
    return;
  }
  std::fprintf(stderr, "aloft: warning: %s\n", message.c_str());
}

WarningCapture::WarningCapture() : previous_(active_capture) { active_capture = this; }

WarningCapture::~WarningCapture() { active_capture = previous_; }

bool WarningCapture::contains(const std::string& fragment) const {
  for (const std::string& m : messages_) {
    if (m.find(fragment) != std::string::npos) return true;
  }
  return false;
}

}  // namespace aloft::host
