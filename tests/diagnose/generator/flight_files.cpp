#include "flight_files.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <system_error>

#include "common/atomic_file.hpp"
#include "common/commands.hpp"

namespace aloft::generator {
namespace {

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

nlohmann::json spec_to_json(const FlightSpec& s) {
  return {{"body", s.body},
          {"effect", s.effect},
          {"data", to_string(s.data)},
          {"duration_s", s.duration_s},
          {"imu_rate_hz", s.imu_rate_hz},
          {"gyro_noise_rad_s", s.gyro_noise_rad_s},
          {"accelerometer", s.accelerometer},
          {"accel_noise_m_s2", s.accel_noise_m_s2},
          {"marker_rate_hz", s.marker_rate_hz},
          {"marker_noise_m", s.marker_noise_m},
          {"occlusions", s.occlusions},
          {"impulse_duration_s", s.impulse_duration_s}};
}

}  // namespace

void write_imu_csv(std::ostream& out, const host::ImuLog& log) {
  const bool accel = !log.accel_m_s2.empty(), rotor = !log.rotor_rad_s.empty();
  out << (accel ? "t,gx,gy,gz,ax,ay,az" : "t,gx,gy,gz") << (rotor ? ",rotor_rad_s\n" : "\n");
  for (std::size_t k = 0; k < log.time_s.size(); ++k) {
    out << fixed(log.time_s[k], 6);
    for (int i = 0; i < 3; ++i) out << ',' << fixed(log.gyro_rad_s[k](i), 6);
    if (accel) {
      for (int i = 0; i < 3; ++i) out << ',' << fixed(log.accel_m_s2[k](i), 6);
    }
    if (rotor) out << ',' << fixed(log.rotor_rad_s[k], 6);
    out << '\n';
  }
}

void write_trc(std::ostream& out, const host::MarkerTrial& trial, const std::string& file_name) {
  const std::size_t frames = trial.time_s.size();
  const std::size_t markers = trial.marker_names.size();
  const std::string rate = fixed(trial.rate_hz, 2);
  out << "PathFileType\t4\t(X/Y/Z)\t" << file_name << '\n';
  out << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\t"
         "OrigDataStartFrame\tOrigNumFrames\n";
  out << rate << '\t' << rate << '\t' << frames << '\t' << markers << "\tmm\t" << rate << "\t1\t" << frames
      << '\n';
  out << "Frame#\tTime";
  for (const auto& name : trial.marker_names) out << '\t' << name << "\t\t";
  out << "\n\t";
  for (std::size_t i = 1; i <= markers; ++i) out << "\tX" << i << "\tY" << i << "\tZ" << i;
  out << "\n\n";
  for (std::size_t k = 0; k < frames; ++k) {
    out << (k + 1) << '\t' << fixed(trial.time_s[k], 5);
    for (std::size_t i = 0; i < markers; ++i) {
      const Eigen::Vector3d& p = trial.positions_m[k][i];
      for (int c = 0; c < 3; ++c) {
        out << '\t';
        if (std::isfinite(p(c))) out << fixed(p(c) * 1000.0, 4);  // empty cell: occluded
      }
    }
    out << '\n';
  }
}

std::string write_flight(const GeneratedFlight& flight, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw host::Error(dir + ": cannot create directory: " + ec.message());
  const std::filesystem::path folder(dir);
  host::write_file_atomically((folder / "body.json").string(),
                              [&](std::ostream& out) { out << flight.body_json; });
  std::string data_file;
  if (flight.spec.data == DataKind::imu) {
    data_file = "imu.csv";
    host::write_file_atomically((folder / data_file).string(),
                                [&](std::ostream& out) { write_imu_csv(out, flight.imu); });
  } else {
    data_file = "markers.trc";
    host::write_file_atomically((folder / data_file).string(),
                                [&](std::ostream& out) { write_trc(out, flight.markers, data_file); });
  }
  nlohmann::json truth = truth_to_json(flight.truth);
  truth["seed"] = flight.seed;
  truth["spec"] = spec_to_json(flight.spec);
  host::write_file_atomically((folder / "truth.json").string(),
                              [&](std::ostream& out) { out << truth.dump(1) << '\n'; });
  return data_file;
}

std::string segment_row(const host::Segment& s) {
  char line[200];
  std::snprintf(line, sizeof line, "%s,%.6f,%.6f,true,%s\n", s.name.c_str(), s.start_s, s.end_s,
                s.comment.c_str());
  return line;
}

}  // namespace aloft::generator
