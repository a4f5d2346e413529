// From the onboard pipeline's result (aloft/onboard/onboard_pipeline.hpp) to a flight record
// (aloft/records/flight_record.hpp), and the two hashes a record carries so that a result can be
// matched to the tensor and settings it was checked with. Both hashes are CRC-32
// (aloft/records/crc32.hpp) over little-endian bytes, numbers as IEEE-754 binary32 whatever
// Scalar is (a firmware checks in float):
//   tensor hash:   Ixx, Iyy, Izz, Ixy, Ixz, Iyz of the tensor as given, kg·m² (24 bytes)
//   settings hash: every setting the onboard pipeline uses (OnboardPipelineSettings), in
//                  the order written in settings_hash below (183 bytes): K (u16),
//                  seed_every (u16), sensor_to_body w x y z, imu_position_known (u8),
//                  imu_position_m x y z, bridge_gap_up_to_us (u32),
//                  end_flight_after_gap_us (u32), gap_interval_factor, min_flight_us
//                  (u32), rearm_after_landing_us (u32), turned_at_least_rad,
//                  estimate_min_turn_rad, then release: accel_floor_m_s2,
//                  accel_relative, torque_relative, angular_accel_floor_rad_s2,
//                  confirm_us (u32), confirm_samples (u16), release_fraction,
//                  level_margin_m_s2, fade_out_at_most_us (u32), step_fraction,
//                  landing_samples (u16), max_lever_arm_m, fit_rms_fraction, ridge_rad_s2,
//                  derivative_half_span_us (u32), given_r_tolerance_m, then release_window:
//                  window_us (u32), block_us (u32), fit_blocks (u16),
//                  block_limit_floor_m_s2, block_limit_relative, min_free_us (u32),
//                  min_block_samples (u16), then release: fall_search_samples (u16),
//                  steepest_fall_from_us (u32), fall_chord_us (u32), step_search_samples
//                  (u16), flight_level_samples (u16), then clock: interval_mean_samples,
//                  half_span_min_samples, half_span_max_samples (u16 each), then lever_arm:
//                  half_block_samples (u16), halves_agree_m, halves_agree_relative,
//                  given_gives_way_after, missed_gives_way_after, solve_every_samples
//                  (u16 each), then feed_lag_samples (u16). gap_interval_factor and
//                  derivative_half_span_us are clock's, estimate_min_turn_rad is
//                  lever_arm's, in the places listed. (Unlisted types: f32.)
#pragma once

#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/records/crc32.hpp"
#include "aloft/records/flight_record.hpp"
#include "aloft/records/little_endian.hpp"
#include "aloft/onboard/onboard_pipeline.hpp"

