// Measured angular velocity in body axes from a pose trial (SPEC §1): for each pair of
// consecutive poses, log(q_k^-1 q_{k+1}) / dt (aloft::omega_body_from_orientations),
// stamped at the midpoint of the pair.
//
// Pairs that straddle a gap (readers/time_stamps.hpp's rule) are skipped: frames are
// missing between the two poses (fit_poses leaves unposed frames out), and a rate over
// the gap would average across it.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "common/trial.hpp"

namespace aloft::host {

struct BodyRates {
  std::vector<double> time_s;               // midpoints of the pairs used
  std::vector<Eigen::Vector3d> omega_body;  // rad/s, body axes
  std::size_t pairs_skipped_at_gaps = 0;
};

// Throws aloft::host::Error (naming the trial's file and time) if a pose is not a unit
// quaternion or time does not increase.
BodyRates body_rates_from_poses(const PoseTrial& poses);

}  // namespace aloft::host
