// simulate, deviation_angle and read_imu: the core's flight and deviation angle, and the
// IMU reader, on NumPy arrays.
#include <string>
#include <utility>
#include <vector>

#include "aloft/dynamics/deviation.hpp"
#include "common/body_file.hpp"
#include "common/commands.hpp"
#include "common/warning.hpp"
#include "python/command_line.hpp"
#include "python/functions.hpp"
#include "python/python_warnings.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/imu_units.hpp"
#include "simulate/trajectory.hpp"

namespace py = pybind11;

namespace aloft::host::python {
namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

void require_size(const InputArray& a, py::ssize_t size, const std::string& name) {
  if (a.ndim() != 1 || a.shape(0) != size) {
    throw Error(name + ": expected " + std::to_string(size) + " numbers, got an array of shape " +
                shape_text(a));
  }
}

}  // namespace

py::dict simulate(py::handle body, const InputArray& w0, double duration, double rate, const InputArray& q0,
                  py::handle integrator, bool single_precision) {
  std::string body_json;
  const std::string source = body_argument(body, &body_json);
  require_size(w0, 3, "w0");
  require_size(q0, 4, "q0");
  const std::string integrator_name = integrator.is_none() ? "rk4" : py::cast<std::string>(integrator);
  std::vector<std::string> warnings;
  const Body read = [&] {
    const WarningCapture capture;
    Body b = read_body(source, body_json);
    warnings = capture.messages();
    return b;
  }();
  raise_python_warnings(warnings);
  const TrajectoryRequest request = simulate_request(Eigen::Vector3d(w0.at(0), w0.at(1), w0.at(2)),
                                                     Eigen::Vector4d(q0.at(0), q0.at(1), q0.at(2), q0.at(3)),
                                                     duration, rate, integrator_name, single_precision);
  std::vector<TrajectorySample> samples;
  {
    const py::gil_scoped_release without_gil;
    samples = simulate_trajectory(read.inertia, request);
  }
  // The samples hold a quaternion stored x, y, z, w: copied once into the arrays' layout.
  const auto n = static_cast<py::ssize_t>(samples.size());
  py::array_t<double> t(n), q({n, py::ssize_t{4}}), w({n, py::ssize_t{3}});
  auto tv = t.mutable_unchecked<1>();
  auto qv = q.mutable_unchecked<2>();
  auto wv = w.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const TrajectorySample& s = samples[static_cast<std::size_t>(i)];
    tv(i) = s.t_s;
    const Eigen::Quaterniond& r = s.state.orientation;
    qv(i, 0) = r.w(), qv(i, 1) = r.x(), qv(i, 2) = r.y(), qv(i, 3) = r.z();
    for (py::ssize_t k = 0; k < 3; ++k) wv(i, k) = s.state.omega_body[k];
  }
  py::dict out;
  out["t"] = t;
  out["q"] = q;
  out["w"] = w;
  return out;
}

py::array_t<double> deviation_angle(const InputArray& w_measured, const InputArray& w_simulated) {
  bool same_shape = w_measured.ndim() == w_simulated.ndim();
  for (py::ssize_t i = 0; same_shape && i < w_measured.ndim(); ++i) {
    same_shape = w_measured.shape(i) == w_simulated.shape(i);
  }
  const py::ssize_t dims = w_measured.ndim();
  if (!same_shape || dims < 1 || dims > 2 || w_measured.shape(dims - 1) != 3) {
    throw Error(
        "deviation_angle: w_measured and w_simulated must be arrays of the same shape, (N, 3) or (3,); got " +
        shape_text(w_measured) + " and " + shape_text(w_simulated));
  }
  const py::ssize_t n = w_measured.ndim() == 2 ? w_measured.shape(0) : 1;
  std::vector<py::ssize_t> shape;
  if (w_measured.ndim() == 2) shape.push_back(n);
  py::array_t<double> angles(shape);
  const double* measured = w_measured.data();
  const double* simulated = w_simulated.data();
  double* out = angles.mutable_data();
  {
    const py::gil_scoped_release without_gil;
    for (py::ssize_t i = 0; i < n; ++i) {
      const Eigen::Map<const Eigen::Vector3d> m(measured + 3 * i), s(simulated + 3 * i);
      // In the order the reports' statistics take it (aloft/dynamics/deviation.hpp).
      out[i] = aloft::deviation_angle<double>(s, m);
    }
  }
  return angles;
}

py::dict read_imu(py::handle path, const py::kwargs& units) {
  ImuUnits imu_units;
  CommandLine line("read_imu");
  add_imu_unit_options(line.command(), imu_units);
  line.add_options(units);
  line.parse();
  const std::string file = path_text(path);
  std::vector<std::string> warnings;
  ImuLog log = [&] {
    const WarningCapture capture;
    ImuLog read = read_imu_csv(file);
    warnings = capture.messages();
    return read;
  }();
  raise_python_warnings(warnings);
  convert_to_si(log, imu_units);
  py::dict out;
  out["t"] = numpy_vector(std::move(log.time_s));
  out["gyro"] = numpy_rows(std::move(log.gyro_rad_s));
  if (!log.accel_m_s2.empty()) out["accel"] = numpy_rows(std::move(log.accel_m_s2));
  return out;
}

}  // namespace aloft::host::python
