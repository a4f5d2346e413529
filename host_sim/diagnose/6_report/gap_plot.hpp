// The figures of `aloft diagnose --plot DIR`: for each flight, the held-out deviation
// angle and relative error over time before (nominal model) and after the chosen effect,
// and the torque-free invariants (kinetic energy, |L|) of the measured motion with the
// nominal tensor, as SVG and PNG (cairo writes both from one drawing).
#pragma once

#include <string>

#include "diagnose/5_flow/diagnosis.hpp"

namespace aloft::host::diagnose {

// Writes DIR/gap.svg and DIR/gap.png (DIR is created). Each file is written whole or not
// at all; throws aloft::host::Error naming the file on failure.
void write_flight_plots(const FlightDiagnosis& diagnosis, const NominalInertia& nominal,
                        const std::string& dir);

// One pair of files per flight, DIR/flight_<segment>.svg and .png, and the session's
// figure, DIR/session.svg and .png (session_plot.hpp).
void write_session_plots(const SessionDiagnosis& diagnosis, const NominalInertia& nominal,
                         const std::string& dir);

}  // namespace aloft::host::diagnose
