// Release as a test over a window, not over single samples. The sample-by-sample detector
// (aloft/onboard/release_detector.hpp) proposes a release; the pipeline then keeps the flight on
// probation for `window_us` and dates the release anew from what the window shows:
//  - The samples are summed in blocks of about `block_us` (at least one sample each): a
//    block's mean specific force and mean lever-arm matrix K (aloft/dynamics/free_flight_residual.hpp).
//    A block mean cancels what a single sample cannot tell from a hand: a body's
//    structural modes ring at 100-800 Hz, and over 5 ms their mean is at most a fifth of
//    their amplitude (|sinc| past its first zero), where a hand's force, slow in body
//    axes, passes whole.
//  - One r explains the newest `fit_blocks` blocks (the surest free flight): fitted within
//    `given_r_tolerance_m` of a given r, or within `max_lever_arm_m` of the centre of mass
//    without one (aloft/onboard/lever_arm_estimate.hpp, over block means). What those blocks
//    leave, their mean residual vector, is the flight's own level (air drag, accelerometer
//    bias: constant over 25 ms in body axes to a tenth of a m/s²).
//  - A block is free when its mean residual is within `block_limit_floor_m_s2` plus
//    `block_limit_relative` of its |K r| of that level, and at most half its samples carry
//    a torque; and, given the body's tensor, when its mean torque-free residual lies near
//    the fit blocks' (torque_free_run: the gyro sees a push the accelerometer may not).
//    The release is the first sample of the trailing run of free blocks: later than
//    proposed when a slow let-go still pushed (its force is slow, and stays in the block
//    mean), earlier when a ringing body broke the sample-by-sample run.
//  - A run shorter than `min_free_us` is no flight yet: the proposal is withdrawn.
// The proposed release is kept (it is dated more finely than a block's grid) unless the
// window's lies more than one block after it, or more than two blocks before it (a proposal
// held back by ringing; closer than that, the block grid is no better than the proposal),
// or the block before the run is not free and starts at or after the proposal (a finger
// that touched again), or holds the proposal and a push that went on past it (pushes_past);
// and at rates where a block holds fewer than `min_block_samples` samples. A release moved
// to a run after a block that is not free is dated past that push's tail (tail_samples).
// A push can hide in the fit itself: a finger that touches again while the newest blocks are
// fitted lifts the flight's level with it, and the blocks before it then look free. Such a
// fit leaves its own blocks apart (a block farther than the floor of a free block from the
// level), or, where the push lasts through all of them, a level farther from zero than a
// free block may lie from it: either way it is not `settled`, and the window then looks
// once more, 2 window_us past the release as dated, with the newest blocks past the push;
// that later look only ever dates the release later, and only from a settled fit of its
// own (the pipeline's rule; docs/validation/release-detection.md, "A finger's re-touch").
// Where the first look had itself moved the release, its date is no finer than the block
// grid and came from the unsettled fit: the later look then dates it anew from its own
// blocks wherever its run starts after it (`dated_over_blocks`).
#pragma once

#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/onboard/lever_arm_estimate.hpp"
#include "aloft/settings.hpp"

namespace aloft {

template <typename Scalar>
struct ReleaseWindowSettings {
  std::uint32_t window_us = 25000;
  std::uint32_t block_us = 5000;
  std::uint16_t fit_blocks = 3;
  // A block's mean residual off the flight's level that is still free flight (m/s²):
  // floor + relative |K r|.
  Scalar block_limit_floor_m_s2 = Scalar(0.8);
  Scalar block_limit_relative = Scalar(0.02);
  std::uint32_t min_free_us = 15000;
  std::uint16_t min_block_samples = 4;

