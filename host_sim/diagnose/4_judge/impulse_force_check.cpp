#include "diagnose/4_judge/impulse_force_check.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "aloft/onboard/lever_arm_estimate.hpp"
#include "diagnose/1_input/body_kinematics.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

// The lever arm's ridge, as the firmware's estimate takes it (LeverArmEstimatorSettings).
constexpr double kRidge_rad_s2 = 10.0;

std::vector<BodyKinematics<double>> kinematics(const Flight& flight) {
  const Eigen::Matrix3d sensor_to_body = flight.sensor_to_body.normalized().toRotationMatrix();
  std::vector<BodyKinematics<double>> out;
  out.reserve(flight.size());
  for (std::size_t k = 0; k < flight.size(); ++k) {
    out.push_back(body_kinematics_at(flight.time_s, flight.omega, flight.accel_m_s2, sensor_to_body, k));
  }
  return out;
}

Eigen::Vector3d lever_arm(const Flight& flight, const std::vector<BodyKinematics<double>>& kin) {
  if (flight.imu_position_m) return *flight.imu_position_m;
  LeverArmFit<double> fit;
  for (std::size_t k = 0; k < kin.size(); ++k) {
    if (flight.usable[k]) fit.add(kin[k]);
  }
  return fit.solve(kRidge_rad_s2);
}

}  // namespace

std::optional<ImpulseForce> impulse_force(const Flight& flight, double impulse_time_s) {
  if (!flight.gyro_input || flight.accel_m_s2.size() != flight.size() || flight.size() < 3)
    return std::nullopt;
  const std::vector<BodyKinematics<double>> kin = kinematics(flight);
  const Eigen::Vector3d r = lever_arm(flight, kin);
  std::vector<Eigen::Vector3d> excess(kin.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < kin.size(); ++k) {
    excess[k] = kin[k].a - lever_arm_matrix(kin[k].w, kin[k].w_dot) * r;
    mean += excess[k];
  }
  mean /= static_cast<double>(kin.size());
  // The integral of the excess over [centre - w, centre + w], each sample weighted by
  // half the span to its neighbours. The window's samples are found by binary search (the
  // times ascend), so the windows together read the flight about once.
  const auto velocity_change = [&](double centre) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    // One sample early: the test below, not the search's rounding of centre - w, decides.
    const auto found =
        std::lower_bound(flight.time_s.begin(), flight.time_s.end(), centre - kImpulseWindow_s);
    const auto first =
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(found - flight.time_s.begin() - 1, 0));
    for (std::size_t k = first; k < kin.size(); ++k) {
      if (flight.time_s[k] - centre > kImpulseWindow_s) break;
      if (std::abs(flight.time_s[k] - centre) > kImpulseWindow_s) continue;
      const double dt =
          0.5 * (flight.time_s[std::min(k + 1, kin.size() - 1)] - flight.time_s[k > 0 ? k - 1 : 0]);
      sum += (excess[k] - mean) * dt;
    }
    return sum.norm();
  };
  double square = 0.0;
  int windows = 0;
  for (double c = flight.start_s() + kImpulseWindow_s; c + kImpulseWindow_s <= flight.end_s();
       c += 2.0 * kImpulseWindow_s) {
    if (std::abs(c - impulse_time_s) < 3.0 * kImpulseWindow_s) continue;
    square += std::pow(velocity_change(c), 2);
    ++windows;
  }
  if (windows < 5) return std::nullopt;
  ImpulseForce out;
  out.velocity_change_m_s = velocity_change(impulse_time_s);
  out.elsewhere_rms_m_s = std::sqrt(square / windows);
  out.seen = out.velocity_change_m_s >= kSeenOverElsewhere * out.elsewhere_rms_m_s;
  return out;
}

void check_impulse_against_accelerometer(Analysis& analysis, const Flight& flight) {
  Verdict& v = analysis.verdict;
  for (const VerdictEffect& e : v.effects) {
    if (e.effect != Effect::impulse) continue;
    const std::optional<ImpulseForce> f = impulse_force(flight, e.params.time_s);
    if (!f) continue;
    if (f->seen) {
      analysis.notes.push_back(
          printf_text("impulse at %.3f s: the accelerometer shows a blow from outside, "
                      "a velocity change of %.3g m/s (%.0f x what the rest of the flight shows)",
                      e.params.time_s, f->velocity_change_m_s,
                      f->velocity_change_m_s / std::max(f->elsewhere_rms_m_s, 1e-12)));
      continue;
    }
    const std::string why = printf_text(
        "impulse at %.3f s: the accelerometer shows no blow from outside there (a velocity change of %.3g "
        "m/s, "
        "%.1f x what the rest of the flight shows): a shift inside the body, or no impulse at all",
        e.params.time_s, f->velocity_change_m_s,
        f->velocity_change_m_s / std::max(f->elsewhere_rms_m_s, 1e-12));
    v.confident = false;
    v.could_not_judge.push_back(why);
  }
}

}  // namespace aloft::host::diagnose
