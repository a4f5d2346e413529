#include "diagnose/1_input/flight_input.hpp"

#include "readers/body_rates.hpp"
#include "diagnose/1_input/contact.hpp"
#include "diagnose/1_input/rest_periods.hpp"
#include "diagnose/1_input/saturation.hpp"

namespace aloft::host::diagnose {
namespace {

Flight cut_flight(const ImuLog& log, const Body& body, const std::vector<RestPeriod>& rest, double from_s,
                  double to_s, const std::string& name) {
  Flight flight;
  flight.name = name;
  flight.gyro_input = true;
  flight.sensor_to_body = body.imu_to_body;
  // A release from rest: the gyro's filter settles from the spin-up (a lag alone the
  // initial-state fit absorbs; the settling it cannot).
  if (released_from_rest(rest, from_s)) flight.settling_until_s = from_s + kFilterSettling_s;
  for (std::size_t k = 0; k < log.time_s.size(); ++k) {
    if (log.time_s[k] < from_s || log.time_s[k] > to_s) continue;
    flight.time_s.push_back(log.time_s[k]);
    flight.omega.push_back(log.gyro_rad_s[k]);
    if (log.accel_m_s2.size() == log.time_s.size()) flight.accel_m_s2.push_back(log.accel_m_s2[k]);
    if (body.rotor && log.rotor_rad_s.size() == log.time_s.size())
      flight.logged_rotor_h_N_m_s = body.rotor->inertia_kg_m2 * log.rotor_rad_s[k] * body.rotor->axis;
  }
  flight.imu_position_m = body.imu_position_m;
  flight.usable.assign(flight.size(), 1);
  mark_saturated_samples(flight);
  if (const auto noise = rest_noise(rest)) flight.rest_noise = noise->sigma;
  return flight;
}

}  // namespace

Flight flight_from_imu(const ImuLog& log, const Body& body, double from_s, double to_s,
                       const std::string& name) {
  return cut_flight(log, body, find_rest_periods(log), from_s, to_s, name);
}

std::vector<Flight> flights_from_segments(const ImuLog& log, const Body& body,
                                          const std::vector<Segment>& segments) {
  const std::vector<RestPeriod> rest = find_rest_periods(log);
  std::vector<Flight> flights;
  for (const Segment& s : segments) {
    flights.push_back(cut_flight(log, body, rest, s.start_s, s.end_s, s.name));
    flights.back().comment = s.comment;
  }
  return flights;
}

std::vector<Flight> flights_from_given_segments(const ImuLog& log, const Body& body,
                                                const std::string& body_source,
                                                const std::vector<Segment>& segments) {
  const std::vector<RestPeriod> rest = find_rest_periods(log);
  std::vector<Flight> flights;
  for (const SegmentInFlight& s : cut_contact(log, body, body_source, segments)) {
    flights.push_back(cut_flight(log, body, rest, s.segment.start_s, s.segment.end_s, s.segment.name));
    flights.back().comment = s.segment.comment;
    flights.back().contacts = s.contacts;
  }
  return flights;
}

Flight flight_from_poses(const PoseTrial& poses, const std::string& name) {
  const BodyRates rates = body_rates_from_poses(poses);
  Flight flight;
  flight.name = name;
  flight.gyro_input = false;
  flight.rates_from_differences = true;
  flight.time_s = rates.time_s;
  flight.omega = rates.omega_body;
  flight.usable.assign(flight.size(), 1);
  return flight;
}

}  // namespace aloft::host::diagnose
