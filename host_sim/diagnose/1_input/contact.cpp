#include "diagnose/1_input/contact.hpp"

#include <algorithm>

#include "aloft/free_flight_residual.hpp"
#include "diagnose/1_input/airborne_windows.hpp"

namespace aloft::host::diagnose {
namespace {

// w_dot from the gyro about this far either side, as the firmware takes it
// (StreamClockSettings::derivative_half_span_us is 1 ms); 2 ms here keeps a 4 kHz gyro's
// differenced noise below 1 m/s² of |K r| for r up to 5 cm.
constexpr double kDerivativeHalfSpan_s = 0.002;

// |a - K r| at sample k, in body axes.
double centre_force(const ImuLog& log, const Eigen::Matrix3d& to_body, const Eigen::Vector3d& r, std::size_t k) {
  const std::size_t n = log.time_s.size();
  std::size_t lo = k, hi = k;
  while (lo > 0 && log.time_s[k] - log.time_s[lo] < kDerivativeHalfSpan_s) --lo;
  while (hi + 1 < n && log.time_s[hi] - log.time_s[k] < kDerivativeHalfSpan_s) ++hi;
  BodyKinematics<double> kin;
  kin.w = to_body * log.gyro_rad_s[k];
  if (hi > lo) kin.w_dot = to_body * (log.gyro_rad_s[hi] - log.gyro_rad_s[lo]) / (log.time_s[hi] - log.time_s[lo]);
  kin.a = to_body * log.accel_m_s2[k];
  return centre_specific_force(kin, r);
}

// The largest centre force over the samples in [from_s, to_s): a Contact, not yet judged.
Contact strongest_force(const ImuLog& log, const Body& body, const FirmwareFlight& flight, double from_s,
                        double to_s, bool before_release) {
  const Eigen::Matrix3d to_body = body.imu_to_body.normalized().toRotationMatrix();
  Contact c;
  c.cut_from_s = from_s;
  c.cut_to_s = to_s;
  c.before_release = before_release;
  for (std::size_t k = 0; k < log.time_s.size(); ++k) {
    if (log.time_s[k] < from_s || log.time_s[k] >= to_s) continue;
    const double force = centre_force(log, to_body, flight.imu_position_m, k);
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
