#include "diagnose/4_judge/baseline_gap.hpp"

#include <algorithm>

namespace aloft::host::diagnose {

void BaselineGap::add(const Flight& flight, const std::vector<Eigen::Vector3d>& readings,
                      const Eigen::Vector3d& inverse_sigma) {
  const Eigen::Matrix3d to_body = flight.sensor_to_body.toRotationMatrix();
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!flight.usable[k]) continue;
    sums_.add(readings[k], flight.omega[k], inverse_sigma);
    body_square_sum_ += (to_body * (readings[k] - flight.omega[k])).cwiseAbs2();
    ++body_samples_;
  }
}

void BaselineGap::describe(Analysis& analysis) const {
  analysis.baseline.rms_da_deg = sums_.rms_da_deg();
  analysis.baseline.rms_rel_err = sums_.rms_rel_err();
  Where& where = analysis.where;
  where.rms_gap_body_rad_s = (body_square_sum_ / std::max(body_samples_, 1)).cwiseSqrt();
  Eigen::Index axis = 0;
  where.rms_gap_body_rad_s.maxCoeff(&axis);
  where.dominant_axis = axis == 0 ? "x" : (axis == 1 ? "y" : "z");
  where.gap_over_noise = sums_.residuals ? sums_.chi_square / sums_.residuals : 0.0;
}

void describe_slices(const Flight& flight, const std::vector<Eigen::Vector3d>& readings,
                     const Eigen::Vector3d& inverse_sigma, Where& where) {
  constexpr int kSlices = 10;
  std::vector<GapSums> slices(kSlices);
  const double t0 = flight.start_s();
  const double span = std::max(flight.end_s() - t0, 1e-12);
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!flight.usable[k]) continue;
    const int s = std::min(kSlices - 1, static_cast<int>((flight.time_s[k] - t0) / span * kSlices));
    slices[static_cast<std::size_t>(s)].add(readings[k], flight.omega[k], inverse_sigma);
  }
  for (int s = 0; s < kSlices; ++s) {
    TimeSlice slice;
    slice.from_s = t0 + span * s / kSlices;
    slice.to_s = t0 + span * (s + 1) / kSlices;
    slice.rms_da_deg = slices[static_cast<std::size_t>(s)].rms_da_deg();
    slice.rms_rel_err = slices[static_cast<std::size_t>(s)].rms_rel_err();
    where.slices.push_back(slice);
  }
}

}  // namespace aloft::host::diagnose
