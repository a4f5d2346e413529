// aloft's errors as Python's: a file that cannot be opened or read (FileError) raises
// OSError, or its subclass for errno (FileNotFoundError, PermissionError,
// IsADirectoryError), with `errno` set; any other Error, bad input, raises ValueError. The
// message is the one the command prints. Other C++ exceptions are left to pybind11's own
// translation (MemoryError, RuntimeError, ...): none ends the interpreter.
#pragma once

namespace aloft::host::python {

void register_error_translation();

}  // namespace aloft::host::python
