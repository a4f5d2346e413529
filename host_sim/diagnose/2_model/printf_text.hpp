// printf-style formatting of numbers into a std::string, for the report's and the bars'
// short sentences (each under a line, so a fixed buffer is enough). Every value is passed
// as a double, so formats use %f, %g or %e whatever the value's type (a count too).
#pragma once

#include <cstdio>
#include <string>

namespace aloft::host::diagnose {

template <typename... Values>
std::string printf_text(const char* format, Values... values) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, format, static_cast<double>(values)...);
  return buffer;
}

}  // namespace aloft::host::diagnose
