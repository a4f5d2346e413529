// A float result as the shortest decimal that reads back as the same float (0.031, not
// 0.03099999949336052): what the firmware holds, without double's extra digits. For the
// JSON reports of figures the pipeline computes in float (replay, records).
#pragma once

#include <charconv>
#include <cstdlib>
#include <string>

namespace aloft::host {

inline double shortest_decimal(float value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof(text), value);
  return error == std::errc() ? std::strtod(std::string(text, end).c_str(), nullptr)
                              : static_cast<double>(value);
}

}  // namespace aloft::host
