// The stream clock of the onboard pipeline (aloft/onboard/onboard_pipeline.hpp): what the time
// stamps of an IMU stream say, sample by sample.
//  - dt is always the difference of two stamps; a stamp not after the previous one is
//    refused (nothing changes).
//  - A gap: a sample flagged imu_gap_before, or one whose stamp is more than
//    `gap_interval_factor` running sample intervals after the previous one. Gaps are
//    counted (StreamCounts), never bridged silently.
//  - The running sample interval, a mean over about `interval_mean_samples` intervals
//    (gaps left out), sets the half span h (in samples) of the central difference that
//    gives w_dot (aloft/onboard/sample_history.hpp): about `derivative_half_span_us` either side,
//    from `half_span_min_samples` to `half_span_max_samples` (rounded: 1.5 samples and
//    under give the least).
#pragma once

#include <cstdint>

#include "aloft/sensor/imu_sample.hpp"
#include "aloft/settings.hpp"
#include "aloft/status.hpp"
#include "aloft/sensor/whole_microseconds.hpp"

namespace aloft {

template <typename Scalar>
struct StreamClockSettings {
  Scalar gap_interval_factor = Scalar(3);
  std::uint16_t interval_mean_samples = 16;
  std::uint32_t derivative_half_span_us = 1000;
  std::uint16_t half_span_min_samples = 1;
  std::uint16_t half_span_max_samples = 4;

  // The one list of these settings (aloft/settings.hpp): unit, meaning, and what chose
  // each value.
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.gap_interval_factor, [] {
      return SettingInfo{"clock.gap_interval_factor", "intervals",
                         "stamps this many running sample intervals apart are a gap. Not swept: 3 means "
                         "at least two samples are missing, far beyond a sensor clock's jitter"};
    });
    v(s.interval_mean_samples, [] {
      return SettingInfo{"clock.interval_mean_samples", "samples",
                         "memory of the running sample interval. Not swept: long enough to average "
                         "the stamps' jitter, short enough to follow a change of rate"};
    });
    v(s.derivative_half_span_us, [] {
      return SettingInfo{"clock.derivative_half_span_us", "µs",
                         "w_dot is a central difference of gyro samples about this far either side, as "
                         "the release detector was written: a one-sample difference at 4 kHz is too "
                         "noisy for w_dot x r. Not swept"};
    });
    v(s.half_span_min_samples, [] {
      return SettingInfo{"clock.half_span_min_samples", "samples",
                         "fewest samples either side of that difference: 1 is the least a central "
                         "difference takes (a definition, not a tuning)"};
    });
    v(s.half_span_max_samples, [] {
      return SettingInfo{"clock.half_span_max_samples", "samples",
                         "most samples either side: 4 keeps the span at 1 ms at 4 kHz, the fastest "
                         "rate measured, with 2h + 1 far inside the 32-sample history"};
    });
  }
};

// The whole recording so far.
struct StreamCounts {
  std::uint32_t samples = 0;
  std::uint32_t gaps = 0;                   // samples flagged imu_gap_before (or stamps far apart)
  std::uint64_t lost_us = 0;                // total length of those gaps
  std::uint32_t clipped_samples = 0;        // samples with a clipped axis
  std::uint32_t short_flights_dropped = 0;  // free flight shorter than min_flight_us
};

// What the clock made of one sample.
struct StreamTick {
  Status status = Status::ok;  // not ok: the sample is refused, nothing changed
  bool gap = false;            // a gap before this sample
  std::uint64_t dt_us = 0;     // since the previous sample (0 for the first)
};

template <typename Scalar>
class StreamClock {
 public:
  // The settings are held, not copied (a pipeline's parts share its one copy): they must
  // outlive the clock.
  explicit StreamClock(const StreamClockSettings<Scalar>& settings) : settings_(settings) {}
  explicit StreamClock(StreamClockSettings<Scalar>&&) = delete;

  StreamTick tick(const ImuSample<Scalar>& sample) {
    StreamTick t;
    if (counts_.samples > 0 && sample.t_us <= last_t_us_) {
      t.status = Status::time_not_increasing;
      return t;
    }
    const bool first = counts_.samples == 0;
    t.dt_us = first ? 0 : sample.t_us - last_t_us_;
    t.gap = !first && (sample.gap_before() || far_apart(t.dt_us));
    ++counts_.samples;
    if (t.gap) {
      ++counts_.gaps;
      counts_.lost_us += t.dt_us;
    }
    if (sample.clipped()) ++counts_.clipped_samples;
    if (!t.gap && t.dt_us > 0) track_interval(t.dt_us);
    last_t_us_ = sample.t_us;
    return t;
  }

  std::uint64_t last_t_us() const { return last_t_us_; }
  std::uint32_t half_span() const { return half_span_; }  // h, samples
  const StreamCounts& counts() const { return counts_; }
  StreamCounts& counts() { return counts_; }  // the pipeline adds its dropped flights

 private:
  bool far_apart(std::uint64_t dt_us) const {
    return interval_us_ > Scalar(0) &&
           scalar_of_us<Scalar>(dt_us) > settings_.gap_interval_factor * interval_us_;
  }

  void track_interval(std::uint64_t dt_us) {
    const Scalar dt = scalar_of_us<Scalar>(dt_us);
    const auto memory = static_cast<Scalar>(settings_.interval_mean_samples);
    interval_us_ = interval_us_ > Scalar(0) ? interval_us_ + (dt - interval_us_) / memory : dt;
    const Scalar span = static_cast<Scalar>(settings_.derivative_half_span_us) / interval_us_;
    const auto least = static_cast<Scalar>(settings_.half_span_min_samples);
    const auto most = static_cast<Scalar>(settings_.half_span_max_samples);
    half_span_ = span < least + Scalar(0.5) ? settings_.half_span_min_samples
                 : span > most              ? settings_.half_span_max_samples
                                            : static_cast<std::uint32_t>(span + Scalar(0.5));
  }

  const StreamClockSettings<Scalar>& settings_;
  StreamCounts counts_;
  std::uint64_t last_t_us_ = 0;
  Scalar interval_us_ = Scalar(0);
  std::uint32_t half_span_ = 1;
};

}  // namespace aloft