namespace aloft {

template <typename Scalar>
std::uint32_t tensor_hash(const Mat3<Scalar>& tensor) {
  std::uint8_t bytes[24];
  const Scalar values[6] = {tensor(0, 0), tensor(1, 1), tensor(2, 2),
                            tensor(0, 1), tensor(0, 2), tensor(1, 2)};
  for (int i = 0; i < 6; ++i) le::put_f32(bytes + 4 * i, static_cast<float>(values[i]));
  return crc32(bytes, sizeof(bytes));
}

// Computed once, at start-up: optimised for size (ALOFT_COLD), it lists some 51 numbers.
template <typename Scalar>
ALOFT_COLD std::uint32_t settings_hash(const OnboardPipelineSettings<Scalar>& s, int live_simulations) {
  std::uint8_t bytes[183];
  std::uint8_t* p = bytes;
  const auto f32 = [&p](Scalar v) { le::put_f32(p, static_cast<float>(v)), p += 4; };
  const auto u32 = [&p](std::uint32_t v) { le::put_u32(p, v), p += 4; };
  const auto u16 = [&p](std::uint16_t v) { le::put_u16(p, v), p += 2; };
  u16(static_cast<std::uint16_t>(live_simulations));
  u16(s.check.seed_every);
  const Quat<Scalar>& q = s.check.sensor_to_body;
  for (const Scalar v : {q.w(), q.x(), q.y(), q.z()}) f32(v);
  le::put_u8(p, s.imu_position_known ? 1 : 0), p += 1;
  for (int i = 0; i < 3; ++i) f32(s.imu_position_m[i]);
  u32(s.bridge_gap_up_to_us);
  u32(s.end_flight_after_gap_us);
  f32(s.clock.gap_interval_factor);
  u32(s.min_flight_us);
  u32(s.rearm_after_landing_us);
  f32(s.turned_at_least_rad);
  f32(s.lever_arm.estimate_min_turn_rad);
  const ReleaseDetectorSettings<Scalar>& r = s.release;
  f32(r.free_flight.accel_floor_m_s2);
  f32(r.free_flight.accel_relative);
  f32(r.free_flight.torque_relative);
  f32(r.free_flight.angular_accel_floor_rad_s2);
  u32(r.confirm_us);
  u16(r.confirm_samples);
  f32(r.release_fraction);
  f32(r.level_margin_m_s2);
  u32(r.fade_out_at_most_us);
  f32(r.step_fraction);
  u16(r.landing_samples);
  f32(r.max_lever_arm_m);
  f32(r.fit_rms_fraction);
  f32(r.ridge_rad_s2);
  u32(s.clock.derivative_half_span_us);
  f32(r.given_r_tolerance_m);
  const ReleaseWindowSettings<Scalar>& w = s.release_window;
  u32(w.window_us);
  u32(w.block_us);
  u16(w.fit_blocks);
  f32(w.block_limit_floor_m_s2);
  f32(w.block_limit_relative);
  u32(w.min_free_us);
  u16(w.min_block_samples);
  u16(r.fall_search_samples);
  u32(r.steepest_fall_from_us);
  u32(r.fall_chord_us);
  u16(r.step_search_samples);
  u16(r.flight_level_samples);
  const StreamClockSettings<Scalar>& c = s.clock;
  u16(c.interval_mean_samples);
  u16(c.half_span_min_samples);
  u16(c.half_span_max_samples);
  const LeverArmEstimatorSettings<Scalar>& l = s.lever_arm;
  u16(l.half_block_samples);
  f32(l.halves_agree_m);
  f32(l.halves_agree_relative);
  u16(l.given_gives_way_after);
  u16(l.missed_gives_way_after);
  u16(l.solve_every_samples);
  u16(s.feed_lag_samples);
  return crc32(bytes, static_cast<std::size_t>(p - bytes));
}

// The record of one finished flight, with its first seeds (FlightResult::first_seeds);
// its sequence number is set when the ring stores it.
static_assert(kept_first_seeds == flight_record_seeds, "a record holds the seeds the check keeps");
template <typename Scalar>
FlightRecord make_flight_record(const FlightResult<Scalar>& result, std::uint32_t tensor_hash_value,
                                std::uint32_t settings_hash_value) {
  FlightRecord r;
  r.flight_number = result.flight_number;
  r.release_us = result.release_us;
  r.landing_us = result.landing_us;
  r.samples = result.samples;
  r.gaps = result.gaps;
  r.clipped_samples = result.clipped_samples;
  r.landed = result.landed;
  r.turned = result.turned;
  r.imu_position_estimated = result.imu_position_estimated;
  r.comparisons = result.overall.count();
  r.rms_da_rad = static_cast<float>(result.overall.rms_da());
  r.rms_rel_err = static_cast<float>(result.overall.rms_relative_error());
  r.max_da_rad = static_cast<float>(result.overall.max_da());
  r.max_rel_err = static_cast<float>(result.overall.max_relative_error());
  r.seeds_stored =
      result.first_seed_count < flight_record_seeds ? result.first_seed_count : flight_record_seeds;
  for (std::uint32_t i = 0; i < r.seeds_stored; ++i) {
    r.seeds[i].rms_da_rad = static_cast<float>(result.first_seeds[i].rms_da_rad);
    r.seeds[i].rms_rel_err = static_cast<float>(result.first_seeds[i].rms_rel_err);
  }
  r.tensor_hash = tensor_hash_value;
  r.settings_hash = settings_hash_value;
  return r;
}

}  // namespace aloft
