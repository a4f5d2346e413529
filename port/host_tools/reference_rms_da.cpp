// The host's double-precision answer for the example firmware: the same onboard check
// (port/cortex_m/example/check_settings.hpp) on the same flight files, in double. Prints the lines the
// firmware prints, so the comparison test reads both the same way.
//   reference_rms_da BODY.json IMU.csv
#include <cmath>
#include <cstdio>
#include <iostream>

#include "aloft/onboard/onboard_check.hpp"
#include "check_settings.hpp"
#include "flight_files.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: reference_rms_da BODY.json IMU.csv\n";
    return 2;
  }
  try {
    const Eigen::Matrix3d tensor = aloft_example::read_inertia_tensor(argv[1]);
    const auto samples = aloft_example::read_gyro_log(argv[2]);
    aloft::InertiaTensor<double> inertia;
    const aloft::Status made = aloft::InertiaTensor<double>::make_from_tensor(tensor, inertia);
    if (made != aloft::Status::ok) {
      throw std::runtime_error(std::string(argv[1]) + ": " + aloft::describe(made));
    }
    aloft::OnboardCheck<double, aloft_example::live_simulations> check(
        inertia, aloft_example::check_settings<double>());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      // Time stamps as the firmware sees them: whole microseconds.
      const double dt = i == 0 ? 0.0
                               : static_cast<double>(std::llround(samples[i].t_s * 1e6) -
                                                     std::llround(samples[i - 1].t_s * 1e6)) *
                                     1e-6;
      const aloft::Status s = check.update(samples[i].omega_rad_s, dt);
      if (s != aloft::Status::ok) {
        throw std::runtime_error(std::string(argv[2]) + ": sample " + std::to_string(i + 1) + ": " +
                                 aloft::describe(s));
      }
    }
    const double rad_to_deg = 180.0 / 3.14159265358979323846;
    std::printf("samples %u\n", check.airborne_samples());
    std::printf("seeds %u\n", check.seeds_started());
    std::printf("comparisons %u\n", check.overall().count());
    std::printf("rms_da_deg %.6f\n", check.overall().rms_da() * rad_to_deg);
    std::printf("max_da_deg %.6f\n", check.overall().max_da() * rad_to_deg);
    std::printf("rms_rel_err %.6f\n", check.overall().rms_relative_error());
  } catch (const std::exception& e) {
    std::cerr << "reference_rms_da: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
