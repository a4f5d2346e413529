// The diagnosis as the JSON report of SPEC §4 (required keys exactly as specified, more
// keys beside them). The few lines for a person: report_text.hpp.
#pragma once

#include <nlohmann/json.hpp>

#include "diagnose/5_flow/diagnosis.hpp"

namespace aloft::host::diagnose {

nlohmann::json flight_report(const FlightDiagnosis& diagnosis);
nlohmann::json session_report(const SessionDiagnosis& diagnosis);

// SPEC §4 `params` of a fitted effect (fixed keys per effect).
nlohmann::json params_json(Effect effect, const EffectParameters& params);

}  // namespace aloft::host::diagnose
