#include "long_session_log.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>

#include "common/atomic_file.hpp"
#include "flight_files.hpp"
#include "seeded_random.hpp"

namespace aloft::generator {

LongSessionLog make_long_session_log(const LongSessionSpec& spec, std::uint64_t seed) {
  LongSessionLog session;
  SeededRandom rest_noise(seed ^ 0x5eed5eedull);
  std::int64_t tick = 0;  // the log's 1 kHz clock, in samples
  constexpr double kRate = 1000.0;
  const auto append = [&](const Eigen::Vector3d& gyro) {
    session.log.time_s.push_back(static_cast<double>(tick++) / kRate);
    session.log.gyro_rad_s.push_back(gyro);
  };
  for (int i = 0; i < spec.flights; ++i) {
    FlightSpec flight_spec;
    flight_spec.body = spec.body;
    flight_spec.effect = spec.effect;
    flight_spec.duration_s = spec.flight_s;
    const GeneratedFlight flight = generate_flight(flight_spec, seed + static_cast<std::uint64_t>(i));
    if (i == 0) {
      session.body = flight.body;
      session.body_json = flight.body_json;
    }
    const double noise = flight_spec.gyro_noise_rad_s;
    for (int k = 0; k < static_cast<int>(std::lround(spec.rest_s * kRate)); ++k)
      append(rest_noise.normal_vector(noise));
    host::Segment segment;
    segment.name = "throw" + std::to_string(i + 1);
    segment.start_s = static_cast<double>(tick) / kRate;
    for (const Eigen::Vector3d& gyro : flight.imu.gyro_rad_s) append(gyro);
    segment.end_s = static_cast<double>(tick - 1) / kRate;
    session.segments.push_back(segment);
  }
  session.log.format = "imu_csv";
  return session;
}

void write_long_session_log(const LongSessionLog& session, const std::string& dir) {
  const std::filesystem::path folder(dir);
  std::filesystem::create_directories(folder);
  host::write_file_atomically((folder / "body.json").string(),
                              [&](std::ostream& out) { out << session.body_json; });
  host::write_file_atomically((folder / "imu.csv").string(),
                              [&](std::ostream& out) { write_imu_csv(out, session.log); });
  host::write_file_atomically((folder / "segments.csv").string(), [&](std::ostream& out) {
    out << "segment,start,end,keep,comment\n" << std::fixed << std::setprecision(6);
    for (const host::Segment& s : session.segments)
      out << s.name << ',' << s.start_s << ',' << s.end_s << ",true,\n";
  });
}

}  // namespace aloft::generator
