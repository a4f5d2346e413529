// Warnings: input that aloft reads anyway, but that a user should know about. One line
// each on stderr, "aloft: warning: FILE: what". Tests capture them instead
// (WarningCapture), so that a warning is part of a reader's checked behaviour.
#pragma once

#include <string>
#include <vector>

namespace aloft::host {

// Prints "aloft: warning: <message>" on stderr, or records it while a WarningCapture lives.
void warn(const std::string& message);

// While alive, warnings on this thread are collected here instead of printed.
class WarningCapture {
 public:
  WarningCapture();
  ~WarningCapture();
  WarningCapture(const WarningCapture&) = delete;
  WarningCapture& operator=(const WarningCapture&) = delete;
  const std::vector<std::string>& messages() const { return messages_; }
  // True when some captured warning holds `fragment`.
  bool contains(const std::string& fragment) const;

 private:
  friend void warn(const std::string& message);
  std::vector<std::string> messages_;
  WarningCapture* previous_;
};

}  // namespace aloft::host
