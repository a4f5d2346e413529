#include "diagnose/1_input/contact.hpp"

#include <algorithm>

#include "aloft/dynamics/free_flight_residual.hpp"
#include "diagnose/1_input/airborne_windows.hpp"
#include "diagnose/1_input/body_kinematics.hpp"

namespace aloft::host::diagnose {
namespace {

// The largest centre force over samples first..last-1: a Contact, not yet judged.
Contact strongest_force(const ImuLog& log, const Eigen::Matrix3d& sensor_to_body, const Eigen::Vector3d& r,
                        std::size_t first, std::size_t last) {
  Contact c;
  for (std::size_t k = first; k < last; ++k) {
    const double force = centre_specific_force(
        body_kinematics_at(log.time_s, log.gyro_rad_s, log.accel_m_s2, sensor_to_body, k), r);
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

// Index of the first sample at or after t (before: false), or after t (true).
std::size_t sample_at(const ImuLog& log, double t, bool after) {
  const auto at = after ? std::upper_bound(log.time_s.begin(), log.time_s.end(), t)
                        : std::lower_bound(log.time_s.begin(), log.time_s.end(), t);
  return static_cast<std::size_t>(at - log.time_s.begin());
}

SegmentInFlight cut_one(const ImuLog& log, const Eigen::Matrix3d& sensor_to_body,
                        const FirmwareFlight* flight, const Segment& s) {
  SegmentInFlight out{s, {}};
  if (!flight) return out;
  const Eigen::Vector3d& r = flight->imu_position_m;
  if (flight->release_s > s.start_s) {
    Contact c = strongest_force(log, sensor_to_body, r, sample_at(log, s.start_s, false),
                                sample_at(log, flight->release_s, false));
    if (c.beyond_rotation_m_s2 >= kContactForce_m_s2) {
      c.cut_from_s = s.start_s;
      c.cut_to_s = flight->release_s;
      out.segment.start_s = flight->release_s;
      out.contacts.push_back(c);
    }
  }
  if (flight->landed && flight->landing_s < s.end_s) {
    // From the landing sample, the first of the contact, to the segment's last.
    Contact c = strongest_force(log, sensor_to_body, r, sample_at(log, flight->landing_s, false),
                                sample_at(log, s.end_s, true));
    if (c.beyond_rotation_m_s2 >= kContactForce_m_s2) {
      c.before_release = false;
      c.cut_from_s = flight->landing_s;
      c.cut_to_s = s.end_s;
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
  const Eigen::Matrix3d sensor_to_body = body.imu_to_body.normalized().toRotationMatrix();
  for (const Segment& s : segments) out.push_back(cut_one(log, sensor_to_body, overlapping(flights, s), s));
  return out;
}

}  // namespace aloft::host::diagnose
