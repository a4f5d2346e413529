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
//    The study's result depends on this number in proportion (see docs/study.md).
//  - Markers 6 mm proud of the surface (a 12 mm marker's centre), spread over the side
//    and one end so that no three are close to collinear, unevenly, as stuck on by hand
//    (the paper says only "four ... markers adhered to the cylinder's surface"; the
//    `side` layout puts all four on the curved side).
// Every one of these is an option of `aloft study` (--spin-rate, --spin-tilt,
// --spin-azimuth, --duration, --marker-noise, --marker-layout); these are the defaults.
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
  return rad_s * Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                                 std::cos(polar));
}

// Where the four markers sit on the cylinder.
enum class MarkerLayout {
  side_and_end,  // three on the side at uneven heights and azimuths, one on the top face
  side,          // all four on the curved side, uneven heights, about 90° apart
};
const char* marker_layout_name(MarkerLayout layout);  // "side-and-end", "side"

struct SyntheticThrowSettings {
  // The spin: 1.5 rev/s about an axis 50° from body z (tilt), its projection 30° round
  // from body x (azimuth).
  double spin_rate_rev_s = 1.5;
  double spin_tilt_deg = 50.0;
  double spin_azimuth_deg = 30.0;
  double flight_time_s = 0.872;
  double camera_rate_hz = 250.0;
  Eigen::Quaterniond initial_orientation = Eigen::Quaterniond(0.9, 0.3, -0.2, 0.25).normalized();
  Eigen::Vector3d launch_position_m = {0.0, 0.0, 1.0};
  // Horizontal launch velocity; the vertical one brings the centre back to launch height
  // after flight_time_s.
  Eigen::Vector2d launch_horizontal_velocity_m_s = {1.5, 0.2};
  double marker_noise_m = 0.1e-3;
  MarkerLayout marker_layout = MarkerLayout::side_and_end;
  std::uint64_t noise_seed = 20160101;

  Eigen::Vector3d initial_omega_body_rad_s() const {
    return rate_about_axis(2.0 * M_PI * spin_rate_rev_s, spin_tilt_deg, spin_azimuth_deg);
  }
};

struct SyntheticThrow {
  Body body;                                     // GF cylinder with its four markers
  MarkerTrial markers;                           // what the cameras report
  PoseTrial true_poses;                          // the true orientation at each camera frame (for tests)
  std::vector<Eigen::Vector3d> true_omega_body;  // true body rate at each camera frame
};

// The paper's cylinder by geometric formulae, with four markers in `layout`.
Body paper_cylinder_body(MarkerLayout layout = MarkerLayout::side_and_end);

SyntheticThrow make_synthetic_throw(const SyntheticThrowSettings& settings = {});

}  // namespace aloft::host
