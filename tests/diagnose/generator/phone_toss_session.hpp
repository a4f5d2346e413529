// Sessions of phone tosses about the intermediate axis (issue 14), for checking the
// tensor report and the pooled verdict. Independent of the diagnosis: its own Euler
// integration, its own filter, nothing from host_sim/diagnose.
//
// What a session looks like:
//   - the body: a phone-shaped box, 77 x 153 x 12 mm (x, y, z), 0.25 kg, so x is the
//     intermediate axis; the nominal tensor is the uniform box's;
//   - the true body: one principal moment off the nominal by a factor (1: exact). Only
//     physical bodies are made: a flat box sits on the triangle inequality's boundary
//     (Iz = Ix + Iy - a thickness term), so a factor that would break it is refused;
//   - 6-12 tosses spun up over 0.1 s in the hand, then released at 18-30 rad/s about x
//     with a small transverse rate drawn until the body flips 2-4 times (sign changes of
//     w_x) in its 0.8-1.0 s of flight (when x is no longer intermediate, any count),
//     with 1.5 s of rest (zero rate) between tosses;
//   - the gyro: the true rate read by a phone's gyro (phone_gyro.hpp): causal low-pass,
//     ~rate_hz with +-2 % timestamp jitter, white noise, quantised.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "common/body_file.hpp"
#include "common/trial.hpp"

namespace aloft::generator {

struct PhoneTossSpec {
  int off_axis = 1;            // body axis whose true moment is off (0 x, 1 y, 2 z)
  double moment_factor = 1.0;  // true moment / nominal moment on that axis
  int tosses = 0;              // 0: drawn in [6, 12]
  double rate_hz = 100.0;
  double cutoff_hz = 25.0;  // <= 0: no filter
  double noise_rad_s = 0.01;
  double quantum_rad_s = 0.00107;  // 0: not quantised
  double jitter = 0.02;            // relative timestamp jitter
};

struct PhoneTossSession {
  host::Body nominal;                   // what the diagnosis is told
  host::ImuLog log;                     // the whole session
  std::vector<host::Segment> segments;  // release to catch of each toss
  Eigen::Vector3d true_moments_xyz = Eigen::Vector3d::Zero();
  Eigen::Vector2d true_ratios = Eigen::Vector2d::Zero();  // Iy/Ix, Iz/Ix
  std::vector<int> flips;                                 // sign changes of w_x per toss
};

// Deterministic in (spec, seed). Throws std::invalid_argument for a factor that would
// break the triangle inequality.
PhoneTossSession generate_phone_toss_session(const PhoneTossSpec& spec, std::uint64_t seed);

}  // namespace aloft::generator
