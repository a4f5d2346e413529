// The built-in trial: the seed study's experiment rebuilt in simulation, because its
// recording is not public. The GF cylinder (../shared/STUDY.md) flies torque-free for
// 0.872 s; four 12 mm markers on its surface are "seen" at 250 Hz with Gaussian
// reconstruction noise. What the study does with these markers (rigid fit, resampling
// to 1 kHz, rates from consecutive orientations) is not here: this is only the camera.
//
// Choices and why (the defaults below):
//  - Initial body rate 9.42 rad/s (1.5 rev/s), its axis 50° from the cylinder axis z
//    and 30° round from x: (6.25, 3.61, 6.06) rad/s. A 10 kg cylinder thrown by hand
//    turns slowly; 1.5 rev/s makes 1.3 turns in flight, and an axis far from every body
//    axis (as the paper asks) makes the rate precess visibly in the body, by 0.147 ω_z
//    = 0.89 rad/s, 44° over the flight, so the GF and CP models part ways.
//  - Marker reconstruction noise: white, 0.1 mm standard deviation per coordinate and
//    frame. Rates from consecutive poses see only the frame-to-frame jitter (a steady
//    bias cancels). A static Vicon marker jitters by less than 0.025 mm, while the error
//    of moving markers is typically a few tenths of a millimetre and up to 2 mm
//    (Merriaux et al., "A study of Vicon system positioning performance", Sensors
//    17:1591, 2017); 0.1 mm is the middle of 0.025-0.5 mm on a logarithmic scale. With
//    four markers 65-80 mm from the centre it makes about 1 mrad of orientation noise.
//    The study's result depends on this number in proportion (see the README).
//  - Markers 6 mm proud of the surface (a 12 mm marker's centre), spread over the side
//    and one end so that no three are close to collinear, unevenly, as stuck on by hand.
//  - The centre of mass follows a ballistic arc (g = 9.81 m/s²) that lands at launch
//    height after the flight time; translation does not affect the rotation but the
//    markers move as in a real throw.
//  - The noise comes from a fixed seed: the built-in trial is one fixed "recording",
//    the same for every --seed (which drives the Monte Carlo draws only).
#pragma once

#include <cmath>
#include <cstdint>

#include "common/body_file.hpp"
#include "common/trial.hpp"

namespace aloft::host {

// Body rate of magnitude `rad_s` about the axis at polar angle `polar_deg` from body z
// and azimuth `azimuth_deg` from body x.
inline Eigen::Vector3d rate_about_axis(double rad_s, double polar_deg, double azimuth_deg) {
  const double polar = polar_deg * M_PI / 180.0, azimuth = azimuth_deg * M_PI / 180.0;
  return rad_s * Eigen::Vector3d(std::sin(polar) * std::cos(azimuth),
                                 std::sin(polar) * std::sin(azimuth), std::cos(polar));
}

struct SyntheticThrowSettings {
  double flight_time_s = 0.872;
  double camera_rate_hz = 250.0;
  // 1.5 rev/s about an axis 50° from body z, its projection 30° round from body x.
  Eigen::Vector3d initial_omega_body_rad_s = rate_about_axis(3.0 * M_PI, 50.0, 30.0);
  Eigen::Quaterniond initial_orientation = Eigen::Quaterniond(0.9, 0.3, -0.2, 0.25).normalized();
  Eigen::Vector3d launch_position_m = {0.0, 0.0, 1.0};
  Eigen::Vector3d launch_velocity_m_s = {1.5, 0.2, 4.2772};  // back to 1 m after 0.872 s
  double marker_noise_m = 0.1e-3;
  std::uint64_t noise_seed = 20160101;
};

struct SyntheticThrow {
  Body body;                // GF cylinder with its four markers
  MarkerTrial markers;      // what the cameras report
  PoseTrial true_poses;     // the true orientation at each camera frame (for tests)
  std::vector<Eigen::Vector3d> true_omega_body;  // true body rate at each camera frame
};

// The paper's cylinder by geometric formulae, with the built-in trial's four markers.
Body paper_cylinder_body();

SyntheticThrow make_synthetic_throw(const SyntheticThrowSettings& settings = {});

}  // namespace aloft::host
