#include "diagnose/1_input/segment_checks.hpp"

#include <algorithm>
#include <cstdio>

#include "common/commands.hpp"
#include "diagnose/1_input/rest_periods.hpp"
#include "readers/time_stamps.hpp"

namespace aloft::host::diagnose {
namespace {

std::string span(double from_s, double to_s) {
  char text[80];
  std::snprintf(text, sizeof text, "%.6g–%.6g s", from_s, to_s);
  return text;
}

bool inside(double from_s, double to_s, double first_s, double last_s) {
  return from_s >= first_s && to_s <= last_s;
}

// True when every segment, read as milliseconds, lies inside the log.
bool fit_in_ms(const std::vector<Segment>& segments, double first_s, double last_s) {
  return std::all_of(segments.begin(), segments.end(), [&](const Segment& s) {
    return inside(1e-3 * s.start_s, 1e-3 * s.end_s, first_s, last_s);
  });
}

// Fewer samples than this are no flight to judge (the diagnosis asks for more).
constexpr std::size_t kFewestSamples = 10;

std::vector<double> rates_in(const ImuLog& log, const Segment& s) {
  std::vector<double> rates;
  for (std::size_t k = 0; k < log.time_s.size(); ++k) {
    if (log.time_s[k] >= s.start_s && log.time_s[k] <= s.end_s) rates.push_back(log.gyro_rad_s[k].norm());
  }
  return rates;
}

// The median rate (rad/s); a thrown body turns well above kStillRate.
double median(std::vector<double> rates) {
  std::nth_element(rates.begin(), rates.begin() + static_cast<std::ptrdiff_t>(rates.size() / 2), rates.end());
  return rates[rates.size() / 2];
}

// A word on a sample rate no gyro logs at, which times in ms give (500 Hz reads 0.5 Hz).
std::string slow_clock_hint(const ImuLog& log) {
  const double rate = estimated_rate_hz(log.time_s);
  if (!(rate > 0.0) || rate >= 10.0) return "";
  char text[112];
  std::snprintf(text, sizeof text,
                "; the log has %.3g samples per second: are its times in ms? (--time-units ms)", rate);
  return text;
}

}  // namespace

void check_segments(const ImuLog& log, const std::vector<Segment>& segments,
                    const std::string& segments_path) {
  if (log.time_s.empty()) return;
  const double first = log.time_s.front(), last = log.time_s.back();
  for (const Segment& s : segments) {
    const std::string named = segments_path + ": segment " + s.name + " (" + span(s.start_s, s.end_s) + ")";
    if (!inside(s.start_s, s.end_s, first, last)) {
      const std::string hint = fit_in_ms(segments, first, last)
                                   ? "; the segments fit the log as milliseconds: write them in seconds"
                                   : "";
      throw Error(named + " is not inside the log " + log.path + " (" + span(first, last) + ")" + hint);
    }
    const std::vector<double> rates = rates_in(log, s);
    if (rates.size() < kFewestSamples) {
      throw Error(named + " holds " + std::to_string(rates.size()) + " samples of the log" +
                  slow_clock_hint(log));
    }
    const double rate = median(rates);
    if (rate < kStillRate_rad_s) {
      char text[48];
      std::snprintf(text, sizeof text, "%.3g", rate);
      throw Error(named + " is a rest period, not a flight: the gyro reads a median " + text +
                  " rad/s there");
    }
  }
}

}  // namespace aloft::host::diagnose