  // The one list of these settings (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.window_us, [] {
      return SettingInfo{"release_window.window_us", "µs",
                         "free flight this long after a proposed release before it is dated over blocks: "
                         "on the held-back real throws a hand let go over its last 20-30 ms. The ring of "
                         "blocks is sized for the default (ReleaseWindow::ring_blocks): above it the later "
                         "look, at twice this, may not see back to the release, and keeps it"};
    });
    v(s.block_us, [] {
      return SettingInfo{"release_window.block_us", "µs",
                         "block span: one period of a 200 Hz mode, so structural modes average out. Chosen "
                         "among 4-5 ms on the tuned seed set of tests/host/test_release_detection.cpp, "
                         "\"real hands\", and reported on the held-out set"};
    });
    v(s.fit_blocks, [] {
      return SettingInfo{"release_window.fit_blocks", "blocks",
                         "the newest blocks that set r and the flight's level (15 ms of the 25). Not swept"};
    });
    v(s.block_limit_floor_m_s2, [] {
      return SettingInfo{"release_window.block_limit_floor_m_s2", "m/s²",
                         "a block's mean residual this far off the flight's level is still free: white "
                         "noise over a block, a mode's leak, drag. Chosen among 0.4-1.0 on the tuned seed "
                         "set, \"real hands\""};
    });
    v(s.block_limit_relative, [] {
      return SettingInfo{"release_window.block_limit_relative", "",
                         "plus this fraction of |K r| (scale errors of 2 %, r a millimetre off). Chosen "
                         "among 0.01-0.04 on the tuned seed set"};
    });
    v(s.min_free_us, [] {
      return SettingInfo{"release_window.min_free_us", "µs",
                         "a shorter trailing run of free blocks withdraws the proposal: a body rang for "
                         "about 15 ms after the hand let go on the held-back real throws"};
    });
    v(s.min_block_samples, [] {
      return SettingInfo{"release_window.min_block_samples", "samples",
                         "blocks of fewer samples (under 800 Hz) keep the sample-by-sample release: dated "
                         "by blocks, 25-88 % of the 100-700 Hz generated releases came within 10 ms, "
                         "against 98-100 %"};
    });
  }
};

// Where a lever arm may lie: a ball (about a given r, or about the centre of mass), and
// the r to use when the window's fit leaves it.
template <typename Scalar>
struct LeverArmBall {
  Vec3<Scalar> centre = Vec3<Scalar>::Zero();
  Scalar radius_m = Scalar(0);
  Vec3<Scalar> otherwise = Vec3<Scalar>::Zero();
  Scalar ridge_rad_s2 = Scalar(10);  // aloft/onboard/lever_arm_estimate.hpp
};

// What the window made of a proposed release.
template <typename Scalar>
struct WindowedRelease {
  bool decided = false;     // false: the window is not yet full
  bool free = false;        // decided: free flight for at least min_free_us
  bool settled = false;     // free: each fit block near the level, and the level a flight's
  std::uint32_t index = 0;  // the release's first sample
  std::uint64_t release_us = 0;
};

template <typename Scalar>
class ReleaseWindow {
 public:
  // The window's 5 closed blocks past the proposal, its own block, the open one, and 5
  // before it: a proposal held back by ringing can be moved up to 25 ms earlier. Fixed
  // at build time (the records' settings hash takes it), derived from the default
  // window_us and block_us: other settings than those move the reach with them.
  static constexpr int ring_blocks = 12;
  static_assert(ring_blocks == 2 * static_cast<int>(ReleaseWindowSettings<float>{}.window_us /
                                                    ReleaseWindowSettings<float>{}.block_us) +
                                   2,
                "the ring holds the window's blocks either side of the proposal, its own and the open one");
  // A later look comes 2 window_us past the release: its closed blocks still reach back to it.
  static_assert((ring_blocks - 1) * ReleaseWindowSettings<float>{}.block_us >=
                    2 * ReleaseWindowSettings<float>{}.window_us,
                "a later look's closed blocks reach back to the release it dates");

  // The settings are held, not copied (a pipeline's parts share its one copy): they must
  // outlive the window.
  explicit ReleaseWindow(const ReleaseWindowSettings<Scalar>& settings) : settings_(settings) {}
  explicit ReleaseWindow(ReleaseWindowSettings<Scalar>&&) = delete;

  // Sample i (stamp t_us, kinematics k), with the gyro's verdict on torque.
  ALOFT_OUT_OF_LINE void add(std::uint32_t i, std::uint64_t t_us, const BodyKinematics<Scalar>& k,
                             bool torque_free) {
    Block* b = &blocks_[newest_ % ring_blocks];
    if (count_ == 0) {
      b->start(i, t_us);
      count_ = 1;
    } else if (static_cast<std::uint32_t>(t_us) - b->start_low_us >= settings_.block_us || i != next_index_) {
      ++newest_;
      if (count_ < ring_blocks) ++count_;
      b = &blocks_[newest_ % ring_blocks];
      b->start(i, t_us);
    }
    b->k_sum += lever_arm_matrix(k.w, k.w_dot);
    b->a_sum += k.a;
    next_index_ = i + 1;
    ++b->samples;
    if (!torque_free) ++b->torque_samples;
  }

