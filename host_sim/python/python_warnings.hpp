// The commands' warnings (common/warning.hpp: input read anyway, "aloft: warning: ..." on
// stderr) as Python warnings (UserWarning), which a notebook shows beside the cell and
// `warnings` filters: collected on the thread that reads the input, raised on the calling
// thread once the call is done. One raised as an error (-W error) propagates as such.
#pragma once

#include <string>
#include <vector>

namespace aloft::host::python {

void raise_python_warnings(const std::vector<std::string>& messages);

}  // namespace aloft::host::python
