// A sample sink for the driver tests that checks every sample as it comes, without
// storing the stream (no heap on the bare-metal targets): the fake chip made sample k
// from aloft_test::mixed_sample(k) at k periods after its first valid packet, so a
// sample's time stamp names the k it must hold. A wrong gap length therefore shows as
// wrong values, not only as a wrong time.
#pragma once

#include <cstdint>

#include "aloft/sensor/icm42688p_driver.hpp"
#include "fake_icm42688p.hpp"
#include "icm42688p_packet_encoder.hpp"

namespace aloft_test {

// Equal values without -Wfloat-equal's complaint: the decoder promises exact results.
template <typename S>
bool identical(S a, S b) {
  return !(a < b) && !(b < a);
}

template <typename S>
struct StreamCheck {
  struct Gap {
    std::uint64_t at_us = 0;      // time of the first sample after the gap
    std::uint64_t length_us = 0;  // time from the sample before the gap to this one
  };
  static constexpr int kGapLog = 8;

  std::uint32_t first_index = 0;  // k of the first valid packet
  std::uint32_t period_us = 1000;
  std::uint32_t samples = 0;
  std::uint32_t mismatches = 0;
  std::uint32_t clipped = 0;
  std::uint32_t gaps = 0;
  std::uint64_t last_t_us = 0;
  Gap gap_log[kGapLog] = {};

  aloft::icm42688p::SampleSink<S> sink() { return {this, &push}; }

  static void push(void* context, const aloft::ImuSample<S>& s) {
    static_cast<StreamCheck*>(context)->check(s);
  }

  void check(const aloft::ImuSample<S>& s) {
    if (s.t_us % period_us != 0) {
      ++mismatches;
      return;
    }
    const ChipSample want = mixed_sample(first_index + static_cast<std::uint32_t>(s.t_us / period_us));
    bool clip_a = false;
    bool clip_g = false;
    for (int axis = 0; axis < 3; ++axis) {
      const S a = static_cast<S>(want.accel[axis]) * aloft::icm42688p::accel_m_s2_per_lsb<S>();
      const S g = static_cast<S>(want.gyro[axis]) * aloft::icm42688p::gyro_rad_s_per_lsb<S>();
      if (!identical(s.accel_m_s2[axis], a) || !identical(s.gyro_rad_s[axis], g)) ++mismatches;
      clip_a = clip_a || want.accel[axis] == 32767 || want.accel[axis] == -32767;
      clip_g = clip_g || want.gyro[axis] == 32767 || want.gyro[axis] == -32767;
    }
    if (s.clipped()) ++clipped;
    if (((s.flags & aloft::imu_accel_clipped) != 0) != clip_a) ++mismatches;
    if (((s.flags & aloft::imu_gyro_clipped) != 0) != clip_g) ++mismatches;
    const bool jumped = samples > 0 && s.t_us != last_t_us + period_us;
    if (samples > 0 && s.t_us <= last_t_us) ++mismatches;
    if (jumped != s.gap_before()) ++mismatches;
    if (jumped) {
      if (gaps < kGapLog) gap_log[gaps] = {s.t_us, s.t_us - last_t_us};
      ++gaps;
    }
    last_t_us = s.t_us;
    ++samples;
  }
};

// Advances the chip's clock by `interval_us` before each of `polls` polls; returns the
// number of polls that did not return ok.
template <typename S>
std::uint32_t run_polls(aloft::icm42688p::Icm42688pDriver<S>& driver, FakeIcm42688p& chip,
                        StreamCheck<S>& check, std::uint32_t polls, std::uint32_t interval_us) {
  std::uint32_t not_ok = 0;
  for (std::uint32_t i = 0; i < polls; ++i) {
    chip.advance_us(interval_us);
    if (driver.poll(check.sink()) != aloft::Status::ok) ++not_ok;
  }
  return not_ok;
}

}  // namespace aloft_test
