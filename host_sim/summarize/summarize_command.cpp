// `aloft summarize REPORT.json...`: one table of many diagnose reports
// (summarize/report_summary.hpp). Every report is read before anything is written: a bad
// one is one line naming the file, exit 2, and no output.
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "common/option_checks.hpp"
#include "summarize/report_summary.hpp"
#include "summarize/summarize_command.hpp"

namespace aloft::host {
namespace {

struct SummarizeOptions {
  std::vector<std::string> reports;
  bool json = false;
  bool per_flight = false;
  std::string out;  // empty: stdout
};

nlohmann::json read_report(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  const nlohmann::json report = nlohmann::json::parse(text.str(), nullptr, false);
  if (report.is_discarded()) throw Error(path + ": not JSON");
  return report;
}

void summarize(const SummarizeOptions& o) {
  std::vector<nlohmann::json> rows;
  for (const std::string& path : o.reports) {
    with_file_context(path, [&] {
      for (nlohmann::json& row : report_rows(path, read_report(path), o.per_flight))
        rows.push_back(std::move(row));
    });
  }
  const std::string table = o.json ? rows_json(rows) : rows_csv(rows);
  if (o.out.empty()) {
    std::fputs(table.c_str(), stdout);
  } else {
    write_file_atomically(o.out, [&](std::ostream& out) { out << table; });
  }
}

}  // namespace

void add_summarize_command(CLI::App& app) {
  auto options = std::make_shared<SummarizeOptions>();
  auto* cmd = app.add_subcommand("summarize",
                                 "one row per diagnose report (JSON): verdict, effects, confidence, shrink, "
                                 "tensor consistency and ratio intervals; CSV, or --json");
  cmd->add_option("reports", options->reports, "reports written by aloft diagnose --json")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_flag("--json", options->json, "a JSON array of rows instead of CSV");
  cmd->add_flag("--flights", options->per_flight, "also one row per flight of each session report");
  cmd->add_option("--out", options->out, "write the table to this file (default: stdout)")
      ->check(output_file());
  cmd->callback([options] { summarize(*options); });
}

}  // namespace aloft::host
