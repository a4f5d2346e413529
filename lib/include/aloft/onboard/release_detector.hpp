// Release and landing of a spinning, off-centre IMU (aloft/dynamics/free_flight_residual.hpp has
// the physics). A sample is in free flight when the gyro sees no torque and the specific
// force left at the centre of mass, |a - K r|, is within its limit. Release is believed
// once free flight has lasted `confirm_us` (and `confirm_samples`); it is then dated back
// to the first sample of that stretch whose residual is below `release_fraction` of the
// limit, so a hand force that fades out is not taken for free flight while it still acts.
// Landing is `landing_samples` consecutive samples that are not free (a catch, an impact),
// dated back to the first of them.
//
// A given r (or an earlier flight's estimate) that misses by a few millimetres leaves a
// residual of w² times the miss, over the limit at high spin: such a stretch is fitted as
// below, and the fit is taken only within `given_r_tolerance_m` of the given r.
//
// Without r (no `imu.position` and no earlier flight to estimate it from) every sample
// stretch the gyro calls torque-free is fitted: the earliest start s whose fit over
// [s, now] has an rms residual below `fit_rms_fraction` of the limit, a bounded |r|, and
// small residuals at both ends is the free stretch. A fit over a few milliseconds could
// absorb a hand force that happens to lie across the spin axis; the torque test, the
// bound on |r|, the residual at the stretch's first sample and the flight-long fit of the
// pipeline (aloft/onboard/onboard_pipeline.hpp), which must stay small and stable before its r is
// used for later flights, keep that from going further than one flight.
#pragma once

#include <cmath>
#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/onboard/lever_arm_estimate.hpp"
#include "aloft/onboard/sample_history.hpp"
#include "aloft/onboard/torque_test.hpp"
#include "aloft/settings.hpp"
#include "aloft/sensor/whole_microseconds.hpp"

namespace aloft {

template <typename Scalar>
struct ReleaseDetectorSettings {
  FreeFlightSettings<Scalar> free_flight = {};
  std::uint32_t confirm_us = 4000;
  std::uint16_t confirm_samples = 5;
  Scalar release_fraction = Scalar(0.5);
  Scalar level_over_flight_mean = Scalar(2);
  Scalar level_margin_m_s2 = Scalar(0.2);
  std::uint32_t fade_out_at_most_us = 3500;
  Scalar step_fraction = Scalar(0.5);
  std::uint16_t landing_samples = 3;
  Scalar max_lever_arm_m = Scalar(0.15);
  Scalar given_r_tolerance_m = Scalar(0.01);
  Scalar fit_rms_fraction = Scalar(0.5);
  Scalar ridge_rad_s2 = Scalar(10);  // see aloft/onboard/lever_arm_estimate.hpp
  // Dating a release whose force fades out (after_fade_out, crossing_before below):
  std::uint32_t steepest_fall_from_us = 900;
  Scalar fall_from_over_level = Scalar(2);
  std::uint32_t fall_chord_us = 3000;
  std::uint16_t fall_search_samples = 16;
  std::uint16_t step_search_samples = 6;
  std::uint16_t flight_level_samples = 32;

  // The one list of these settings (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    visit_settings(s.free_flight, v);
    visit_confirming(s, v);
    visit_lever_arm(s, v);
    visit_fade_out(s, v);
  }