  // The release proposed at proposed_us (sample proposed_index), judged once the closed
  // blocks reach window_us past it (a later look: twice that), with r fitted within `ball`,
  // and each block's torque tested against `inertia` (the body's tensor; null: not tested).
  // `dated_over_blocks`: a later look at a release the first look moved (file comment).
  ALOFT_COLD WindowedRelease<Scalar> date(std::uint32_t proposed_index, std::uint64_t proposed_us,
                                          const LeverArmBall<Scalar>& ball, bool later_look = false,
                                          const Mat3<Scalar>* inertia = nullptr,
                                          bool dated_over_blocks = false) const {
    WindowedRelease<Scalar> out;
    if (count_ < 2u + settings_.fit_blocks) return out;
    // Stamps as their low 32 bits (a block's), spans as differences: exact below 35 min.
    const std::uint32_t end_low = blocks_[newest_ % ring_blocks].start_low_us;  // the open block's
    const auto proposed_low = static_cast<std::uint32_t>(proposed_us);
    const std::uint32_t reach_us = later_look ? 2u * settings_.window_us : settings_.window_us;
    if (static_cast<std::int32_t>(end_low - proposed_low) < static_cast<std::int32_t>(reach_us)) return out;
    out.decided = true;
    const Vec3<Scalar> r = window_r(ball);
    bool a_push = false;
    const Vec3<Scalar> level = flight_level(r, a_push);
    std::uint32_t run = 0;  // closed blocks in the trailing free run
    // Its fit blocks so far within the floor of a free block of the level, and the level
    // itself a flight's (a later look dates only later, from fit blocks past the push).
    bool settled = later_look || !a_push;
    const Scalar floor = settings_.block_limit_floor_m_s2;
    for (; run + 1u < count_; ++run) {
      const Scalar excess_sq = free_excess_sq(closed(run), r, level);
      if (excess_sq < Scalar(0)) break;
      if (run < settings_.fit_blocks && excess_sq > floor * floor) settled = false;
    }
    if (inertia != nullptr) run = torque_free_run(*inertia, run, end_low, settled);
    if (run == 0u) return out;
    const Block& first = closed(run - 1u);
    if (end_low - first.start_low_us < settings_.min_free_us) return out;
    out.free = true;
    out.settled = settled && run >= settings_.fit_blocks;
    // Blocks of few samples date no better than the sample-by-sample rules (file comment).
    const auto after_us = static_cast<std::int32_t>(first.start_low_us - proposed_low);
    const auto block_us = static_cast<std::int32_t>(settings_.block_us);
    // A block that is not free and starts at or after the proposal: a push after the
    // proposed release (a finger that touched again), whose tail may reach into the run.
    const bool pushed_after =
        run + 1u < count_ && static_cast<std::int32_t>(closed(run).start_low_us - proposed_low) >= 0;
    // Later only where the ring holds a block before the run: a run from the oldest block held
    // may start before it (a later look under a window_us above the default's, for which the
    // ring is sized, or a recording's first 60 ms).
    const bool later = after_us > block_us && run + 1u < count_;
    const bool pushed_through = !pushed_after && after_us > 0 && run + 2u < count_ &&
                                pushes_past(proposed_low, closed(run), closed(run + 1u), first, r, level);
    // A release the first look dated over blocks from an unsettled fit: no finer than the
    // grid, and its tail taken from blocks the push had lifted (traced: 0.35 ms early at
    // 2 kHz, a tail that the first look's excesses made run past its block).
    const bool regridded = later_look && dated_over_blocks && after_us > 0;
    const bool moved = (later || after_us < -2 * block_us || pushed_after || pushed_through || regridded) &&
                       first.samples >= settings_.min_block_samples;
    if (!moved) {
      out.index = proposed_index;
      out.release_us = proposed_us;
      return out;
    }
    const std::uint32_t tail = run + 1u < count_ ? tail_samples(closed(run), run - 1u, r, level) : 0u;
    const std::uint32_t next_low = run >= 2u ? closed(run - 2u).start_low_us : end_low;
    out.index = first.first_index + tail;
    out.release_us = static_cast<std::uint64_t>(static_cast<std::int64_t>(proposed_us) + after_us) +
                     tail * (next_low - first.start_low_us) / first.samples;
    return out;
  }

