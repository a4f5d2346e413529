#include "python/python_warnings.hpp"

#include <pybind11/pybind11.h>

namespace aloft::host::python {

void raise_python_warnings(const std::vector<std::string>& messages) {
  for (const std::string& message : messages) {
    if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) throw pybind11::error_already_set();
  }
}

}  // namespace aloft::host::python
