// The accelerometer's position r over a recording, flight by flight (the least squares
// themselves: aloft/onboard/lever_arm_estimate.hpp). Each flight's torque-free samples are fitted;
// a flight's fit joins the recording's estimate, which the following flights use like a
// given r, only when it can be trusted:
//  - the flight turned at least `estimate_min_turn_rad`: a world-fixed hand force turns in
//    body axes and cannot then be absorbed by a body-fixed r;
//  - |r| is within the bound on an IMU inside the body, and the fit's rms residual is below
//    the free-flight floor;
//  - r cannot lie further than `trusted_within_m` + `trusted_within_relative` |r| from the
//    true one (LeverArmFit::worst_error_m: where a misfit as large as the fit's rms
//    residual, or the ridge, could move it). A flight that turns little about one axis
//    sees r's part along it weakly. This test replaced one that asked the fit's two halves
//    (alternating blocks of 16 samples) to agree within the same tolerance: both halves
//    see r alike, so they agreed on an r 10-50 mm off, and with this test in place the
//    halves decided no flight of the release tests (docs/onboard-pipeline.md).
// Within a flight, a given or earlier r gives way to the flight's own fit after
// `given_gives_way_after` samples, or after `missed_gives_way_after` when the release was
// found with a fitted r (the given one missed it).
#pragma once

#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/onboard/lever_arm_estimate.hpp"
#include "aloft/settings.hpp"

namespace aloft {

template <typename Scalar>
struct LeverArmEstimatorSettings {
  Scalar estimate_min_turn_rad = Scalar(2);
  Scalar trusted_within_m = Scalar(0.005);
  Scalar trusted_within_relative = Scalar(0.25);
  std::uint16_t given_gives_way_after = 64;
  std::uint16_t missed_gives_way_after = 8;
  // Once the flight's fit has taken over, its r is solved anew every this many samples,
  // not at every one (at every one while the release is still on probation, where the
  // release window dates it with that r).
  std::uint16_t solve_every_samples = 8;

  // The one list of these settings (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.estimate_min_turn_rad, [] {
      return SettingInfo{"lever_arm.estimate_min_turn_rad", "rad",
                         "a flight's r fit joins the recording's estimate only past this turn, so a "
                         "world-fixed hand force, which turns in body axes, cannot pass for a body-fixed "
                         "r. Not swept"};
    });
    v(s.trusted_within_m, [] {
      return SettingInfo{"lever_arm.trusted_within_m", "m",
                         "a flight's r is trusted when neither a misfit as large as its rms residual nor "
                         "the ridge could have moved it further than this, plus the relative part. Not "
                         "swept: a ruler's few millimetres"};
    });
    v(s.trusted_within_relative, [] {
      return SettingInfo{"lever_arm.trusted_within_relative", "", "plus this fraction of |r|. Not swept"};
    });
    v(s.given_gives_way_after, [] {
      return SettingInfo{"lever_arm.given_gives_way_after", "samples",
                         "a given r gives way to the flight's own fit after this many torque-free "
                         "samples: r fitted over 16 ms at 4 kHz is no worse than a ruler's few "
                         "millimetres (derived, not swept)"};
    });
    v(s.missed_gives_way_after, [] {
      return SettingInfo{"lever_arm.missed_gives_way_after", "samples",
                         "sooner when the release's fit missed the given r: measured with "
                         "release.given_r_tolerance_m (a given r 3 mm off: 100 % within 10 ms)"};
    });
    v(s.solve_every_samples, [] {
      return SettingInfo{"lever_arm.solve_every_samples", "samples",
                         "once the flight's fit has taken over, its r is solved anew every this many "
                         "samples: 2,797 -> 2,731 instructions per sample on the STM32F405, the release "
                         "figures the same but one landing at 100-250 Hz; solving every 8 on probation "
                         "too made one generated release early"};
    });
  }
};

// Limits the estimator shares with the release detector (ReleaseDetectorSettings).
template <typename Scalar>
struct LeverArmLimits {
  Scalar ridge_rad_s2 = Scalar(10);       // aloft/onboard/lever_arm_estimate.hpp
  Scalar max_lever_arm_m = Scalar(0.15);  // |r| beyond this is not an IMU inside the body
  Scalar rms_limit_m_s2 = Scalar(2);      // a trusted fit's rms residual (the free-flight floor)
};

