// The Python module `aloft` (docs/python.md; SPEC §6).
#include <pybind11/pybind11.h>

#include "python/functions.hpp"
#include "python/python_errors.hpp"

namespace py = pybind11;
using namespace aloft::host::python;

namespace {

constexpr const char* kModuleDoc = R"(aloft: check a rigid body's inertia tensor by throwing it.

Every command of the aloft program as a function, in this process, on paths or on NumPy
arrays. A function that mirrors a command returns what json.loads makes of that command's
--json report (study: of its results.json); the same code builds it. Bad input raises
ValueError, a file that cannot be read OSError, each with the command's message.
Keyword options are the command line's, with _ for - (time_units="ms" is --time-units ms).
A body is a body file's path or a dict of its content. Arrays are float64 and C-contiguous.
Guide: docs/python.md.)";

void add_array_functions(py::module_& m) {
  m.def("simulate", &simulate, py::arg("body"), py::arg("w0"), py::arg("duration"), py::arg("rate"),
        py::arg("q0") = py::make_tuple(1.0, 0.0, 0.0, 0.0), py::arg("integrator") = py::none(),
        py::arg("float") = false,
        R"(One torque-free flight, as `aloft simulate` writes it.

w0: initial omega in body axes, rad/s (3); q0: initial orientation body -> world, w first (4),
of unit length; duration (s) and rate (Hz): samples from t = 0 to duration inclusive;
integrator: "rk4" (default) or "splitting"; float: integrate in single precision.
Returns {"t": (N,), "q": (N, 4) w first, "w": (N, 3) body axes}.)");
  m.def("deviation_angle", &deviation_angle, py::arg("w_measured"), py::arg("w_simulated"),
        R"(The deviation angle between measured and simulated omega, radians in [0, pi].

Both (N, 3) (or (3,)); returns (N,) (or a 0-d array). The core's own angle, as the reports use it.)");
  m.def("read_imu", &read_imu, py::arg("path"),
        R"(An IMU log (plain or phyphox CSV) in SI units, as every command reads it.

Options time_units ("s", "ms", "us"), gyro_units ("rad/s", "deg/s"), accel_units ("m/s2", "g").
Returns {"t": (N,) s, "gyro": (N, 3) rad/s, and "accel": (N, 3) m/s^2 where the log has it}.)");
}

}  // namespace

PYBIND11_MODULE(aloft, m) {
  m.doc() = kModuleDoc;
  register_error_translation();
  add_array_functions(m);
}