  // The first sample of the oldest block held (with none, the next to come).
  std::uint32_t oldest_index() const {
    return count_ == 0 ? next_index_ : blocks_[(newest_ + 1u - count_) % ring_blocks].first_index;
  }

 private:
  // Left uninitialised until start(): a pipeline in static memory costs no start-up code.
  struct Block {
    void start(std::uint32_t i, std::uint64_t t_us) {
      k_sum.setZero();
      a_sum.setZero();
      start_low_us = static_cast<std::uint32_t>(t_us);
      first_index = i;
      samples = 0;
      torque_samples = 0;
    }
    Mat3<Scalar> k_sum;
    Vec3<Scalar> a_sum;
    std::uint32_t start_low_us;  // the first sample's stamp, low 32 bits
    std::uint32_t first_index;
    std::uint16_t samples;
    std::uint16_t torque_samples;
  };

  // How many of the first free block's samples the push before it may still reach into.
  // The push's level is the mean of the block before (at most its peak, when it covered
  // only part of that block: the tail comes out longer). A finger lifts off at zero slope,
  // so the end of its fall is quadratic, and the first free block starts in that end (the
  // block before it took the fall's steep middle): a quadratic fall to zero averages a
  // third of its start, and lasts three times the first block's mean excess over its
  // samples, over the push's level. (From the top of a raised cosine or along a straight
  // line the force averages half its start: two times, the factor before, which left
  // tails short by 0.05-0.1 ms where the block started mid-fall.) Not a bound: a block that
  // starts further down the fall than the push's level says comes out short still.
  // Measured (tests/host/test_release_detection.cpp, re-touch): without the tail the first
  // free block's start came up to 5 ms before the finger's end; with it, once, 16 of 324
  // fast-hand releases were early against 31 with half of it; docs/validation/
  // release-detection.md, "A finger's re-touch".
  ALOFT_COLD std::uint32_t tail_samples(const Block& pushed, std::uint32_t first_n, const Vec3<Scalar>& r,
                                        const Vec3<Scalar>& level) const {
    constexpr Scalar fall_over_mean = Scalar(3);
    const Block& first = closed(first_n);
    const Scalar push = excess(pushed, r, level);
    const Scalar first_excess = excess(first, r, level);
    const Scalar most = static_cast<Scalar>(first.samples - 1u);
    Scalar samples = fall_over_mean * static_cast<Scalar>(first.samples) * first_excess / push;
    if (!(samples <= most)) samples = most;  // and a push of zero (never: the block is not free)
    const auto whole = static_cast<std::uint32_t>(samples);
    return static_cast<Scalar>(whole) < samples ? whole + 1u : whole;  // rounded up
  }

  // Whether the push in the block holding the proposal reached past it. A let-go's force only
  // falls: before the proposal it is no more than the block before's mean, and after it a
  // free stretch lies within a free block's floor; a mean above both shares pushed past it.
  ALOFT_COLD bool pushes_past(std::uint32_t proposed_low, const Block& holding, const Block& before,
                              const Block& next, const Vec3<Scalar>& r, const Vec3<Scalar>& level) const {
    const Scalar share = static_cast<Scalar>(proposed_low - holding.start_low_us) /
                         static_cast<Scalar>(next.start_low_us - holding.start_low_us);
    return excess(holding, r, level) >
           share * excess(before, r, level) + (Scalar(1) - share) * settings_.block_limit_floor_m_s2;
  }

  // The n-th newest closed block (0: the newest; the open block is not yet closed). Out of
  // line: on the STM32F405, 240 B of flash less than inlined into the cold paths that call it.
  ALOFT_OUT_OF_LINE const Block& closed(std::uint32_t n) const {
    return blocks_[(newest_ - 1u - n) % ring_blocks];
  }