// What a finished flight says about r.
template <typename Scalar>
struct LeverArmReport {
  Vec3<Scalar> r = Vec3<Scalar>::Zero();  // the given r, the recording's estimate or this flight's fit
  bool estimated = false;
  Scalar fit_rms_m_s2 = Scalar(0);  // rms of |a - K r| over the flight with that r
};

template <typename Scalar>
class LeverArmEstimator {
 public:
  // The settings are held, not copied (a pipeline's parts share its one copy): they must
  // outlive the estimator.
  // Out of line: inlined into a pipeline's constructor, its float members lie too far from
  // the pipeline's base for one store each (a Cortex-M4F's float store reaches 1,020 B), and
  // each zero took two instructions (the STM32F405 image: 96 B of flash less).
  ALOFT_COLD LeverArmEstimator(const LeverArmEstimatorSettings<Scalar>& settings,
                               const LeverArmLimits<Scalar>& limits)
      : settings_(settings), limits_(limits) {}
  LeverArmEstimator(LeverArmEstimatorSettings<Scalar>&&, const LeverArmLimits<Scalar>&) = delete;

  // A flight starts; `release_missed_given_r`: its release was found with a fitted r.
  void start_flight(bool release_missed_given_r) {
    release_missed_given_r_ = release_missed_given_r;
    flight_fit_.reset();
  }

  // One torque-free sample's terms. True when the flight's own fit has taken over and its
  // r is due to be solved anew (flight_r() is then the r to judge the flight with): at
  // the sample it takes over, then every `solve_every_samples`.
  bool add(const LeverArmTerms<Scalar>& terms) {
    flight_fit_.add_in_line(terms);
    const std::uint32_t every = settings_.solve_every_samples > 0 ? settings_.solve_every_samples : 1u;
    return taken_over() && (flight_fit_.count() - gives_way_after()) % every == 0;
  }
  // The flight's own fit judges the flight from now on.
  bool taken_over() const { return flight_fit_.count() >= gives_way_after(); }
  Vec3<Scalar> flight_r() const { return flight_fit_.solve(limits_.ridge_rad_s2); }

  // The flight ended: what it says about r (`given`: the body file's r, or null), and the
  // recording's estimate updated when the flight's fit can be trusted (see the file comment).
  ALOFT_COLD LeverArmReport<Scalar> finish_flight(const Vec3<Scalar>* given, Scalar turn_angle_rad) {
    LeverArmReport<Scalar> out;
    if (given != nullptr) {
      out.r = *given;
      out.fit_rms_m_s2 = flight_fit_.rms_residual(*given);
      return out;
    }
    const Vec3<Scalar> r = flight_r();
    if (trusted(r, turn_angle_rad)) {
      estimate_fit_.merge(flight_fit_);
      estimate_ = estimate_fit_.solve(limits_.ridge_rad_s2);
      has_estimate_ = true;
    }
    out.r = has_estimate_ ? estimate_ : r;
    out.estimated = true;
    out.fit_rms_m_s2 = flight_fit_.rms_residual(out.r);
    return out;
  }

  bool has_estimate() const { return has_estimate_; }
  const Vec3<Scalar>& estimate() const { return estimate_; }

 private:
  std::uint32_t gives_way_after() const {
    return release_missed_given_r_ ? settings_.missed_gives_way_after : settings_.given_gives_way_after;
  }

  bool trusted(const Vec3<Scalar>& r, Scalar turn_angle_rad) const {
    const Scalar within = settings_.trusted_within_m + settings_.trusted_within_relative * r.norm();
    return turn_angle_rad >= settings_.estimate_min_turn_rad && r.norm() <= limits_.max_lever_arm_m &&
           flight_fit_.rms_residual(r) <= limits_.rms_limit_m_s2 &&
           flight_fit_.worst_error_m(r, limits_.ridge_rad_s2, limits_.max_lever_arm_m) <= within;
  }

  const LeverArmEstimatorSettings<Scalar>& settings_;
  LeverArmLimits<Scalar> limits_;
  LeverArmFit<Scalar> flight_fit_;
  LeverArmFit<Scalar> estimate_fit_;
  Vec3<Scalar> estimate_ = Vec3<Scalar>::Zero();
  bool has_estimate_ = false;
  bool release_missed_given_r_ = false;
};

}  // namespace aloft
