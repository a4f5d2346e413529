#include "readers/body_rates.hpp"

#include <string>

#include "aloft/dynamics/angular_velocity.hpp"
#include "common/commands.hpp"
#include "readers/time_stamps.hpp"

namespace aloft::host {

BodyRates body_rates_from_poses(const PoseTrial& poses) {
  BodyRates rates;
  const std::size_t n = std::min(poses.time_s.size(), poses.orientation.size());
  const std::vector<char> gap_after = steps_followed_by_gap(poses.time_s);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double dt = poses.time_s[k + 1] - poses.time_s[k];
    if (gap_after[k]) {
      ++rates.pairs_skipped_at_gaps;
      continue;
    }
    Eigen::Vector3d omega;
    const Status status =
        omega_body_from_orientations(poses.orientation[k], poses.orientation[k + 1], dt, omega);
    if (status != Status::ok) {
      throw Error(poses.path + ": poses at t = " + std::to_string(poses.time_s[k]) +
                  " s: " + describe(status));
    }
    rates.time_s.push_back(0.5 * (poses.time_s[k] + poses.time_s[k + 1]));
    rates.omega_body.push_back(omega);
  }
  return rates;
}

}  // namespace aloft::host