  // How far a block's mean residual vector for lever arm r lies from the level (m/s²). Cold:
  // one copy for its four calls (tail_samples, pushes_past), themselves cold; like
  // flight_level and free_excess_sq, date()'s alone, it runs when a release is dated, not
  // per sample (on the STM32F405 the three cold, not -O3, are 128 B of flash less).
  ALOFT_COLD static Scalar excess(const Block& b, const Vec3<Scalar>& r, const Vec3<Scalar>& level) {
    return ((b.a_sum - b.k_sum * r) / static_cast<Scalar>(b.samples) - level).norm();
  }

  ALOFT_COLD Vec3<Scalar> window_r(const LeverArmBall<Scalar>& ball) const {
    LeverArmFit<Scalar> fit;
    for (std::uint32_t n = 0; n < settings_.fit_blocks; ++n) {
      const Block& b = closed(n);
      const Scalar samples = static_cast<Scalar>(b.samples);
      fit.add_mean(b.k_sum / samples, b.a_sum / samples, b.samples);
    }
    const Vec3<Scalar> r = fit.solve(ball.ridge_rad_s2);
    return (r - ball.centre).squaredNorm() <= ball.radius_m * ball.radius_m ? r : ball.otherwise;
  }

  // The fit blocks' level, and whether it is a push: a level farther from zero than a free
  // block may lie from it is a push that lasted through the fit blocks, not the flight's own
  // (drag, an accelerometer's bias and scale error: the free-block limit's floor and relative
  // part). A finger that touched again for 15 ms under a given r left a level of 3.8 m/s²
  // where the limit was 1.4, and the blocks before it, at the finger's level, looked free.
  // The fit is then not settled, and the later look dates the release past the push.
  // Measured on fresh seeds (docs/validation/release-detection.md, "A finger's re-touch").
  ALOFT_COLD Vec3<Scalar> flight_level(const Vec3<Scalar>& r, bool& a_push) const {
    Vec3<Scalar> sum = Vec3<Scalar>::Zero();
    Scalar k_r_sum = Scalar(0);
    Scalar samples = Scalar(0);
    for (std::uint32_t n = 0; n < settings_.fit_blocks; ++n) {
      const Block& b = closed(n);
      const Vec3<Scalar> k_r = b.k_sum * r;
      sum += b.a_sum - k_r;
      k_r_sum += k_r.norm();
      samples += static_cast<Scalar>(b.samples);
    }
    const Vec3<Scalar> level = sum / samples;
    const Scalar limit = free_limit(k_r_sum / samples);
    a_push = level.squaredNorm() > limit * limit;
    return level;
  }

  // How far a free block's mean residual may lie from the level (m/s²), for a mean |K r| of
  // `mean_k_r_m_s2`: the floor plus the relative part.
  Scalar free_limit(Scalar mean_k_r_m_s2) const {
    return settings_.block_limit_floor_m_s2 + settings_.block_limit_relative * mean_k_r_m_s2;
  }

  // A free block's mean residual's squared distance from the level (m²/s⁴); -1 for a block
  // that is not free. K r once, for the limit and the residual (168 B of flash less than
  // twice).
  ALOFT_COLD Scalar free_excess_sq(const Block& b, const Vec3<Scalar>& r, const Vec3<Scalar>& level) const {
    if (2u * b.torque_samples > b.samples) return Scalar(-1);
    const Vec3<Scalar> k_r = b.k_sum * r;
    const Scalar samples = static_cast<Scalar>(b.samples);
    const Scalar limit = free_limit(k_r.norm() / samples);
    const Scalar excess_sq = ((b.a_sum - k_r) / samples - level).squaredNorm();
    return excess_sq <= limit * limit ? excess_sq : Scalar(-1);
  }

  struct TorqueLevel {
    Vec3<Scalar> residual;  // the fit blocks' mean torque-free residual
    Scalar inertia_sq;      // |I|², the limits' unit
    std::uint32_t middle_low_us;
  };

