#include "study/full_flight_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "aloft/dynamics/angular_velocity.hpp"
#include "aloft/dynamics/deviation.hpp"
#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/dynamics/rk4_integrator.hpp"
#include "aloft/lanes/xsimd_lanes.hpp"
#include "common/commands.hpp"
#include "study/full_flight_wide_lanes.hpp"

namespace aloft::host {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

// Sums of squared DA, one per frame.
struct SquaredDaSums {
  double body = 0.0, world = 0.0;
  void add(const Eigen::Quaterniond& from, const Eigen::Quaterniond& to, const StudyFlight& f,
           std::size_t j) {
    const double b = deviation_angle(rotation_axis_between(from, to), f.measured_omega_body[j]);
    const double w = deviation_angle(world_rotation_axis_between(from, to), f.measured_omega_world[j]);
    body += b * b;
    world += w * w;
  }
};

// Pose flight: orientation and rate integrated; the simulated omega of each interval
// comes from the two simulated orientations that bound it, like the measured one. The
// flight was validated once (validate_study_flight), so the steps are unchecked.
RmsDaByFrame pose_flight_rms_da(const StudyFlight& f, const InertiaTensor<double>& inertia, std::size_t k) {
  const Rk4Integrator<double> integrator(inertia);
  const std::size_t n = f.samples();
  const RigidBodyState<double> seed{f.orientation[k], f.state_omega_body[k]};
  SquaredDaSums sums;

  RigidBodyState<double> s = seed;
  for (std::size_t j = k; j + 1 < n; ++j) {
    const Eigen::Quaterniond before = s.orientation;
    integrator.step_unchecked(s, f.time_s[j + 1] - f.time_s[j]);
    sums.add(before, s.orientation, f, j);
  }
  s = seed;
  for (std::size_t j = k; j-- > 0;) {
    const Eigen::Quaterniond after = s.orientation;
    integrator.step_unchecked(s, -(f.time_s[j + 1] - f.time_s[j]));
    sums.add(s.orientation, after, f, j);
  }
  const double intervals = static_cast<double>(n - 1);
  return {std::sqrt(sums.body / intervals) * kDegreesPerRadian,
          std::sqrt(sums.world / intervals) * kDegreesPerRadian};
}

// Rate flight: the body rate alone, compared with the gyro at every sample (the seed
// sample itself included, where the deviation is zero by construction).
double rate_flight_rms_da(const StudyFlight& f, const InertiaTensor<double>& inertia, std::size_t k) {
  const std::size_t n = f.samples();
  double sum_sq = 0.0;
  Eigen::Vector3d w = f.state_omega_body[k];
  for (std::size_t j = k; j + 1 < n; ++j) {
    w = body_rate_rk4_step(inertia, w, f.time_s[j + 1] - f.time_s[j]);
    const double da = deviation_angle(w, f.measured_omega_body[j + 1]);
    sum_sq += da * da;
  }
  w = f.state_omega_body[k];
  for (std::size_t j = k; j-- > 0;) {
    w = body_rate_rk4_step(inertia, w, -(f.time_s[j + 1] - f.time_s[j]));
    const double da = deviation_angle(w, f.measured_omega_body[j]);
    sum_sq += da * da;
  }
  return std::sqrt(sum_sq / static_cast<double>(n)) * kDegreesPerRadian;
}

}  // namespace

Eigen::Vector3d rotation_axis_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Quaterniond d = a.conjugate() * b;
  return d.w() < 0.0 ? Eigen::Vector3d(-d.vec()) : Eigen::Vector3d(d.vec());
}

Eigen::Vector3d world_rotation_axis_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Quaterniond d = b * a.conjugate();
  return d.w() < 0.0 ? Eigen::Vector3d(-d.vec()) : Eigen::Vector3d(d.vec());
}

namespace {

void append(std::vector<double>& out, const Eigen::Vector3d& v) {
  out.insert(out.end(), {v.x(), v.y(), v.z()});
}

// This build's own SIMD width (SSE2 on any x86-64: 2 doubles).
void run_lanes_baseline(const FlightArrays<double>& f, const FlightSimulation<double>* sims,
                        SquaredDeviations<double>* out) {
  BatchFlight<xsimd::batch<double>>::run(f, sims, out);
}

}  // namespace

