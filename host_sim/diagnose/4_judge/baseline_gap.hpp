// The nominal model's gap, the baseline every effect is judged against: summed over one
// flight or over a session's flights, the same way (one gap, one definition).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/analysis.hpp"
#include "diagnose/1_input/flight.hpp"

namespace aloft::host::diagnose {

class BaselineGap {
 public:
  // readings: the nominal model's prediction at each sample of the flight (sensor axes
  // for a gyro); samples that are not usable are left out.
  void add(const Flight& flight, const std::vector<Eigen::Vector3d>& readings,
           const Eigen::Vector3d& inverse_sigma);
  // Fills analysis.baseline and where's per-axis gap, dominant axis and gap over noise.
  void describe(Analysis& analysis) const;

 private:
  GapSums sums_;
  Eigen::Vector3d body_square_sum_ = Eigen::Vector3d::Zero();
  int body_samples_ = 0;
};

// The nominal model's gap (`readings`) in ten slices of the flight's time: where along the
// flight it grows (where.slices).
void describe_slices(const Flight& flight, const std::vector<Eigen::Vector3d>& readings,
                     const Eigen::Vector3d& inverse_sigma, Where& where);

}  // namespace aloft::host::diagnose