 private:
  template <typename Self, typename Visitor>
  static void visit_confirming(Self& s, Visitor& v) {
    v(s.confirm_us, [] {
      return SettingInfo{"release.confirm_us", "µs",
                         "free flight this long before release is believed. Set on the generated throws "
                         "of tests/host/test_release_detection.cpp, whose bars hold with it; not swept"};
    });
    v(s.confirm_samples, [] {
      return SettingInfo{"release.confirm_samples", "samples",
                         "and at least this many free samples (at 1 kHz: 5 ms). Set with confirm_us; not "
                         "swept"};
    });
    v(s.release_fraction, [] {
      return SettingInfo{"release.release_fraction", "",
                         "release is dated back to the first sample whose residual is below this fraction "
                         "of the limit. Set on the generated throws; not swept"};
    });
    v(s.level_over_flight_mean, [] {
      return SettingInfo{"release.level_over_flight_mean", "",
                         "the flight's level is this times its mean residual, plus level_margin_m_s2: the "
                         "release follows the last sample above it and the landing is dated back to "
                         "where the residual left it. With it no generated release is early, where a "
                         "fixed fraction of the limit gave releases up to 2.9 ms early at 30-40 rad/s, "
                         "4 kHz (tests/host/test_release_detection.cpp)"};
    });
    v(s.level_margin_m_s2, [] {
      return SettingInfo{"release.level_margin_m_s2", "m/s²",
                         "added to that level, above the noise of a near-zero mean. Set with the factor on "
                         "the same throws; not swept"};
    });
    v(s.landing_samples, [] {
      return SettingInfo{"release.landing_samples", "samples",
                         "consecutive samples that are not free make a landing (a clipped accelerometer "
                         "counts), so one ringing sample does not. Not swept"};
    });
    v(s.flight_level_samples, [] {
      return SettingInfo{"release.flight_level_samples", "samples",
                         "the flight's residual level while airborne is a running mean over about this "
                         "many samples, the history's length. Not swept"};
    });
  }

  template <typename Self, typename Visitor>
  static void visit_lever_arm(Self& s, Visitor& v) {
    v(s.max_lever_arm_m, [] {
      return SettingInfo{"release.max_lever_arm_m", "m",
                         "a fitted r beyond this is not an IMU inside the body: a physical bound, the "
                         "size of a thrown body"};
    });
    v(s.given_r_tolerance_m, [] {
      return SettingInfo{"release.given_r_tolerance_m", "m",
                         "a given r that misses a torque-free sample: a fit this close may replace it. "
                         "With it a given r 3 mm off (tensor 15 % wrong) found 100 % of releases within "
                         "10 ms, none early, from 96.7 % (tests/host/test_release_detection.cpp)"};
    });
    v(s.fit_rms_fraction, [] {
      return SettingInfo{"release.fit_rms_fraction", "",
                         "a fitted r counts only when its rms residual is below this fraction of the "
                         "limit. Set on the generated throws; not swept"};
    });
    v(s.ridge_rad_s2, [] {
      return SettingInfo{"release.ridge_rad_s2", "rad/s²",
                         "ridge of the r fit, (this)² per sample: pins the part of r along a fixed spin "
                         "axis, which no sample sees, to zero. Not swept"};
    });
  }

  template <typename Self, typename Visitor>
  static void visit_fade_out(Self& s, Visitor& v) {
    v(s.fade_out_at_most_us, [] {
      return SettingInfo{"release.fade_out_at_most_us", "µs",
                         "a fading hand force is extrapolated this far at most; samples this far apart "
                         "(under about 285 Hz) are dated between samples. Set on the generated throws at "
                         "100-250 Hz; not swept"};
    });
    v(s.step_fraction, [] {
      return SettingInfo{"release.step_fraction", "",
                         "samples far apart: release where the residual crossed this fraction of its step. "
                         "A 2nd-order filter at rate/4 delays the crossing by 3.6-9 ms at 250-100 Hz, more "
                         "than a 2-10 ms fade crosses half before it ends (0.7-3.3 ms): derived"};
    });
    v(s.steepest_fall_from_us, [] {
      return SettingInfo{"release.steepest_fall_from_us", "µs",
                         "samples this far apart (under about 1.1 kHz) date a fading force from its "
                         "steepest fall: above 1.1 kHz that rule came out up to 0.43 ms early on 5 "
                         "generated throws at 2 and 4 kHz"};
    });
    v(s.fall_from_over_level, [] {
      return SettingInfo{"release.fall_from_over_level", "",
                         "samples closer: the fall is taken from the newest earlier sample above this "
                         "times the flight's level. Set with that rule on the generated throws; not swept"};
    });
    v(s.fall_chord_us, [] {
      return SettingInfo{"release.fall_chord_us", "µs",
                         "each fall measured over at least this long: 400 Hz behind a 100 Hz filter, "
                         "releases dated without it came 5-9 ms late (63-70 % within 10 ms)"};
    });
    v(s.fall_search_samples, [] {
      return SettingInfo{"release.fall_search_samples", "samples",
                         "samples before the first flight-level one searched for that fall: the filter's "
                         "tail spans a few samples of 5-10 ms there. Set with the chord; not swept"};
    });
    v(s.step_search_samples, [] {
      return SettingInfo{"release.step_search_samples", "samples",
                         "samples far apart: this many before the first flight-level sample are searched "
                         "for the step's top. Not swept"};
    });
  }
};

