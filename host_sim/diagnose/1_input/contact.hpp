// Contact inside a given segment (issue 31 item 4). A segment drawn by hand, or by a
// coarse annotation, often holds the last of the throw and the first of the catch. With
// an accelerometer, the firmware's release and landing code (run as `aloft replay --imu`
// runs it: airborne_windows.hpp) says where the flight is, and the specific force at the
// centre of mass, |a - K r|, says how hard the hand or the ground pushed in what it cuts.
// Those samples are cut away and named in the report; a torque-free model fitted over a
// hand's push would take the push for an effect (an `impulse`, a moment error).
#pragma once

#include <string>
#include <vector>

#include "common/body_file.hpp"
#include "common/trial.hpp"
#include "diagnose/1_input/flight.hpp"

namespace aloft::host::diagnose {

// Below this (m/s²) what the firmware's code leaves outside the flight holds no force
// worth naming, and is kept: its own free-flight limit over 5 ms blocks is 0.8 m/s² +
// 2 % of |K r| (release_window.hpp), a single sample of a ringing body reaches 8 m/s²,
// while a hand's push is tens of m/s² and an impact hundreds. A release dated a few ms
// late thus cuts nothing from a segment that starts in the air.
constexpr double kContactForce_m_s2 = 10.0;

struct SegmentInFlight {
  Segment segment;                // the segment with contact cut away
  std::vector<Contact> contacts;  // what was cut, in time order
};

// Each segment of `segments` cut to the firmware's flight that overlaps it most, where
// what lies outside that flight holds a force of at least kContactForce_m_s2. Segments
// without such contact, and every segment of a log without an accelerometer, come back
// as they were.
std::vector<SegmentInFlight> cut_contact(const ImuLog& log, const Body& body, const std::string& body_source,
                                         const std::vector<Segment>& segments);

}  // namespace aloft::host::diagnose
