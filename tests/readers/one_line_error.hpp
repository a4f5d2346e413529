// Bad input must end in aloft::host::Error with one line that names the file, the line
// or frame, and the problem. error_message_of runs a reader and returns that line.
#pragma once

#include <initializer_list>
#include <string>

#include <catch2/catch.hpp>

#include "common/commands.hpp"

namespace aloft::test {

template <typename Call>
std::string error_message_of(Call&& call) {
  try {
    call();
  } catch (const aloft::host::Error& e) {
    const std::string message = e.what();
    CHECK(message.find('\n') == std::string::npos);
    return message;
  }
  FAIL("expected aloft::host::Error, nothing was thrown");
  return {};
}

}  // namespace aloft::test

// Expects the call to fail with a message holding each of the given fragments.
#define CHECK_ONE_LINE_ERROR(call, ...)                                                    \
  do {                                                                                     \
    const std::string message_ = aloft::test::error_message_of([&] { call; });             \
    for (const std::string& fragment_ : std::initializer_list<std::string>{__VA_ARGS__}) { \
      INFO("message: " << message_);                                                       \
      CHECK(message_.find(fragment_) != std::string::npos);                                \
    }                                                                                      \
  } while (0)