// A release found: its first free-flight sample, its time (earlier than that sample's
// stamp when the samples are too far apart to resolve the hand's force fading out), and
// the lever arm it was found with.
template <typename Scalar>
struct FoundRelease {
  bool found = false;
  std::uint32_t index = 0;
  std::uint64_t release_us = 0;
  Vec3<Scalar> r = Vec3<Scalar>::Zero();
  bool r_fitted = false;  // r was fitted (none given, or the given one missed)
};

// A landing found: its first sample and its time (between that sample and the one before
// when the samples are far apart, see level_crossing).
struct FoundLanding {
  bool found = false;
  std::uint32_t index = 0;
  std::uint64_t landing_us = 0;
};

// TorqueTest: the gyro's torque test, of the body alone or of a body with a rotor
// (aloft/onboard/torque_test.hpp).
template <typename Scalar, int N, typename TorqueTest = BodyTorqueTest<Scalar>>
class ReleaseDetector {
 public:
  using History = SampleHistory<Scalar, N>;

  // The settings are held, not copied (a pipeline's parts share its one copy): they must
  // outlive the detector, as must what the torque test holds.
  ReleaseDetector(const ReleaseDetectorSettings<Scalar>& settings, const TorqueTest& torque)
      : settings_(settings), torque_(torque) {}
  ReleaseDetector(ReleaseDetectorSettings<Scalar>&&, const TorqueTest&) = delete;

  void reset() {
    in_run_ = false;
    landing_run_ = 0;
  }

  // Is sample i free (torque-free gyro, residual within the limit for lever arm r)?
  bool free_at(const History& history, std::uint32_t i, std::uint32_t h, const Vec3<Scalar>& r) const {
    BodyKinematics<Scalar> k;
    if (!history.kinematics(i, h, k)) return false;
    return torque_free(history, i, h, k) && centre_specific_force(k, r) <= limit(k, r);
  }

  // Evaluates sample c while waiting for release; r is the known lever arm or null (then
  // fitted). Found once release is confirmed, dated no earlier than not_before_us.
  ALOFT_COLD FoundRelease<Scalar> find_release(const History& history, std::uint32_t c, std::uint32_t h,
                                               const Vec3<Scalar>* r, std::uint64_t not_before_us) {
    FoundRelease<Scalar> out;
    const BodyKinematics<Scalar>& k = newest_.k;
    if (!tested(history, c, h) || !newest_.torque_free) {
      in_run_ = false;
      given_missed_ = c;
      return out;
    }
    if (!in_run_ || !history.holds(run_start_ - h)) run_start_ = in_run_ ? history.oldest() + h : c;
    in_run_ = true;
    const bool given_fits = r != nullptr && centre_specific_force(k, *r) <= limit(k, *r);
    if (!given_fits) given_missed_ = c;
    std::uint32_t start = 0;
    out.r_fitted = !given_fits;
    if (given_fits) {
      // The run of samples the given r fits: from the last miss on, inside the torque-free run.
      start = given_missed_ + 1 > run_start_ ? given_missed_ + 1 : run_start_;
      out.r = *r;
    } else if (!fit_free_stretch(history, c, h, k, r, start, out.r)) {
      return out;
    }
    if (!confirmed(history, start, c, h) || history.t_us(start) < not_before_us) return out;
    out.found = true;
    out.index = first_at_flight_level(history, start, c, h, out.r);
    out.release_us = history.t_us(out.index);
    if (out.index > 0 && history.dt_us(out.index) >= settings_.fade_out_at_most_us) {
      out.release_us = crossing_before(history, out.index, h, out.r);
    }
    return out;
  }

