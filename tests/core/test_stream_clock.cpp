// The stream clock (aloft/sensor/stream_clock.hpp): dt, gaps, clipping and the w_dot half span
// from time stamps alone.
#include "aloft/sensor/stream_clock.hpp"

#include "test_api.hpp"

namespace {

// The clock holds its settings by reference (a pipeline's parts share one copy).
const aloft::StreamClockSettings<float> default_settings;

using Clock = aloft::StreamClock<float>;

aloft::ImuSample<float> sample_at(std::uint64_t t_us, std::uint8_t flags = 0) {
  aloft::ImuSample<float> s;
  s.t_us = t_us;
  s.flags = flags;
  return s;
}

// n samples period_us apart from t0_us; returns the last stamp.
std::uint64_t run(Clock& clock, std::uint64_t t0_us, std::uint32_t period_us, int n) {
  std::uint64_t t = t0_us;
  for (int i = 0; i < n; ++i, t += period_us) (void)clock.tick(sample_at(t));
  return t - period_us;
}

}  // namespace

ALOFT_TEST_CASE("stream clock: the w_dot half span is about 1 ms in samples, 1 to 4", "[stream_clock]") {
  const std::uint32_t periods_us[] = {10000, 1000, 500, 333, 250, 125};
  const std::uint32_t expected[] = {1, 1, 2, 3, 4, 4};
  for (int i = 0; i < 6; ++i) {
    Clock clock{default_settings};
    (void)run(clock, 1000000, periods_us[i], 100);
    ALOFT_CHECK(clock.half_span() == expected[i]);
  }
}

ALOFT_TEST_CASE("stream clock: stamps more than 3 intervals apart are a gap, counted with its length",
                "[stream_clock]") {
  Clock clock{default_settings};
  std::uint64_t t = run(clock, 1000000, 1000, 50);
  const aloft::StreamTick near = clock.tick(sample_at(t + 2900));  // 2.9 intervals: no gap
  ALOFT_CHECK(!near.gap);
  ALOFT_CHECK(near.dt_us == 2900u);
  t += 2900;
  t = run(clock, t + 1000, 1000, 50);
  const aloft::StreamTick far = clock.tick(sample_at(t + 5000));
  ALOFT_CHECK(far.gap);
  ALOFT_CHECK(far.dt_us == 5000u);
  const aloft::StreamTick flagged = clock.tick(sample_at(t + 6000, aloft::imu_gap_before));
  ALOFT_CHECK(flagged.gap);
  ALOFT_CHECK(clock.counts().gaps == 2u);
  ALOFT_CHECK(clock.counts().lost_us == 6000u);
  ALOFT_CHECK(clock.counts().samples == 103u);
}

ALOFT_TEST_CASE("stream clock: a stamp not after the last is refused and nothing changes", "[stream_clock]") {
  Clock clock{default_settings};
  const std::uint64_t t = run(clock, 1000000, 1000, 10);
  ALOFT_CHECK(clock.tick(sample_at(t)).status == aloft::Status::time_not_increasing);
  ALOFT_CHECK(clock.tick(sample_at(t - 1)).status == aloft::Status::time_not_increasing);
  ALOFT_CHECK(clock.counts().samples == 10u);
  ALOFT_CHECK(clock.last_t_us() == t);
  ALOFT_CHECK(clock.tick(sample_at(t + 1000, aloft::imu_gyro_clipped)).status == aloft::Status::ok);
  ALOFT_CHECK(clock.counts().clipped_samples == 1u);
}

ALOFT_TEST_CASE("stream clock: its settings decide", "[stream_clock]") {
  aloft::StreamClockSettings<float> wide;
  wide.derivative_half_span_us = 2000;  // 2 ms either side: 2 samples at 1 kHz
  wide.gap_interval_factor = 10;        // a 5-interval jump is no gap
  Clock clock{wide};
  const std::uint64_t t = run(clock, 1000000, 1000, 50);
  ALOFT_CHECK(clock.half_span() == 2u);
  ALOFT_CHECK(!clock.tick(sample_at(t + 5000)).gap);
}
