// One error type at the boundary where a file is read: whatever a library or the
// standard library throws while a reader works on a file (an allocation that cannot be
// met, a conversion out of range, a parser's own exception) leaves the reader as
// aloft::host::Error naming the file, so the user sees aloft's one line
// "FILE: problem" and exit code 2, never a library's internal message or code.
#pragma once

#include <exception>
#include <new>
#include <string>

#include "common/commands.hpp"

namespace aloft::host {

template <typename Read>
auto with_file_context(const std::string& path, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error(path + ": too large to hold in memory");
  } catch (const std::exception& e) {
    throw Error(path + ": cannot be read (" + std::string(e.what()) + ")");
  }
}

}  // namespace aloft::host
