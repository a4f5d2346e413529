#include "python/python_errors.hpp"

#include <pybind11/pybind11.h>

#include <cerrno>
#include <exception>

#include "common/commands.hpp"

namespace py = pybind11;

namespace aloft::host::python {
namespace {

PyObject* os_error_type(int error_number) {
  switch (error_number) {
    case ENOENT: return PyExc_FileNotFoundError;
    case EACCES:
    case EPERM: return PyExc_PermissionError;
    case EISDIR: return PyExc_IsADirectoryError;
    default: return PyExc_OSError;
  }
}

// OSError(message) with `errno` set afterwards: str() of it is then the message alone
// (OSError formats "[Errno N] ..." only when built with errno and strerror).
void raise_os_error(const FileError& e) {
  PyObject* type = os_error_type(e.error_number);
  py::object error = py::reinterpret_borrow<py::object>(type)(e.what());
  if (e.error_number != 0) error.attr("errno") = e.error_number;
  PyErr_SetObject(type, error.ptr());
}

}  // namespace

void register_error_translation() {
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const FileError& e) {
      raise_os_error(e);
    } catch (const Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace aloft::host::python
