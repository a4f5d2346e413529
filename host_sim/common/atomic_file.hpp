// Writing output so that nothing is ever half-written: the content goes to a temporary
// file beside the target, and only a complete write is renamed into place.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace aloft::host {

// Calls `write` with a stream to a temporary file next to `path`, then renames it to
// `path`. If `write` throws or the stream fails, the temporary is removed, `path` is
// left as it was, and aloft::host::Error is thrown.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace aloft::host
