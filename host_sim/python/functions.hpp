// The module's functions (docs/python.md; SPEC §6), registered with their argument names
// and docstrings in module.cpp.
#pragma once

#include <pybind11/pybind11.h>

#include "python/numpy_arrays.hpp"

namespace aloft::host::python {

// array_functions.cpp: on arrays.
pybind11::dict simulate(pybind11::handle body, const InputArray& w0, double duration, double rate,
                        const InputArray& q0, pybind11::handle integrator, bool single_precision);
pybind11::array_t<double> deviation_angle(const InputArray& w_measured, const InputArray& w_simulated);
pybind11::dict read_imu(pybind11::handle path, const pybind11::kwargs& units);

}  // namespace aloft::host::python
