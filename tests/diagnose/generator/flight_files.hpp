// Writing a generated flight to disk in the formats of SPEC §3, laid out like
// ../shared/data/practice/caseNN/: body.json, imu.csv (plain layout, t,gx,gy,gz
// [,ax,ay,az], 6 decimals) or markers.trc (OpenSim/Vicon TRC, tab separated, mm, 4
// decimals, occluded markers as empty cells), and truth.json (truth_to_json plus the
// seed and the spec). Every file is written through write_file_atomically.
#pragma once

#include <iosfwd>
#include <string>

#include "flight_generator.hpp"

namespace aloft::generator {

void write_imu_csv(std::ostream& out, const host::ImuLog& log);
void write_trc(std::ostream& out, const host::MarkerTrial& trial, const std::string& file_name);

// A segments file (SPEC §3) of a generated log: its header, and a kept flight's row (6 decimals).
constexpr const char* kSegmentsHeader = "segment,start,end,keep,comment\n";
std::string segment_row(const host::Segment& segment);

// Creates `dir` if needed and writes the flight's files into it. Returns the name of
// the data file ("imu.csv" or "markers.trc"). Throws aloft::host::Error on failure.
std::string write_flight(const GeneratedFlight& flight, const std::string& dir);

}  // namespace aloft::generator