  // Evaluates sample c while airborne. Found once landing is confirmed.
  // `not_before`: the first sample that may still be dated the landing (not yet fed).
  // Out of line: its floating-point registers are saved on its own frame, not on its
  // caller's, which the release window's dating and the flight's end run under.
  ALOFT_OUT_OF_LINE FoundLanding find_landing(const History& history, std::uint32_t c, std::uint32_t h,
                                              const Vec3<Scalar>& r, std::uint32_t not_before) {
    FoundLanding out;
    const BodyKinematics<Scalar>& k = newest_.k;
    bool evidence = false;
    if (tested(history, c, h)) {
      const ResidualAndLimit<Scalar> e = residual_and_limit(settings_.free_flight, k, r);
      evidence = !newest_.torque_free || e.residual > e.limit;
      if (!evidence) {
        landing_run_ = 0;
        flight_level_ += (e.residual - flight_level_) / static_cast<Scalar>(settings_.flight_level_samples);
      }
    } else {
      evidence = (history.flags(c) & imu_accel_clipped) != 0;  // else: no verdict, run kept
    }
    if (evidence) {
      if (landing_run_ == 0) landing_start_ = c;
      ++landing_run_;
    }
    if (landing_run_ < settings_.landing_samples) return out;
    std::uint32_t landing = landing_start_;
    // Back to where the residual left the flight's own level (a force that builds up).
    const Scalar level = settings_.level_over_flight_mean * flight_level_ + settings_.level_margin_m_s2;
    while (landing > not_before && history.holds(landing - 1 - h) &&
           residual_above(history, landing - 1, h, r, level)) {
      --landing;
    }
    out.found = true;
    out.index = landing;
    out.landing_us = history.t_us(landing);
    if (landing > not_before && history.dt_us(landing) >= settings_.fade_out_at_most_us) {
      out.landing_us = level_crossing(history, landing, h, r, level);
    }
    return out;
  }

  // Samples too far apart to see the force build up: the landing lies between the last
  // sample at flight level and the next. The residual, interpolated linearly between them,
  // crosses the level too early on a rising, filtered edge and the next sample is up to an
  // interval late: the landing is dated halfway between the two (measured on generated
  // catches and impacts at 100 and 250 Hz, tests/host/test_release_detection.cpp).
  ALOFT_COLD std::uint64_t level_crossing(const History& history, std::uint32_t j, std::uint32_t h,
                                          const Vec3<Scalar>& r, Scalar level) const {
    const Scalar before = residual(history, j - 1, h, r);
    const Scalar after = residual(history, j, h, r);
    if (!(before >= Scalar(0)) || !(after > level) || !(before < level)) return history.t_us(j);
    const Scalar part = Scalar(0.5) + Scalar(0.5) * (level - before) / (after - before);
    return history.t_us(j - 1) + whole_us(part * static_cast<Scalar>(history.dt_us(j)));
  }

  // The sample the last find_release or find_landing evaluated: its kinematics (when
  // `valid`) and the gyro's torque verdict, for the pipeline's window
  // (aloft/onboard/release_window.hpp) to take without forming them again.
  struct TestedSample {
    bool valid = false;
    bool torque_free = false;
    BodyKinematics<Scalar> k;
  };
  const TestedSample& newest_tested() const { return newest_; }

  // Samples from this index on may still turn out to be the landing (not to be fed yet).
  std::uint32_t pending_from(std::uint32_t c) const { return landing_run_ > 0 ? landing_start_ : c + 1; }

  bool torque_free(const History& history, std::uint32_t i, std::uint32_t h,
                   const BodyKinematics<Scalar>& k) const {
    if constexpr (TorqueTest::knows_rotor) {
      return torque_.relative(history, i, h, k) <= settings_.free_flight.torque_relative;
    } else {
      // The body's test called here, not through the test's own relative(): the compiler
      // then lays the image out as before the rotor's test (8 B of alignment padding else).
      return relative_torque(torque_.inertia(), torque_.scale_floor(), k) <=
             settings_.free_flight.torque_relative;
    }
  }
  // The torque test of sample i (kinematics k over +-h), remembered for the 32 newest
  // samples tested: the pipeline's lever-arm fit takes the same samples a few steps later
  // (torque_free_remembered) and need not repeat it.
  bool torque_free_at(const History& history, std::uint32_t i, std::uint32_t h,
                      const BodyKinematics<Scalar>& k) {
    const bool free = torque_free(history, i, h, k);
    if (h != memo_h_ || i != memo_newest_ + 1u) memo_known_ = 0;  // only a gapless run is kept
    const std::uint32_t bit = 1u << (i % 32u);
    memo_h_ = h;
    memo_newest_ = i;
    memo_known_ |= bit;
    memo_free_ = free ? (memo_free_ | bit) : (memo_free_ & ~bit);
    return free;
  }
  bool torque_free_remembered(const History& history, std::uint32_t i, std::uint32_t h,
                              const BodyKinematics<Scalar>& k) const {
    const std::uint32_t bit = 1u << (i % 32u);
    if (h == memo_h_ && i <= memo_newest_ && memo_newest_ - i < 32u && (memo_known_ & bit) != 0) {
      return (memo_free_ & bit) != 0;
    }
    return torque_free(history, i, h, k);
  }
  Scalar limit(const BodyKinematics<Scalar>& k, const Vec3<Scalar>& r) const {
    return free_flight_accel_limit(settings_.free_flight, k, r);
  }
  const ReleaseDetectorSettings<Scalar>& settings() const { return settings_; }

