// One table across many `aloft diagnose` reports (issue 26): a lab runs its sessions as
// independent jobs (GNU parallel, a Slurm array; docs/diagnose.md), then summarises the
// reports they wrote. One row per report (a session's pooled analysis, or a single
// flight's), and with per_flight one more row per flight of a session report.
//
// Columns (CSV header, and the keys of each --json object):
//   report                   the report file, as given
//   scope                    session (a report with "flights"), flight (a one-flight
//                            report), or session_flight (a flight inside a session report)
//   segment                  the flight's segment name (session_flight rows), else empty
//   verdict                  verdict.effect
//   effects                  verdict.effects' effects, most important first, joined by '+'
//   confident                verdict.confident
//   shrink                   1 - heldout_rms_rel_err_after / heldout_rms_rel_err_before of
//                            the verdict: how much of the held-out gap the final model closes
//   consistent_with_nominal  tensor.consistent_with_nominal
//   ratio_21, ratio_21_lo, ratio_21_hi   tensor.ratio_best[0] and its 95 % interval
//   ratio_31, ratio_31_lo, ratio_31_hi   tensor.ratio_best[1] and its 95 % interval
// A value the report does not hold is an empty cell (null in JSON).
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace aloft::host {

// The rows of one parsed report; throws aloft::host::Error naming `path` when `report`
// is not a diagnose report (no verdict object).
std::vector<nlohmann::json> report_rows(const std::string& path, const nlohmann::json& report,
                                        bool per_flight);

// The rows as CSV (header first), or as a JSON array.
std::string rows_csv(const std::vector<nlohmann::json>& rows);
std::string rows_json(const std::vector<nlohmann::json>& rows);

}  // namespace aloft::host
