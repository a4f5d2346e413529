// `aloft records DUMP [--json | --csv]` (SPEC §5): the flights stored in a raw dump of
// the flight-record area, one row per flight, by sequence number. The table is for
// people; --json and --csv give the same rows for programs. Bad slots (torn, corrupt)
// are named on stderr, one line each with the offset and reason, and in the JSON's
// `problems`; they do not fail the command. Times are seconds on the firmware's clock,
// angles degrees; a flight that did not land has no landing time, and one that turned too
// little to judge the tensor has no deviation statistics (null, empty cell or "-").
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/json_text.hpp"
#include "common/tensor_estimate_json.hpp"
#include "common/commands.hpp"
#include "records/record_dump.hpp"
#include "records/records_command.hpp"

namespace aloft::host {
namespace {

constexpr double degrees_per_radian = 57.29577951308232;

std::string hex32(std::uint32_t v) {
  char text[12];
  std::snprintf(text, sizeof(text), "0x%08x", v);
  return text;
}

std::string fixed(double v, int decimals) {
  char text[48];
  std::snprintf(text, sizeof(text), "%.*f", decimals, v);
  return text;
}

double seconds(std::uint64_t us) { return static_cast<double>(us) * 1e-6; }

// The tensor estimate's ratio i (or its 95 % half-width); empty before version 3 and where
// the flight did not determine it.
std::string tensor_cell(const ListedRecord& r, int i, bool half_width) {
  const FlightRecordTensor& t = r.record.tensor;
  if (r.record.version < 3 || !t.determined) return "";
  const TensorEstimate<float> e = tensor_estimate_of(t);
  if (!half_width) return fixed(e.ratio(i), 5);
  char text[32];
  std::snprintf(text, sizeof(text), "%.2g", static_cast<double>(e.ratios_95[i]));
  return text;
}

// Absolute moment i, kg·m²: only where a rotor gave the scale.
std::string moment_cell(const ListedRecord& r, int i) {
  const FlightRecordTensor& t = r.record.tensor;
  if (r.record.version < 3 || !t.determined || !t.absolute) return "";
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", static_cast<double>(t.principal[i]));
  return text;
}

// One row: the columns every format shares, as text ("" for a missing value).
struct Column {
  const char* name;
  std::string (*cell)(const ListedRecord&);
};

const std::vector<Column>& columns() {
  static const std::vector<Column> c = {
      {"sequence", [](const ListedRecord& r) { return std::to_string(r.record.sequence); }},
      {"flight", [](const ListedRecord& r) { return std::to_string(r.record.flight_number); }},
      {"release_s", [](const ListedRecord& r) { return fixed(seconds(r.record.release_us), 6); }},
      {"landing_s",
       [](const ListedRecord& r) { return r.record.landed ? fixed(seconds(r.record.landing_us), 6) : ""; }},
      {"samples", [](const ListedRecord& r) { return std::to_string(r.record.samples); }},
      {"gaps", [](const ListedRecord& r) { return std::to_string(r.record.gaps); }},
      {"clipped", [](const ListedRecord& r) { return std::to_string(r.record.clipped_samples); }},
      {"rms_da_deg",
       [](const ListedRecord& r) {
         return r.record.turned ? fixed(r.record.rms_da_rad * degrees_per_radian, 4) : "";
       }},
      {"rms_rel_err",
       [](const ListedRecord& r) { return r.record.turned ? fixed(r.record.rms_rel_err, 5) : ""; }},
      {"i1_i3", [](const ListedRecord& r) { return tensor_cell(r, 0, false); }},
      {"i1_i3_95", [](const ListedRecord& r) { return tensor_cell(r, 0, true); }},
      {"i2_i3", [](const ListedRecord& r) { return tensor_cell(r, 1, false); }},
      {"i2_i3_95", [](const ListedRecord& r) { return tensor_cell(r, 1, true); }},
      {"i1_kg_m2", [](const ListedRecord& r) { return moment_cell(r, 0); }},
      {"i2_kg_m2", [](const ListedRecord& r) { return moment_cell(r, 1); }},
      {"i3_kg_m2", [](const ListedRecord& r) { return moment_cell(r, 2); }},
      {"tensor_hash", [](const ListedRecord& r) { return hex32(r.record.tensor_hash); }},
      {"settings_hash", [](const ListedRecord& r) { return hex32(r.record.settings_hash); }},
      {"offset", [](const ListedRecord& r) { return std::to_string(r.offset); }},
  };
  return c;
}

void print_table(const RecordDump& dump) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> widths;
  for (const Column& c : columns()) widths.push_back(std::string(c.name).size());
  for (const ListedRecord& r : dump.records) {
    rows.emplace_back();
    for (std::size_t i = 0; i < columns().size(); ++i) {
      std::string cell = columns()[i].cell(r);
      if (cell.empty()) cell = "-";
      widths[i] = std::max(widths[i], cell.size());
      rows.back().push_back(cell);
    }
  }
  const auto print_row = [&](const auto& cell_of) {
    std::string line;
    for (std::size_t i = 0; i < columns().size(); ++i) {
      const std::string cell = cell_of(i);
      line += (i ? "  " : "") + std::string(widths[i] - cell.size(), ' ') + cell;
    }
    std::cout << line << '\n';
  };
  print_row([](std::size_t i) { return std::string(columns()[i].name); });
  for (const auto& row : rows) print_row([&](std::size_t i) { return row[i]; });
  std::cout << dump.records.size() << " flights\n";
}

void print_csv(const RecordDump& dump) {
  for (std::size_t i = 0; i < columns().size(); ++i) std::cout << (i ? "," : "") << columns()[i].name;
  std::cout << '\n';
  for (const ListedRecord& r : dump.records) {
    for (std::size_t i = 0; i < columns().size(); ++i) std::cout << (i ? "," : "") << columns()[i].cell(r);
    std::cout << '\n';
  }
}

nlohmann::json number_or_null(bool present, double value) {
  return present && std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json flight_json(const ListedRecord& listed) {
  const FlightRecord& r = listed.record;
  nlohmann::json seeds = nlohmann::json::array();
  for (std::uint32_t i = 0; i < r.seeds_stored; ++i)
    seeds.push_back({{"rms_da_deg", number_or_null(r.turned, r.seeds[i].rms_da_rad * degrees_per_radian)},
                     {"rms_rel_err", number_or_null(r.turned, r.seeds[i].rms_rel_err)}});
  return {{"sequence", r.sequence},
          {"record_version", r.version},
          {"flight", r.flight_number},
          {"offset", listed.offset},
          {"release_s", seconds(r.release_us)},
          {"landing_s", number_or_null(r.landed, seconds(r.landing_us))},
          {"landed", r.landed},
          {"turned", r.turned},
          {"imu_position_from", r.imu_position_estimated ? "estimated" : "body"},
          {"samples", r.samples},
          {"gaps", r.gaps},
          {"clipped_samples", r.clipped_samples},
          {"comparisons", r.comparisons},
          {"rms_da_deg", number_or_null(r.turned, r.rms_da_rad * degrees_per_radian)},
          {"rms_rel_err", number_or_null(r.turned, r.rms_rel_err)},
          {"max_da_deg", number_or_null(r.turned, r.max_da_rad * degrees_per_radian)},
          {"max_rel_err", number_or_null(r.turned, r.max_rel_err)},
          {"first_seeds", seeds},
          {"tensor_estimate",
           r.version >= 3 ? tensor_estimate_json(tensor_estimate_of(r.tensor)) : nlohmann::json(nullptr)},
          {"tensor_hash", hex32(r.tensor_hash)},
          {"settings_hash", hex32(r.settings_hash)}};
}

}  // namespace

nlohmann::json records_json(const std::string& path, const RecordDump& dump) {
  nlohmann::json flights = nlohmann::json::array(), problems = nlohmann::json::array();
  for (const ListedRecord& r : dump.records) flights.push_back(flight_json(r));
  for (const DumpProblem& p : dump.problems) problems.push_back({{"offset", p.offset}, {"reason", p.reason}});
  return {{"file", path}, {"slots", dump.slots}, {"flights", flights}, {"problems", problems}};
}

namespace {

void print_json(const std::string& path, const RecordDump& dump) {
  std::cout << json_text(records_json(path, dump)) << '\n';
}

struct RecordsOptions {
  std::string dump_path;
  bool json = false;
  bool csv = false;
};

void run_records(const RecordsOptions& o) {
  const RecordDump dump = read_record_dump(o.dump_path);
  for (const DumpProblem& p : dump.problems)
    std::fprintf(stderr, "%s: offset %llu: %s\n", o.dump_path.c_str(),
                 static_cast<unsigned long long>(p.offset), p.reason.c_str());
  if (o.json)
    print_json(o.dump_path, dump);
  else if (o.csv)
    print_csv(dump);
  else
    print_table(dump);
  std::cout.flush();
}

}  // namespace

void add_records_command(CLI::App& app) {
  auto options = std::make_shared<RecordsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "records", "list the flights in a dump of the firmware's flight-record area (docs/flight-records.md)");
  cmd->add_option("DUMP", options->dump_path, "raw dump of the record area")->required();
  auto* json = cmd->add_flag("--json", options->json, "JSON: flights and problems");
  auto* csv = cmd->add_flag("--csv", options->csv, "CSV: one row per flight");
  json->excludes(csv);
  cmd->callback([options] { run_records(*options); });
}

}  // namespace aloft::host
