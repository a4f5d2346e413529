// Rest periods of a gyro log: stretches where the sensor lies still, so what it reads
// there is its bias plus its noise as filtered and quantised, with no motion in it. The
// noise floor is best measured there (noise_floor.hpp: method "rest"); and a flight cut
// right after rest starts while the gyro's low-pass is still settling from the spin-up.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "common/trial.hpp"

namespace aloft::host::diagnose {

// A still sensor reads less than this (rad/s): a gyro's bias and noise stay well below,
// a thrown or hand-held body moves well above it.
constexpr double kStillRate_rad_s = 0.5;
// A rest period lasts at least this long once its edges are dropped (s).
constexpr double kMinimumRest_s = 0.5;
// Dropped at each end of a still run (s): the low-pass's tail of the motion next to it.
constexpr double kRestEdge_s = 0.1;
// A second-order low-pass at 15 Hz (the slowest phone gyros) settles from a step to 1/1000
// of it in ln(1000) / (2π · 15 Hz / √2) ≈ 0.104 s: how long a flight released from rest
// carries the spin-up in its readings, whatever the gyro's cutoff above that.
constexpr double kFilterSettling_s = 0.104;

struct RestPeriod {
  double from_s = 0.0, to_s = 0.0;                  // the still run without its edges
  double still_until_s = 0.0;                       // the run's last still sample (the motion's start)
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();  // RMS about the period's mean, per axis
  std::size_t samples = 0;
};

// Every rest period of the log, in time order: runs of samples below kStillRate_rad_s,
// without their edges, at least kMinimumRest_s long, whose spread is noise rather than a
// slow motion (rest_periods.cpp: the spread against the sample-to-sample steps).
std::vector<RestPeriod> find_rest_periods(const ImuLog& log);

struct RestNoise {
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();  // per sensor axis
  double seconds = 0.0;                             // rest it was measured on
  int periods = 0;
};

// The noise pooled over the quietest periods (within 1.5× the quietest one's spread, so
// a hand holding the sensor not quite still does not inflate it); none without rest.
std::optional<RestNoise> rest_noise(const std::vector<RestPeriod>& periods);

// A hand spins a body up from rest in less than this before releasing it (s).
constexpr double kSpinUp_s = 0.3;

// True when the log was still until at most kSpinUp_s before `start_s` (or a moment after
// it): a flight starting there was released from rest, and its first samples are the
// gyro's filter settling from the release.
bool released_from_rest(const std::vector<RestPeriod>& periods, double start_s);

}  // namespace aloft::host::diagnose
