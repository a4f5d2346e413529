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

// report_functions.cpp: what each command's --json report holds.
pybind11::object diagnose(pybind11::handle body, pybind11::handle imu, pybind11::handle markers,
                          pybind11::handle poses, pybind11::handle segments, const pybind11::kwargs& options);
pybind11::object replay(pybind11::handle body, pybind11::handle imu, pybind11::handle fifo,
                        pybind11::handle odr_hz, const pybind11::kwargs& options);
pybind11::object records(pybind11::handle dump);
pybind11::object study(pybind11::handle body, pybind11::handle imu, pybind11::handle markers,
                       pybind11::handle poses, pybind11::handle segments, pybind11::handle seed,
                       pybind11::handle mc_samples, pybind11::handle threads, pybind11::handle out,
                       const pybind11::kwargs& options);
pybind11::object inspect(pybind11::handle path, pybind11::handle body, const pybind11::kwargs& options);

}  // namespace aloft::host::python
