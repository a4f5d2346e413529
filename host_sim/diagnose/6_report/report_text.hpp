// The diagnosis as a few lines for a person (the summary `aloft diagnose` prints): what
// was judged, the baseline gap, the verdict and how far it shrinks the held-out gap, what
// could not be judged. The JSON report beside it: report_json.hpp.
#pragma once

#include <string>

#include "diagnose/5_flow/diagnosis.hpp"

namespace aloft::host::diagnose {

std::string flight_summary(const FlightDiagnosis& diagnosis);
std::string session_summary(const SessionDiagnosis& diagnosis);

}  // namespace aloft::host::diagnose
