#include "diagnose/1_input/contact.hpp"

#include <algorithm>

#include "aloft/free_flight_residual.hpp"
#include "diagnose/1_input/airborne_windows.hpp"
#include "diagnose/1_input/body_kinematics.hpp"

namespace aloft::host::diagnose {
namespace {

// The largest centre force over the samples in [from_s, to_s): a Contact, not yet judged.
Contact strongest_force(const ImuLog& log, const Body& body, const FirmwareFlight& flight, double from_s,
                        double to_s, bool before_release) {
  Contact c;
  c.cut_from_s = from_s;
  c.cut_to_s = to_s;
  c.before_release = before_release;
  for (std::size_t k = 0; k < log.time_s.size(); ++k) {
    if (log.time_s[k] < from_s || log.time_s[k] >= to_s) continue;
    const double force = centre_specific_force(
        body_kinematics_at(log.time_s, log.gyro_rad_s, log.accel_m_s2, body.imu_to_body, k),
        flight.imu_position_m);
    if (force > c.beyond_rotation_m_s2) {
      c.beyond_rotation_m_s2 = force;
      c.at_s = log.time_s[k];
    }
  }
  return c;
}

// The firmware's flight that overlaps `s` most; nullptr when none does.
const FirmwareFlight* overlapping(const std::vector<FirmwareFlight>& flights, const Segment& s) {
  const FirmwareFlight* best = nullptr;
  double most = 0.0;
  for (const FirmwareFlight& f : flights) {
    const double overlap = std::min(f.landing_s, s.end_s) - std::max(f.release_s, s.start_s);
    if (overlap > most) {
      most = overlap;
      best = &f;
    }
  }
  return best;
}

SegmentInFlight cut_one(const ImuLog& log, const Body& body, const FirmwareFlight* flight, const Segment& s) {
  SegmentInFlight out{s, {}};
  if (!flight) return out;
  if (flight->release_s > s.start_s) {
    const Contact c = strongest_force(log, body, *flight, s.start_s, flight->release_s, true);
    if (c.beyond_rotation_m_s2 >= kContactForce_m_s2) {
      out.segment.start_s = flight->release_s;
      out.contacts.push_back(c);
    }
  }
  if (flight->landed && flight->landing_s < s.end_s) {
    // The landing sample itself is the first of the contact: cut from just after it.
    const Contact c = strongest_force(log, body, *flight, flight->landing_s, s.end_s + 1e-9, false);
    if (c.beyond_rotation_m_s2 >= kContactForce_m_s2) {
      out.segment.end_s = flight->landing_s;
      out.contacts.push_back(c);
    }
  }
  return out;
}

}  // namespace

std::vector<SegmentInFlight> cut_contact(const ImuLog& log, const Body& body, const std::string& body_source,
                                         const std::vector<Segment>& segments) {
  const std::vector<FirmwareFlight> flights = firmware_flights(log, body, body_source);
  std::vector<SegmentInFlight> out;
  for (const Segment& s : segments) out.push_back(cut_one(log, body, overlapping(flights, s), s));
  return out;
}

}  // namespace aloft::host::diagnose
