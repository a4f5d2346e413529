// Stands in for the recorded trial when ../shared/data is absent, so the firmware build
// never depends on it: a torque-free throw of the practice "brick" (the core's RK4 in
// double, ten substeps per sample), sampled at 1 kHz for 1.18 s by a gyro with white
// noise and a small bias (fixed seed), so the onboard check has a real gap to measure.
//   generate_flight OUT_BODY.json OUT_IMU.csv
#include <cstdio>
#include <iostream>
#include <random>

#include "aloft/dynamics/euler_equations.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: generate_flight OUT_BODY.json OUT_IMU.csv\n";
    return 2;
  }
  // A 2.3 kg brick, as practice/case00: principal moments in kg m^2 along body axes.
  const double moments[3] = {0.002823489583, 0.009669583333, 0.010873489583};
  aloft::InertiaTensor<double> inertia;
  const aloft::Status made = aloft::InertiaTensor<double>::make_from_principal(
      Eigen::Vector3d(moments[0], moments[1], moments[2]), Eigen::Quaterniond::Identity(), inertia);
  if (made != aloft::Status::ok) {
    std::cerr << "generate_flight: " << aloft::describe(made) << "\n";
    return 1;
  }

  const double rate_hz = 1000.0;
  const int samples = 1181;
  const int substeps = 10;
  const Eigen::Vector3d bias(0.03, -0.02, 0.01);  // rad/s
  const double noise_rad_s = 0.02;
  std::mt19937 random(20161104u);
  std::normal_distribution<double> noise(0.0, noise_rad_s);

  std::FILE* body = std::fopen(argv[1], "w");
  std::FILE* imu = std::fopen(argv[2], "w");
  if (!body || !imu) {
    std::cerr << "generate_flight: cannot write " << (body ? argv[2] : argv[1]) << "\n";
    return 1;
  }
  std::fprintf(body,
               "{\"name\": \"generated brick\", \"mass\": 2.3, \"inertia\": {\"tensor\": "
               "[[%.17g, 0, 0], [0, %.17g, 0], [0, 0, %.17g]]}}\n",
               moments[0], moments[1], moments[2]);
  std::fprintf(imu, "t,gx,gy,gz\n");
  Eigen::Vector3d omega(-7.13, 4.96, 2.45);  // rad/s, body axes: an off-axis throw
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3d measured =
        omega + bias + Eigen::Vector3d(noise(random), noise(random), noise(random));
    std::fprintf(imu, "%.6f,%.9g,%.9g,%.9g\n", i / rate_hz, measured.x(), measured.y(), measured.z());
    for (int k = 0; k < substeps; ++k) {
      omega = aloft::body_rate_rk4_step(inertia, omega, 1.0 / (rate_hz * substeps));
    }
  }
  const bool written = std::fclose(body) == 0 && std::fclose(imu) == 0;
  if (!written) {
    std::cerr << "generate_flight: write failed\n";
    return 1;
  }
  return 0;
}
