// How far a simulated angular velocity is from a measured one: in direction, the
// deviation angle DA = atan2(|a x b|, a . b) (the seed study's measure, degrees in
// reports, radians here), and in size and direction together, the relative error
// |w_sim - w_meas| / |w_meas|. DeviationStats accumulates both in fixed memory.
#pragma once

#include "aloft/cold_path.hpp"
#include "aloft/lanes/lane_angle.hpp"
#include "aloft/dynamics/rotation.hpp"
#include "aloft/status.hpp"

#include <cstdint>

namespace aloft {

// Angle between a and b in [0, pi], radians; accurate for tiny and near-pi angles. The
// atan2 is aloft's polynomial one (aloft/lanes/lane_angle.hpp: within 1e-15 rad of std::atan2
// in double, 2e-7 in float), the same the SIMD lanes and the firmware use.
template <typename Scalar>
inline Scalar deviation_angle(const Vec3<Scalar>& a, const Vec3<Scalar>& b) {
  return lane_deviation_angle(LaneVec3<Scalar>{a.x(), a.y(), a.z()}, LaneVec3<Scalar>{b.x(), b.y(), b.z()});
}

// |simulated - measured| / |measured|; infinite when measured is zero.
template <typename Scalar>
inline Scalar relative_error(const Vec3<Scalar>& simulated, const Vec3<Scalar>& measured) {
  return (simulated - measured).norm() / measured.norm();
}

// Count, mean square, RMS and maximum of DA (radians) and relative error. The mean
// square is updated incrementally (m += (x^2 - m)/n), so it neither overflows nor loses
// the small terms of a long run in float the way a plain running sum would.
template <typename Scalar>
class DeviationStats {
 public:
  // Adds one comparison. Non-finite vectors or a zero measured vector are refused.
  Status add(const Vec3<Scalar>& simulated, const Vec3<Scalar>& measured) {
    if (!all_finite(simulated) || !all_finite(measured)) return Status::non_finite_input;
    if (!(measured.squaredNorm() > Scalar(0))) return Status::zero_vector;
    add_values(deviation_angle(simulated, measured), relative_error(simulated, measured));
    return Status::ok;
  }

  // Adds one already computed pair (DA in radians, relative error).
  void add_values(Scalar da, Scalar rel_err) {
    ++count_;
    const Scalar n = static_cast<Scalar>(count_);
    mean_square_da_ += (da * da - mean_square_da_) / n;
    mean_square_rel_ += (rel_err * rel_err - mean_square_rel_) / n;
    if (da > max_da_) max_da_ = da;
    if (rel_err > max_rel_) max_rel_ = rel_err;
  }

  // Folds another accumulator into this one (as if its samples had been added here).
  // Cold: it runs when a seed retires or a flight ends, not per sample (on the STM32F405,
  // one copy built for size in place of its inlined copies: 200 B of flash less).
  ALOFT_COLD void merge(const DeviationStats& other) {
    if (other.count_ == 0) return;
    const std::uint32_t total = count_ + other.count_;
    const Scalar wa = static_cast<Scalar>(count_) / static_cast<Scalar>(total);
    const Scalar wb = Scalar(1) - wa;
    mean_square_da_ = wa * mean_square_da_ + wb * other.mean_square_da_;
    mean_square_rel_ = wa * mean_square_rel_ + wb * other.mean_square_rel_;
    if (other.max_da_ > max_da_) max_da_ = other.max_da_;
    if (other.max_rel_ > max_rel_) max_rel_ = other.max_rel_;
    count_ = total;
  }

  void reset() { *this = DeviationStats(); }

  // The accumulator of `count` comparisons kept elsewhere as sums of squares and maxima
  // (the onboard check's seeds: a sum costs a sample one addition, a running mean a
  // division and a subtraction more).
  static DeviationStats from_sums(std::uint32_t count, Scalar sum_square_da, Scalar sum_square_rel,
                                  Scalar max_da, Scalar max_rel) {
    DeviationStats out;
    if (count == 0) return out;
    const Scalar n = static_cast<Scalar>(count);
    out.count_ = count;
    out.mean_square_da_ = sum_square_da / n;
    out.mean_square_rel_ = sum_square_rel / n;
    out.max_da_ = max_da;
    out.max_rel_ = max_rel;
    return out;
  }

  std::uint32_t count() const { return count_; }
  Scalar mean_square_da() const { return mean_square_da_; }
  Scalar rms_da() const { return std::sqrt(mean_square_da_); }
  Scalar max_da() const { return max_da_; }
  Scalar mean_square_relative_error() const { return mean_square_rel_; }
  Scalar rms_relative_error() const { return std::sqrt(mean_square_rel_); }
  Scalar max_relative_error() const { return max_rel_; }

 private:
  std::uint32_t count_ = 0;
  Scalar mean_square_da_ = Scalar(0);
  Scalar mean_square_rel_ = Scalar(0);
  Scalar max_da_ = Scalar(0);
  Scalar max_rel_ = Scalar(0);
};

}  // namespace aloft
