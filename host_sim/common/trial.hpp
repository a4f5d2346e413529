// The data model of recorded trials, shared by the readers (host_sim/readers/), the
// study and the diagnosis. Units are SI (SPEC §1): seconds, metres, rad/s, m/s².
// Readers convert from the file's units; nothing downstream sees mm or degrees.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <string>
#include <vector>

namespace aloft::host {

// Marker trajectories (TRC, C3D). positions[frame][marker]; an occluded marker is NaN.
struct MarkerTrial {
  std::string path;
  std::string format;         // "trc" or "c3d"
  std::string units_in_file;  // "mm" or "m" as the file states them
  double rate_hz = 0.0;
  std::vector<std::string> marker_names;
  std::vector<double> time_s;
  std::vector<std::vector<Eigen::Vector3d>> positions_m;
};

// Rigid-body poses (OpenSim .mot/.sto free joint, pose CSV): orientation body->world.
struct PoseTrial {
  std::string path;
  std::string format;  // "mot", "sto" or "pose_csv"
  std::vector<double> time_s;
  std::vector<Eigen::Quaterniond> orientation;
  std::vector<Eigen::Vector3d> position_m;  // empty when the file has none
};

// Gyro (and optional accelerometer) samples, sensor axes.
struct ImuLog {
  std::string path;
  std::string format;  // "imu_csv" or "phyphox"
  std::vector<double> time_s;
  std::vector<Eigen::Vector3d> gyro_rad_s;
  std::vector<Eigen::Vector3d> accel_m_s2;  // empty when the file has none
  // The body's rotor speed relative to the body (plain layout's `rotor_rad_s`, SPEC §3),
  // rad/s whatever --gyro-units says (the column's name gives its unit); empty when the
  // file has none.
  std::vector<double> rotor_rad_s;
  // Where each sample stands in the file (1-based lines), for messages about one sample.
  std::size_t header_line = 0;
  std::vector<std::size_t> line_numbers;
};

// One flight inside a longer IMU log (SPEC §3 segments file).
struct Segment {
  std::string name;
  double start_s = 0.0;
  double end_s = 0.0;
  std::string comment;
};

}  // namespace aloft::host