 private:
  // The earliest start in [run_start_, c] whose fitted r passes (see the file comment).
  // near: a given (or earlier estimated) r that did not fit this stretch; the fit must then
  // lie within given_r_tolerance_m of it.
  ALOFT_COLD bool fit_free_stretch(const History& history, std::uint32_t c, std::uint32_t h,
                                   const BodyKinematics<Scalar>& kc, const Vec3<Scalar>* near,
                                   std::uint32_t& start, Vec3<Scalar>& r_fit) const {
    // The fit must lie in a ball: about the given r, else about the centre of mass.
    const Vec3<Scalar> centre = near != nullptr ? *near : Vec3<Scalar>::Zero();
    const Scalar radius = near != nullptr ? settings_.given_r_tolerance_m : settings_.max_lever_arm_m;
    LeverArmFit<Scalar> fit;
    bool found = false;
    for (std::uint32_t j = c + 1; j-- > run_start_;) {
      BodyKinematics<Scalar> kj;
      if (!history.kinematics(j, h, kj)) break;
      fit.add(kj);
      const Vec3<Scalar> r = fit.solve(settings_.ridge_rad_s2);
      if ((r - centre).squaredNorm() > radius * radius) continue;
      const Scalar lc = limit(kc, r);
      if (fit.rms_residual(r) > settings_.fit_rms_fraction * lc || centre_specific_force(kc, r) > lc ||
          centre_specific_force(kj, r) > limit(kj, r)) {
        continue;
      }
      start = j;
      r_fit = r;
      found = true;
    }
    return found;
  }

  // Kinematics and torque verdict of sample c, kept as newest_.
  // Formed in newest_ itself, not copied there: every sample pays for the copy.
  bool tested(const History& history, std::uint32_t c, std::uint32_t h) {
    newest_.valid = history.kinematics(c, h, newest_.k);
    newest_.torque_free = newest_.valid && torque_free_at(history, c, h, newest_.k);
    return newest_.valid;
  }

  bool confirmed(const History& history, std::uint32_t start, std::uint32_t c, std::uint32_t h) const {
    const std::uint32_t n = c - start + 1;
    if (n + 2 * h + 2 >= static_cast<std::uint32_t>(N)) return true;  // as long as the history allows
    return n >= settings_.confirm_samples && history.span_us(start, c) >= settings_.confirm_us;
  }

  // The first sample of the trailing run of [start, c] whose residual is down at the level
  // of the stretch's later half: a hand force that fades out stays above it until it is
  // gone, where a fixed fraction of the limit would be crossed while it still acts.
  ALOFT_COLD std::uint32_t first_at_flight_level(const History& history, std::uint32_t start, std::uint32_t c,
                                                 std::uint32_t h, const Vec3<Scalar>& r) {
    Scalar sum = Scalar(0);
    std::uint32_t n = 0;
    for (std::uint32_t j = start + (c - start) / 2; j <= c; ++j) {
      BodyKinematics<Scalar> k;
      if (!history.kinematics(j, h, k)) continue;
      sum += centre_specific_force(k, r);
      ++n;
    }
    flight_level_ = n > 0 ? sum / static_cast<Scalar>(n) : Scalar(0);
    // The later half can still hold the end of a fading force (the stretch is only a few
    // milliseconds long): its level never counts above the floor.
    Scalar level = settings_.level_over_flight_mean * flight_level_ + settings_.level_margin_m_s2;
    if (level > settings_.free_flight.accel_floor_m_s2) level = settings_.free_flight.accel_floor_m_s2;
    // From the newest sample back: the release follows the last sample still above that
    // level, so a force that dips under it while it fades is not taken for the release.
    std::uint32_t j0 = c;
    while (j0 > start && !residual_above(history, j0 - 1, h, r, level)) --j0;
    return after_fade_out(history, j0, c, h, r, level);
  }

