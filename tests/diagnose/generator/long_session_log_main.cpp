// aloft_long_session_log: writes one long IMU session (long_session_log.hpp) to a folder:
// body.json, imu.csv and segments.csv, ready for `aloft diagnose --segments`.
//
//   aloft_long_session_log --out DIR                 200 throws in 10 minutes at 1 kHz
//   aloft_long_session_log --out DIR --flights 60    60 throws (3 minutes)
#include <CLI/CLI.hpp>
#include <cstdint>
#include <iostream>

#include "common/usage_error.hpp"
#include "long_session_log.hpp"

int main(int argc, char** argv) {
  using namespace aloft::generator;
  CLI::App app{"Write one long IMU log of many throws with rest between, and its segments file."};
  std::string out_dir;
  LongSessionSpec spec;
  std::uint64_t seed = 100;
  app.add_option("--out", out_dir, "folder to write into")->required();
  app.add_option("--flights", spec.flights, "throws in the log (default 200)")->check(CLI::PositiveNumber);
  app.add_option("--effect", spec.effect, "every throw's withheld effect (default aero_torque)");
  app.add_option("--seed", seed, "seed of the first throw (throw i: seed + i)");
  if (const auto code = aloft::host::parse_command_line(app, argc, argv)) return *code;
  try {
    const LongSessionLog session = make_long_session_log(spec, seed);
    write_long_session_log(session, out_dir);
    std::cout << session.segments.size() << " throws, " << session.log.time_s.size() << " samples ("
              << session.log.time_s.back() << " s) written to " << out_dir << "\n";
  } catch (const std::exception& e) {
    std::cerr << "aloft_long_session_log: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
