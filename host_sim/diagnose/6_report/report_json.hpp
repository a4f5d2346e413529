// The diagnosis as the JSON report of SPEC §4 (required keys exactly as specified, more
// keys beside them), and as a few lines for a person.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "diagnose/5_flow/diagnosis.hpp"

namespace aloft::host::diagnose {

nlohmann::json flight_report(const FlightDiagnosis& diagnosis);
nlohmann::json session_report(const SessionDiagnosis& diagnosis);

// SPEC §4 `params` of a fitted effect (fixed keys per effect).
nlohmann::json params_json(Effect effect, const EffectParameters& params);

// A few readable lines: what was judged, the baseline gap, the verdict and how far it
// shrinks the held-out gap, what could not be judged.
std::string flight_summary(const FlightDiagnosis& diagnosis);
std::string session_summary(const SessionDiagnosis& diagnosis);

}  // namespace aloft::host::diagnose