  // Where the hand's force ended: a fall of the residual, extended as a straight line to
  // zero; the first sample from then on is the release. Which fall depends on how far
  // apart the samples are:
  //  - under `steepest_fall_from_us`: from the newest earlier sample still above
  //    `fall_from_over_level` times the level to
  //    j0, the first at flight level. The last of a force that fades hides in the noise
  //    there, so the line runs on past j0 (noise at j0 can only move the release later).
  //    A weak push that never rose that high (a finger that touched again, 3-4 m/s²):
  //    from j0 - 1, the last sample above the level. Either way along the line through the
  //    residual's square root: a finger lifts off at zero slope (a raised-cosine fall), so
  //    its force is quadratic near its end, where a straight line through the residual
  //    reaches zero too early (a finger of 3-4 m/s² rises over twice a fitted r's level
  //    too: dated 0.05 and 0.2 ms early so). The root's line reaches zero no earlier than
  //    any force whose tail is quadratic or steeper, a hand's linear end included (there it
  //    comes later by the geometric mean of the two samples' times to the end, a few tenths
  //    of a millisecond behind a steep let-go). Measured, docs/validation/release-detection.md,
  //    "A finger's re-touch" (its price there: a rotor throw on a fresh seed set, released
  //    1.87 ms late rather than 31.6 ms, ends at its rotor's brake, its r fitted over a slow
  //    turn: "A body with a rotor").
  //  - from `steepest_fall_from_us` up to `fade_out_at_most_us` (about 285 Hz to 1.1 kHz): the
  //    sensor's anti-alias filter, set in proportion to its rate, draws the end of the
  //    force out into a tail of a few samples, and a few samples are 5-10 ms here (j0 came
  //    5-9 ms after the release at 400 Hz behind a 100 Hz filter). So the steepest fall in
  //    the `fall_search_samples` up to j0, each measured over at least `fall_chord_us`: its line reaches
  //    zero no earlier than a force that falls with a slope (or ever more steeply) has
  //    ended, and later by the filter's delay rather than by its settling.
  // The line is extended `fade_out_at_most_us` at most.
  ALOFT_COLD std::uint32_t after_fade_out(const History& history, std::uint32_t j0, std::uint32_t c,
                                          std::uint32_t h, const Vec3<Scalar>& r, Scalar level) const {
    std::uint32_t a = j0, b = j0;
    bool root = false;  // the line through the residual's square root (above)
    Scalar e_a = residual(history, j0, h, r), e_b = e_a;
    const std::uint32_t dt = history.dt_us(j0);
    const std::uint32_t searched = settings_.fall_search_samples;
    if (dt < settings_.steepest_fall_from_us) {
      const Scalar fall_from = settings_.fall_from_over_level * level;
      while (a > j0 - searched && a > h && history.holds(a - 1 - h)) {
        --a;
        e_a = residual(history, a, h, r);
        if (e_a < Scalar(0) || e_a > fall_from) break;
      }
      if (!(e_a > fall_from)) {  // a weak push (see above)
        if (j0 <= h + 1u || !history.holds(j0 - 2u - h)) return j0;
        a = j0 - 1u;
        e_a = residual(history, a, h, r);
      }
      root = true;
    } else {
      const std::uint32_t step =
          (settings_.fall_chord_us + dt - 1u) / dt;  // samples per fall, at least the chord
      Scalar steepest = Scalar(0);
      for (std::uint32_t end = j0; end + searched > j0 && end > h + step; --end) {
        const Scalar e_start = residual(history, end - step, h, r), e_end = residual(history, end, h, r);
        if (e_start < Scalar(0) || e_end < Scalar(0)) break;
        const Scalar slope = (e_start - e_end) / static_cast<Scalar>(history.span_us(end - step, end));
        if (slope > steepest) {
          steepest = slope;
          a = end - step;
          b = end;
          e_a = e_start;
          e_b = e_end;
        }
      }
    }
    if (!(e_a > e_b)) return j0;
    Scalar to_zero_us = static_cast<Scalar>(history.span_us(a, b)) * e_b / (e_a - e_b);
    if (root) {
      if (!(e_b >= Scalar(0))) return j0;  // no kinematics at j0
      const Scalar root_a = std::sqrt(e_a), root_b = std::sqrt(e_b);
      to_zero_us = static_cast<Scalar>(history.span_us(a, b)) * root_b / (root_a - root_b);
    }
    const Scalar cap_us = static_cast<Scalar>(settings_.fade_out_at_most_us);
    if (to_zero_us > cap_us) to_zero_us = cap_us;
    // In whole µs after b (the cap keeps it far below 2^32).
    const auto after_b_us = static_cast<std::uint32_t>(whole_us(to_zero_us));
    std::uint32_t j = b;
    while (j < c && history.span_us(b, j) < after_b_us) ++j;
    return j;
  }

