#include "replay/replay_report_text.hpp"

#include "common/printf_text.hpp"
#include "common/tensor_estimate_json.hpp"

namespace aloft::host {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

std::string flight_row(const ReplayResult& result, const FlightResult<float>& f) {
  const std::string landing =
      f.landed ? printf_text("%10.6f", recording_time_s(result, f.landing_us)) : std::string("         -");
  const Vec3<float>& r = f.imu_position_m;
  const std::string position = printf_text("%6.1f %6.1f %6.1f %s", double(r.x()) * 1e3, double(r.y()) * 1e3,
                                           double(r.z()) * 1e3, f.imu_position_estimated ? "est " : "body");
  const std::string verdict = f.turned && f.overall.count() > 0
                                  ? printf_text("%10.4f %11.6f", double(f.overall.rms_da()) * kRadToDeg,
                                                double(f.overall.rms_relative_error()))
                                  : std::string(f.turned ? "         -           -  (no comparison)"
                                                         : "         -           -  (did not turn)");
  return printf_text("%6u %10.6f %s %7u %4u  %s %s\n", f.flight_number,
                     recording_time_s(result, f.release_us), landing.c_str(), f.samples, f.gaps,
                     position.c_str(), verdict.c_str());
}

}  // namespace

std::string replay_report_text(const Recording& recording, const ReplayResult& result) {
  std::string text = printf_text(
      "%s: %u samples, %u gaps (%.6f s lost), %u clipped, %u invalid, %u empty reads, %llu bytes "
      "skipped\n",
      recording.path.c_str(), result.stream.samples, result.stream.gaps, double(result.stream.lost_us) / 1e6,
      result.stream.clipped_samples, result.invalid_samples, result.empty_reads,
      static_cast<unsigned long long>(result.bytes_skipped));
  text +=
      printf_text("gyro filter: first-order, %u µs (%s)\n", unsigned{result.gyro_filter_us},
                  result.gyro_filter_from_option ? "--gyro-filter-us"
                                                 : "aloft's firmware's; --gyro-filter-us states the log's");
  if (result.flights.empty()) return text + "no flight found\n";
  text += "flight  release_s  landing_s samples gaps  imu_position_mm         rms_da_deg rms_rel_err\n";
  for (const FlightResult<float>& f : result.flights) text += flight_row(result, f);
  text += "tensor estimate, from each flight's own samples (95 % intervals):\n";
  for (const FlightResult<float>& f : result.flights)
    text += printf_text("%6u  %s\n", f.flight_number, tensor_estimate_text(f.tensor).c_str());
  return text;
}

}  // namespace aloft::host
