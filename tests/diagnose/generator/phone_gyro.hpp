// A phone's gyro as the tests model it (issues 8 and 14): the sensor's reading (true rate
// through the sensor model) passes a causal second-order Butterworth low-pass, is read at
// ~rate_hz with +-jitter relative timestamp jitter (the stamps are the true read times),
// gets white noise after the filter, and is quantised as phone apps log it.
// Independent of the diagnosis: nothing from host_sim/diagnose.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "common/trial.hpp"
#include "seeded_random.hpp"

namespace aloft::generator {

struct PhoneGyroSpec {
  double rate_hz = 100.0;
  double cutoff_hz = 25.0;         // <= 0: no filter
  double noise_rad_s = 0.01;       // white, per axis, added after the filter
  double quantum_rad_s = 0.00107;  // 0: not quantised
  double jitter = 0.02;            // relative jitter of each sampling interval
};

// `fine` is the unfiltered reading every `step_s` seconds from t = 0 (step_s well below
// 1 / cutoff and 1 / rate). Returns the log, read from t = 0 to the last fine sample; the
// jitter and the noise come from `noise`, in that order per sample.
host::ImuLog read_phone_gyro(const std::vector<Eigen::Vector3d>& fine, double step_s,
                             const PhoneGyroSpec& spec, SeededRandom& noise);

}  // namespace aloft::generator