  // Samples too far apart to see a hand's force fade (and an anti-alias filter that smears
  // the step over one or two of them): the release is where the residual, interpolated
  // between samples, crossed `step_fraction` of its value at the top of the step before
  // j0. The filter's delay keeps that crossing after the true release unless the force
  // faded over several sample intervals.
  ALOFT_COLD std::uint64_t crossing_before(const History& history, std::uint32_t j0, std::uint32_t h,
                                           const Vec3<Scalar>& r) const {
    // The top: the largest residual of the few samples before j0 (flight noise after the
    // step can leave j0 a sample or two late).
    std::uint32_t top = j0;
    Scalar e_top = Scalar(0);
    for (std::uint32_t j = j0; j > 0 && j + settings_.step_search_samples > j0;) {
      --j;
      const Scalar e = residual(history, j, h, r);
      if (e > e_top) {
        top = j;
        e_top = e;
      }
    }
    if (top == j0) return history.t_us(j0);
    const Scalar mark = settings_.step_fraction * e_top;
    std::uint32_t j = j0 - 1;
    while (j > top && residual(history, j, h, r) <= mark) --j;
    const Scalar e_j = residual(history, j, h, r);
    const Scalar e_next = residual(history, j + 1, h, r);
    if (!(e_next >= Scalar(0)) || !(e_j > e_next)) return history.t_us(j0);
    Scalar part = (e_j - mark) / (e_j - e_next);
    if (part > Scalar(1)) part = Scalar(1);  // j0 itself above the mark: no later than j + 1
    return history.t_us(j) + whole_us(part * static_cast<Scalar>(history.dt_us(j + 1)));
  }

  // |a - K r| at sample j, or -1 when its kinematics are not available.
  Scalar residual(const History& history, std::uint32_t j, std::uint32_t h, const Vec3<Scalar>& r) const {
    BodyKinematics<Scalar> k;
    return history.kinematics(j, h, k) ? centre_specific_force(k, r) : Scalar(-1);
  }

  ALOFT_COLD bool residual_above(const History& history, std::uint32_t j, std::uint32_t h,
                                 const Vec3<Scalar>& r, Scalar level) const {
    BodyKinematics<Scalar> k;
    if (!history.kinematics(j, h, k)) return true;
    const Scalar e = centre_specific_force(k, r);
    return e > level || e > settings_.release_fraction * limit(k, r);
  }

  const ReleaseDetectorSettings<Scalar>& settings_;
  TorqueTest torque_;
  TestedSample newest_;
  std::uint32_t run_start_ = 0;
  std::uint32_t landing_start_ = 0;
  std::uint16_t landing_run_ = 0;
  bool in_run_ = false;                      // a run of torque-free samples, from run_start_
  std::uint32_t given_missed_ = 0;           // the newest sample the given r did not fit (or not torque-free)
  Scalar flight_level_ = Scalar(0);          // running mean residual in flight (m/s²)
  std::uint32_t memo_newest_ = 0xFFFFFFFFu;  // torque_free_at: the newest sample tested
  std::uint32_t memo_h_ = 0;
  std::uint32_t memo_known_ = 0;  // bit i % 32: sample i tested, with memo_h_
  std::uint32_t memo_free_ = 0;   // bit i % 32: and found torque-free
};

}  // namespace aloft
