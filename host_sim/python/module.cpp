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

void add_report_functions(py::module_& m) {
  m.def("diagnose", &diagnose, py::arg("body"), py::arg("imu") = py::none(), py::arg("markers") = py::none(),
        py::arg("poses") = py::none(), py::arg("segments") = py::none(),
        R"(`aloft diagnose`: why simulation and measurement part. Returns its --json report.

Exactly one of imu, markers, poses; segments (or window="A:B") with imu. Options as the command's:
window, time_units, gyro_units, accel_units, pose_columns, pose_sequence, osim, joint, threads,
json, plot, corrected_body (the last three write files, as the command does).
Runs without the GIL; Ctrl-C stops a session's diagnosis (KeyboardInterrupt, nothing written).)");
  m.def("replay", &replay, py::arg("body"), py::arg("imu") = py::none(), py::arg("fifo") = py::none(),
        py::arg("odr_hz") = py::none(),
        R"(`aloft replay`: the firmware's onboard pipeline on a recording. Returns its --json report.

imu: plain IMU log with ax, ay, az; or fifo: ICM-42688-P FIFO bytes with odr_hz. Unit options as the command's.)");
  m.def("records", &records, py::arg("dump"),
        R"(`aloft records DUMP --json`: the flights in a dump of the flight-record area.)");
  m.def("study", &study, py::arg("body") = py::none(), py::arg("imu") = py::none(),
        py::arg("markers") = py::none(), py::arg("poses") = py::none(), py::arg("segments") = py::none(),
        py::arg("seed") = 1, py::arg("mc_samples") = py::none(), py::arg("threads") = py::none(),
        py::arg("out") = py::none(),
        R"(`aloft study`: the paper's study, on the built-in throw or a recording. Returns results.json.

out: also write the output folder (results.json, rms_da.csv, experiment.csv, figure.svg, figure.png)
as the command does; None (default) writes nothing. Other options as the command's (frame, throw, ...).
Runs without the GIL; Ctrl-C stops it (KeyboardInterrupt, nothing written).)");
  m.def("inspect", &inspect, py::arg("path"), py::arg("body") = py::none(),
        R"(`aloft inspect`: the summary of a trial file (markers, poses, IMU log, segments).)");
}

}  // namespace

PYBIND11_MODULE(aloft, m) {
  m.doc() = kModuleDoc;
  register_error_translation();
  add_array_functions(m);
  add_report_functions(m);
}
