// The diagnosis as the JSON report of SPEC §4 (required keys exactly as specified, more
// keys beside them). The few lines for a person: report_text.hpp.
#pragma once

#include <nlohmann/json.hpp>

#include "diagnose/5_flow/diagnosis.hpp"

namespace aloft::host::diagnose {

nlohmann::json flight_report(const FlightDiagnosis& diagnosis);
nlohmann::json session_report(const SessionDiagnosis& diagnosis);

}  // namespace aloft::host::diagnose
