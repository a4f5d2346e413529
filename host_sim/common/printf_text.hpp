// printf-style formatting into a std::string, for the reports' short sentences and rows (each
// under a line, so a fixed buffer is enough; longer text is cut there). The compiler checks
// the format against the values, as it checks printf's.
#pragma once

#include <string>

namespace aloft::host {

std::string printf_text(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace aloft::host
