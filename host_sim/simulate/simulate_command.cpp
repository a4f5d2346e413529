// `aloft simulate` (SPEC §5): one torque-free flight from a given initial state,
// written as CSV t,qw,qx,qy,qz,wx,wy,wz (omega in body axes), one row per sample.
#include <charconv>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/body_file.hpp"
#include "common/commands.hpp"
#include "common/option_checks.hpp"
#include "simulate/trajectory.hpp"

namespace aloft::host {
namespace {

std::vector<double> parse_numbers(const std::string& text, std::size_t count, const std::string& option) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string cell;
  while (std::getline(in, cell, ',')) {
    try {
      std::size_t used = 0;
      values.push_back(std::stod(cell, &used));
      if (used != cell.size()) throw std::invalid_argument(cell);
    } catch (const std::exception&) {
      throw Error(option + ": \"" + cell + "\" is not a number");
    }
  }
  if (values.size() != count) {
    throw Error(option + ": expected " + std::to_string(count) + " comma-separated numbers, got " +
                std::to_string(values.size()));
  }
  return values;
}

// The shortest text that reads back as the same number, so 0.005 is written "0.005", not
// "0.0050000000000000001"; a single-precision result is written at float's precision.
template <typename Number>
std::string shortest(Number value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof(text), value);
  return std::string(text, error == std::errc() ? end : text);
}

struct SimulateOptions {
  std::string body_path;
  std::string w0 = "";
  std::string q0 = "1,0,0,0";
  double duration_s = 0.0;
  double rate_hz = 0.0;
  std::string integrator = "rk4";
  bool single_precision = false;
  std::string out_path;
};

void run_simulate(const SimulateOptions& o) {
  const Body body = read_body_file(o.body_path);
  const std::vector<double> w = parse_numbers(o.w0, 3, "--w0");
  const std::vector<double> q = parse_numbers(o.q0, 4, "--q0");
  const TrajectoryRequest request =
      simulate_request(Eigen::Vector3d(w[0], w[1], w[2]), Eigen::Vector4d(q[0], q[1], q[2], q[3]),
                       o.duration_s, o.rate_hz, o.integrator, o.single_precision);
  const std::vector<TrajectorySample> samples = simulate_trajectory(body.inertia, request);
  write_file_atomically(o.out_path, [&](std::ostream& out) {
    out << "t,qw,qx,qy,qz,wx,wy,wz\n";
    const auto state_cell = [&](double v) {
      return o.single_precision ? shortest(static_cast<float>(v)) : shortest(v);
    };
    for (const TrajectorySample& s : samples) {
      const auto& r = s.state.orientation;
      const auto& v = s.state.omega_body;
      out << shortest(s.t_s);
      for (const double cell : {r.w(), r.x(), r.y(), r.z(), v.x(), v.y(), v.z()}) {
        out << ',' << state_cell(cell);
      }
      out << '\n';
    }
  });
  std::fprintf(stderr, "aloft simulate: %zu samples written to %s\n", samples.size(), o.out_path.c_str());
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "simulate one torque-free flight and write t,qw,qx,qy,qz,wx,wy,wz (quaternion w first)");
  cmd->add_option("--body", options->body_path, "body file (JSON: docs/file-formats.md)")->required();
  cmd->add_option("--w0", options->w0, "initial angular velocity in body axes, rad/s: wx,wy,wz")->required();
  cmd->add_option("--q0", options->q0,
                  "initial orientation body->world: w,x,y,z (scalar first; scipy's as_quat() gives x,y,z,w)")
      ->capture_default_str();
  cmd->add_option("--duration", options->duration_s, "flight duration, s")->required();
  cmd->add_option("--rate", options->rate_hz, "output sample rate, Hz (internal steps <= 1 ms)")->required();
  cmd->add_option("--integrator", options->integrator, "rk4 or splitting (4th-order Lie splitting)")
      ->capture_default_str()
      ->check(CLI::IsMember({"rk4", "splitting"}));
  cmd->add_flag("--float", options->single_precision, "integrate in single precision");
  cmd->add_option("--out", options->out_path, "output CSV")->required()->check(output_file());
  cmd->callback([options] { run_simulate(*options); });
}

}  // namespace aloft::host
