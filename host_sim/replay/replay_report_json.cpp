#include "replay/replay_report_json.hpp"

#include "common/shortest_decimal.hpp"
#include "common/tensor_estimate_json.hpp"

#include <cstdlib>
#include <string>

namespace aloft::host {
namespace {

using nlohmann::json;

constexpr double kRadToDeg = 57.29577951308232;

// Why a flight carries no verdict on the tensor, or empty when it does.
std::string why_no_verdict(const FlightResult<float>& f) {
  if (!f.turned) return "the body turned too little to say anything about the tensor (a drop?)";
  if (f.overall.count() == 0) return "no comparison was made (too few airborne samples)";
  return "";
}

json flight_json(const ReplayResult& result, const FlightResult<float>& f) {
  json j;
  j["flight"] = f.flight_number;
  j["release_s"] = recording_time_s(result, f.release_us);
  j["landing_s"] = f.landed ? json(recording_time_s(result, f.landing_us)) : json(nullptr);
  j["samples"] = f.samples;
  j["gaps"] = f.gaps;
  j["clipped_samples"] = f.clipped_samples;
  j["imu_position_m"] = {shortest_decimal(f.imu_position_m.x()), shortest_decimal(f.imu_position_m.y()),
                         shortest_decimal(f.imu_position_m.z())};
  j["imu_position_from"] = f.imu_position_estimated ? "estimated" : "body";
  j["comparisons"] = f.overall.count();
  const std::string note = why_no_verdict(f);
  if (note.empty()) {
    j["rms_da_deg"] = static_cast<double>(f.overall.rms_da()) * kRadToDeg;
    j["max_da_deg"] = static_cast<double>(f.overall.max_da()) * kRadToDeg;
    j["rms_rel_err"] = shortest_decimal(f.overall.rms_relative_error());
  } else {
    j["rms_da_deg"] = nullptr;
    j["max_da_deg"] = nullptr;
    j["rms_rel_err"] = nullptr;
    j["note"] = note;
  }
  j["tensor_estimate"] = tensor_estimate_json(f.tensor);
  return j;
}

json stream_json(const ReplayResult& result) {
  json gaps = json::array();
  for (const StreamGap& g : result.gaps) {
    gaps.push_back(
        {{"at_s", recording_time_s(result, g.at_us)}, {"length_s", static_cast<double>(g.length_us) / 1e6}});
  }
  return {{"samples", result.stream.samples},
          {"invalid_samples", result.invalid_samples},
          {"clipped_samples", result.stream.clipped_samples},
          {"bytes_skipped", result.bytes_skipped},
          {"empty_reads", result.empty_reads},
          {"resyncs", result.resyncs},
          {"gaps", gaps},
          {"lost_s", static_cast<double>(result.stream.lost_us) / 1e6}};
}

}  // namespace

json replay_report_json(const Recording& recording, const ReplayResult& result) {
  json flights = json::array();
  for (const FlightResult<float>& f : result.flights) flights.push_back(flight_json(result, f));
  return {{"recording", {{"path", recording.path}, {"format", recording.format}}},
          {"stream", stream_json(result)},
          {"gyro_filter",
           {{"time_constant_us", result.gyro_filter_us},
            {"from", result.gyro_filter_from_option ? "option" : "firmware"}}},
          {"flights", flights}};
}

}  // namespace aloft::host
