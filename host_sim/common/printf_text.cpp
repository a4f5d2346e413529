#include "common/printf_text.hpp"

#include <cstdarg>
#include <cstdio>

namespace aloft::host {

std::string printf_text(const char* format, ...) {
  char buffer[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return buffer;
}

}  // namespace aloft::host