LaneFlight::LaneFlight(const StudyFlight& flight) {
  time_ = flight.time_s;
  for (const Eigen::Quaterniond& q : flight.orientation) {
    orientation_.insert(orientation_.end(), {q.w(), q.x(), q.y(), q.z()});
  }
  for (const Eigen::Vector3d& w : flight.state_omega_body) append(state_omega_, w);
  for (const Eigen::Vector3d& w : flight.measured_omega_body) append(measured_body_, w);
  for (const Eigen::Vector3d& w : flight.measured_omega_world) append(measured_world_, w);
  arrays_.samples = time_.size();
  arrays_.time_s = time_.data();
  arrays_.orientation_wxyz = orientation_.empty() ? nullptr : orientation_.data();
  arrays_.state_omega_body = state_omega_.data();
  arrays_.measured_body = measured_body_.data();
  arrays_.measured_world = measured_world_.empty() ? nullptr : measured_world_.data();
}

std::size_t simulation_lanes() {
  if (full_flight_lanes_avx512_supported()) return kFullFlightLanesAvx512;
  if (full_flight_lanes_avx2_supported()) return kFullFlightLanesAvx2;
  return std::size_t(LaneTraits<xsimd::batch<double>>::count);
}

void full_flight_rms_da_deg_lanes(const LaneFlight& flight, const FlightSimulation<double>* sims,
                                  std::size_t count, RmsDaByFrame* out) {
  constexpr std::size_t kMaxLanes = kFullFlightLanesAvx512;
  const std::size_t lanes = simulation_lanes();
  if (count == 0 || count > lanes) throw Error("full_flight_rms_da_deg_lanes: bad count (internal error)");
  // Lanes past `count` repeat the last simulation; their results are dropped.
  FlightSimulation<double> padded[kMaxLanes];
  for (std::size_t l = 0; l < lanes; ++l) padded[l] = sims[std::min(l, count - 1)];
  SquaredDeviations<double> sums[kMaxLanes];
  if (lanes == kFullFlightLanesAvx512) {
    run_full_flight_lanes_avx512(flight.arrays(), padded, sums);
  } else if (lanes == kFullFlightLanesAvx2) {
    run_full_flight_lanes_avx2(flight.arrays(), padded, sums);
  } else {
    run_lanes_baseline(flight.arrays(), padded, sums);
  }
  const bool pose = flight.arrays().orientation_wxyz != nullptr;
  for (std::size_t l = 0; l < count; ++l) {
    const double comparisons = static_cast<double>(sums[l].comparisons);
    out[l] = {std::sqrt(sums[l].body / comparisons) * kDegreesPerRadian,
              pose ? std::sqrt(sums[l].world / comparisons) * kDegreesPerRadian
                   : std::numeric_limits<double>::quiet_NaN()};
  }
}

RmsDaByFrame full_flight_rms_da_deg(const StudyFlight& flight, const InertiaTensor<double>& inertia,
                                    std::size_t k) {
  if (flight.has_orientation()) return pose_flight_rms_da(flight, inertia, k);
  return {rate_flight_rms_da(flight, inertia, k), std::numeric_limits<double>::quiet_NaN()};
}

void validate_study_flight(const StudyFlight& f) {
  const std::size_t n = f.samples();
  const std::string where = f.name + ": ";
  if (n < 3) {
    throw Error(where + "flight has " + std::to_string(n) + " samples; at least 3 are needed");
  }
  if (f.state_omega_body.size() != n || (f.has_orientation() && f.orientation.size() != n) ||
      f.measured_omega_body.size() != (f.has_orientation() ? n - 1 : n) ||
      f.measured_omega_world.size() != (f.has_orientation() ? n - 1 : 0)) {
    throw Error(where + "inconsistent flight data (internal error)");
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = where + "sample " + std::to_string(i) + ": ";
    if (!std::isfinite(f.time_s[i]) || (i > 0 && !(f.time_s[i] > f.time_s[i - 1]))) {
      throw Error(at + "time does not increase");
    }
    if (!all_finite(f.state_omega_body[i])) throw Error(at + "angular velocity is not finite");
    if (f.has_orientation() && !is_unit(f.orientation[i])) {
      throw Error(at + "orientation is not a finite unit quaternion");
    }
  }
  for (std::size_t j = 0; j < f.measured_omega_body.size(); ++j) {
    if (!all_finite(f.measured_omega_body[j]) || f.measured_omega_body[j].squaredNorm() == 0.0) {
      throw Error(where + "sample " + std::to_string(j) +
                  ": measured angular velocity is zero or not finite");
    }
  }
}

}  // namespace aloft::host
