#include "summarize/report_summary.hpp"

#include <sstream>

#include "common/json_text.hpp"
#include "common/commands.hpp"

namespace aloft::host {

using nlohmann::json;

namespace {

const std::vector<std::string> kColumns = {
    "report",      "scope",       "segment",     "verdict",
    "effects",     "confident",   "shrink",      "consistent_with_nominal",
    "ratio_21",    "ratio_21_lo", "ratio_21_hi", "ratio_31",
    "ratio_31_lo", "ratio_31_hi"};

// report[a][b]... or null when any step is missing.
json at(const json& j, std::initializer_list<json::json_pointer::string_t> keys) {
  const json* node = &j;
  for (const auto& key : keys) {
    if (!node->is_object() || !node->contains(key)) return nullptr;
    node = &(*node)[key];
  }
  return *node;
}

json element(const json& j, std::size_t i) { return j.is_array() && i < j.size() ? j[i] : json(nullptr); }

json shrink_of(const json& verdict) {
  const json before = at(verdict, {"heldout_rms_rel_err_before"});
  const json after = at(verdict, {"heldout_rms_rel_err_after"});
  if (!before.is_number() || !after.is_number() || before.get<double>() <= 0.0) return nullptr;
  return 1.0 - after.get<double>() / before.get<double>();
}

json row_of(const std::string& path, const std::string& scope, const json& report) {
  const json& verdict = report.at("verdict");
  std::string effects;
  for (const json& e : at(verdict, {"effects"}).is_array() ? verdict["effects"] : json::array()) {
    if (!e.contains("effect") || !e["effect"].is_string()) continue;
    effects += (effects.empty() ? "" : "+") + e["effect"].get<std::string>();
  }
  const json ratio = at(report, {"tensor", "ratio_best"});
  const json ratio_95 = at(report, {"tensor", "ratio_95"});
  return {{"report", path},
          {"scope", scope},
          {"segment", at(report, {"segment"})},
          {"verdict", at(verdict, {"effect"})},
          {"effects", effects},
          {"confident", at(verdict, {"confident"})},
          {"shrink", shrink_of(verdict)},
          {"consistent_with_nominal", at(report, {"tensor", "consistent_with_nominal"})},
          {"ratio_21", element(ratio, 0)},
          {"ratio_21_lo", element(element(ratio_95, 0), 0)},
          {"ratio_21_hi", element(element(ratio_95, 0), 1)},
          {"ratio_31", element(ratio, 1)},
          {"ratio_31_lo", element(element(ratio_95, 1), 0)},
          {"ratio_31_hi", element(element(ratio_95, 1), 1)}};
}

bool is_report(const json& j) { return j.is_object() && j.contains("verdict") && j["verdict"].is_object(); }

// A CSV cell: numbers with 9 significant digits, text quoted when it holds , " or a newline.
std::string cell(const json& value) {
  if (value.is_null()) return "";
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  std::ostringstream out;
  if (value.is_number()) {
    out.precision(9);
    out << value.get<double>();
    return out.str();
  }
  const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  out << '"';
  for (char c : text) out << (c == '"' ? "\"\"" : std::string(1, c));
  out << '"';
  return out.str();
}

}  // namespace

std::vector<json> report_rows(const std::string& path, const json& report, bool per_flight) {
  if (!is_report(report)) throw Error(path + ": not an aloft diagnose report (no \"verdict\" object)");
  const json& flights = at(report, {"flights"});
  std::vector<json> rows = {row_of(path, flights.is_array() ? "session" : "flight", report)};
  if (per_flight && flights.is_array()) {
    for (std::size_t i = 0; i < flights.size(); ++i) {
      if (!is_report(flights[i])) {
        throw Error(path + ": flights[" + std::to_string(i) +
                    "] is not a flight report (no \"verdict\" object)");
      }
      rows.push_back(row_of(path, "session_flight", flights[i]));
    }
  }
  return rows;
}

std::string rows_csv(const std::vector<json>& rows) {
  std::ostringstream out;
  for (std::size_t c = 0; c < kColumns.size(); ++c) out << (c ? "," : "") << kColumns[c];
  out << '\n';
  for (const json& row : rows) {
    for (std::size_t c = 0; c < kColumns.size(); ++c) out << (c ? "," : "") << cell(row[kColumns[c]]);
    out << '\n';
  }
  return out.str();
}

std::string rows_json(const std::vector<json>& rows) { return json_text(json(rows)) + "\n"; }

}  // namespace aloft::host
