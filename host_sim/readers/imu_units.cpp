#include "readers/imu_units.hpp"

#include <cmath>

namespace aloft::host {
namespace {

// One factor per unit name; the option checks only admit these names.
double seconds_per(const std::string& unit) { return unit == "ms" ? 1e-3 : unit == "us" ? 1e-6 : 1.0; }
double rad_s_per(const std::string& unit) { return unit == "deg/s" ? M_PI / 180.0 : 1.0; }
double m_s2_per(const std::string& unit) { return unit == "g" ? kStandardGravity_m_s2 : 1.0; }

}  // namespace

void add_imu_unit_options(CLI::App& command, ImuUnits& units) {
  // No CLI::IsMember description: it would show in the help as "TEXT:{s,ms,us}".
  command.add_option("--time-units", units.time, "the IMU log's time column: s (default), ms or us")
      ->type_name("UNIT")
      ->check(CLI::IsMember({"s", "ms", "us"}).description(""));
  command.add_option("--gyro-units", units.gyro, "the IMU log's gyro columns: rad/s (default) or deg/s")
      ->type_name("UNIT")
      ->check(CLI::IsMember({"rad/s", "deg/s"}).description(""));
  command
      .add_option("--accel-units", units.accel, "the IMU log's accelerometer columns: m/s2 (default) or g")
      ->type_name("UNIT")
      ->check(CLI::IsMember({"m/s2", "g"}).description(""));
}

void convert_to_si(ImuLog& log, const ImuUnits& units) {
  const double time = seconds_per(units.time), gyro = rad_s_per(units.gyro), accel = m_s2_per(units.accel);
  if (time != 1.0) {
    for (double& t : log.time_s) t *= time;
  }
  if (gyro != 1.0) {
    for (Eigen::Vector3d& w : log.gyro_rad_s) w *= gyro;
  }
  if (accel != 1.0) {
    for (Eigen::Vector3d& a : log.accel_m_s2) a *= accel;
  }
}

}  // namespace aloft::host
