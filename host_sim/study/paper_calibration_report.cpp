#include "study/paper_calibration_report.hpp"

#include <cstdio>
#include <sstream>

#include "study/paper_cylinder.hpp"

namespace aloft::host {

using nlohmann::json;

namespace {

// The paper's row of the same name, or null.
const paper::PublishedRow* paper_row(const std::string& name) {
  if (name == "GF") return &paper::kGeometricFormulae;
  if (name == "CP") return &paper::kCompoundPendulum;
  if (name.rfind("moments", 0) == 0) return &paper::kMoments10;
  if (name.rfind("axes", 0) == 0) return &paper::kAxes10;
  if (name.rfind("both", 0) == 0) return &paper::kBoth10;
  return nullptr;
}

json throw_json(const ThrowParameters& p) {
  return {{"spin_rate_rev_s", p.spin_rate_rev_s},
          {"spin_tilt_deg", p.spin_tilt_deg},
          {"spin_azimuth_deg", p.spin_azimuth_deg},
          {"marker_noise_mm", p.marker_noise_mm}};
}

}  // namespace

json calibration_json(const CalibrationResult& result, const CalibrationSettings& s) {
  json out;
  out["what"] =
      "throw searched to match the paper's GF and CP rows only (p10, median, p90), per frame; "
      "the Monte Carlo rows at that throw are predictions of the paper's";
  out["fixed"] = {{"flight_time_s", s.base.flight_time_s},
                  {"marker_layout", marker_layout_name(s.base.marker_layout)},
                  {"axes_sampler", axes_sampler_name(s.sampler)},
                  {"mc_samples", s.mc_samples},
                  {"seed", s.seed}};
  out["grid_points"] = result.grid_points;
  json frames = json::array();
  for (const FrameCalibration& f : result.frames) {
    json entry;
    entry["frame"] = frame_name(f.frame);
    entry["throw"] = throw_json(f.throw_found);
    entry["gf_cp_rms_difference_deg"] = f.search_rms_diff_deg;
    entry["evaluations"] = f.evaluations;
    json rows = json::array();
    for (const PredictedRow& r : f.rows) {
      json row = {
          {"analysis", r.name},
          {"role", r.used_in_search ? "fitted" : "predicted"},
          {"rms_da_deg", {{"p10", r.summary.p10}, {"median", r.summary.median}, {"p90", r.summary.p90}}}};
      if (const paper::PublishedRow* p = paper_row(r.name)) {
        row["paper_rms_da_deg"] = {{"p10", p->p10}, {"median", p->median}, {"p90", p->p90}};
      }
      rows.push_back(row);
    }
    entry["rows"] = rows;
    frames.push_back(entry);
  }
  out["frames"] = frames;
  out["wall_time_s"] = result.wall_time_s;
  return out;
}

std::string calibration_table(const CalibrationResult& result) {
  std::ostringstream out;
  char line[240];
  for (const FrameCalibration& f : result.frames) {
    const ThrowParameters& p = f.throw_found;
    std::snprintf(line, sizeof line,
                  "%s axes: throw %.2f rev/s, axis %.1f deg from z, %.1f deg from x, marker noise "
                  "%.3f mm (GF/CP RMS difference %.2f deg, %zu evaluations)\n",
                  frame_name(f.frame), p.spin_rate_rev_s, p.spin_tilt_deg, p.spin_azimuth_deg,
                  p.marker_noise_mm, f.search_rms_diff_deg, f.evaluations);
    out << line;
    std::snprintf(line, sizeof line, "  %-20s %-9s %6s %6s %6s | paper %5s %5s %5s | diff %5s %5s %5s\n",
                  "RMS DA (deg)", "", "p10", "median", "p90", "p10", "med", "p90", "p10", "med", "p90");
    out << line;
    for (const PredictedRow& r : f.rows) {
      const paper::PublishedRow* pr = paper_row(r.name);
      const DistributionSummary& s = r.summary;
      std::snprintf(line, sizeof line,
                    "  %-20s %-9s %6.2f %6.2f %6.2f | paper %5.1f %5.1f %5.1f | diff %+5.1f %+5.1f %+5.1f\n",
                    r.name.c_str(), r.used_in_search ? "fitted" : "predicted", s.p10, s.median, s.p90,
                    pr->p10, pr->median, pr->p90, s.p10 - pr->p10, s.median - pr->median, s.p90 - pr->p90);
      out << line;
    }
  }
  return out.str();
}

}  // namespace aloft::host