  // The trailing run of `run` blocks that the force leaves free, shortened to the blocks
  // whose torque is free too (torque_apart), and `settled` false where a fit block's torque
  // lies apart. The torque only ever shortens a run the force leaves long enough: where it
  // would withdraw the flight, the fit is not settled instead, and the later look dates it.
  // Apart from date(): its frame is not under the lever arm's fit (the worst-case stack).
  ALOFT_COLD std::uint32_t torque_free_run(const Mat3<Scalar>& inertia, std::uint32_t run,
                                           std::uint32_t end_low, bool& settled) const {
    // The fit blocks' mean torque-free residual, their middle, and |I|².
    TorqueLevel level{Vec3<Scalar>::Zero(), inertia.squaredNorm(), 0};
    std::uint32_t samples = 0;
    for (std::uint32_t n = 0; n < settings_.fit_blocks; ++n) {
      level.residual += twice_torque_residual(inertia, closed(n).k_sum);
      samples += closed(n).samples;
    }
    level.residual /= static_cast<Scalar>(2u * samples);
    const std::uint32_t first_low = closed(settings_.fit_blocks - 1u).start_low_us;
    level.middle_low_us = first_low + (end_low - first_low) / 2u;
    std::uint32_t n = 0;
    for (; n < run; ++n) {
      const int apart = torque_apart(closed(n), inertia, level);
      if (n < settings_.fit_blocks && apart != 0) settled = false;
      if (apart == 2) break;
    }
    if (n == run) return run;
    if (n > 0u && end_low - closed(n - 1u).start_low_us >= settings_.min_free_us) return n;
    settled = false;
    return run;
  }

  // How far a block's mean torque-free residual lies off the fit blocks': 0 within its
  // noise and relative parts, 1 within the drift's too, 2 beyond (not free). The limit, in
  // units of |I| (rad/s²), is the root sum of squares of
  //  - noise_rad_s2 / sqrt(samples): a block mean of the gyro's w_dot, its noise;
  //  - relative |w|²: the tensor's error (15 % in the tests' "I 15 % off" cases), whose
  //    gyroscopic part the fit blocks' level takes up where w is the same;
  //  - drift_per_s |w| |w_dot| times the block's distance from the fit blocks' middle: that
  //    part's change as w turns.
  // Chosen on the tuned seeds of tests/host/test_release_detection.cpp and reported on
  // fresh ones (docs/validation/release-detection.md, "A finger's re-touch"): without the
  // drift term a spinning flight with the tensor 15 % off came 64 ms late, not 38 ms.
  // Constants, not settings: on the STM32F405 the settings' copy costs RAM and flash.
  ALOFT_COLD int torque_apart(const Block& b, const Mat3<Scalar>& inertia, const TorqueLevel& level) const {
    constexpr Scalar noise_rad_s2 = Scalar(20), relative_of_w_sq = Scalar(0.02), drift_per_s = Scalar(0.2);
    const Scalar samples = static_cast<Scalar>(b.samples);
    const Mat3<Scalar>& k = b.k_sum;
    const Scalar w_sq = Scalar(-0.5) * k.trace() / samples;
    const Scalar w_dot_sq = twice_w_dot_sum(k).squaredNorm() / (Scalar(4) * samples * samples);
    const auto age_us =
        static_cast<std::int32_t>(level.middle_low_us - b.start_low_us - settings_.block_us / 2u);
    const Scalar drift = drift_per_s * Scalar(1e-6) * static_cast<Scalar>(age_us < 0 ? -age_us : age_us);
    const Scalar relative = relative_of_w_sq * w_sq;
    const Scalar apart_sq =
        (twice_torque_residual(inertia, k) / (Scalar(2) * samples) - level.residual).squaredNorm();
    const Scalar noise_sq = level.inertia_sq * (noise_rad_s2 * noise_rad_s2 / samples + relative * relative);
    const Scalar drift_sq = level.inertia_sq * drift * drift * w_sq * w_dot_sq;
    return (apart_sq > noise_sq) + (apart_sq > noise_sq + drift_sq);
  }

  const ReleaseWindowSettings<Scalar>& settings_;
  Block blocks_[ring_blocks];
  std::uint32_t newest_ = 0;      // the open block: blocks_[newest_ % ring_blocks]
  std::uint32_t count_ = 0;       // blocks held, the open one included
  std::uint32_t next_index_ = 0;  // the index the open block takes next (another starts a block)
};

}  // namespace aloft
