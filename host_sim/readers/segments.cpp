#include "readers/segments.hpp"

#include <cmath>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "readers/text_cells.hpp"

namespace aloft::host {

namespace {

// true = keep, false = skip; throws for anything else.
bool parse_keep(const std::string& cell, const std::string& path, std::size_t line) {
  const std::string v = to_lower(cell);
  if (v.empty() || v == "true" || v == "yes" || v == "1") return true;
  if (v == "false" || v == "no" || v == "0") return false;
  throw Error(at_line(path, line, "keep must be true or false, not '" + cell + "'"));
}

// The header row; throws "FILE:LINE: ..." unless it is segment,start,end[,keep,comment].
std::vector<std::string> segments_header(const std::string& line, const std::string& path,
                                         std::size_t number) {
  const std::vector<std::string> header = split_csv_line(line, path, number);
  const char* expected[] = {"segment", "start", "end", "keep", "comment"};
  const bool header_ok = header.size() >= 3 && header.size() <= 5 && [&] {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (to_lower(header[i]) != expected[i]) return false;
    }
    return true;
  }();
  if (!header_ok) throw Error(at_line(path, number, "header must be segment,start,end[,keep,comment]"));
  return header;
}

}  // namespace

static std::vector<Segment> read_segments_csv_unguarded(const std::string& path) {
  const TextFile file = read_text_file(
      path, [&](const std::string& line, std::size_t number) { segments_header(line, path, number); });
  std::size_t header_index = 0;
  while (is_blank(file.lines[header_index])) ++header_index;
  const std::vector<std::string> header = segments_header(file.lines[header_index], path, header_index + 1);

  std::vector<Segment> kept;
  std::size_t rows = 0;
  for (std::size_t i = header_index + 1; i < file.lines.size(); ++i) {
    if (is_blank(file.lines[i])) continue;
    const std::size_t line = i + 1;
    // The comment column, when there is one, takes the rest of the line, commas included.
    std::vector<std::string> cells = split_csv_line(file.lines[i], path, line, header.size() == 5 ? 5 : 0);
    for (std::string& cell : cells) cell = trim(cell);  // also inside quotes
    ++rows;
    // SPEC §3: a keep=false row is not a flight and is skipped whatever its other cells
    // hold (phyphox users leave its start and end blank), so keep is read first.
    if (cells.size() >= 4 && !parse_keep(cells[3], path, line)) continue;
    if (cells.size() < 3) {
      throw Error(at_line(path, line, "a segment needs a name, a start and an end"));
    }
    if (cells.size() > header.size()) {
      throw Error(at_line(path, line, "more cells than the header names"));
    }
    Segment s;
    s.name = cells[0];
    if (s.name.empty()) throw Error(at_line(path, line, "segment name is empty"));
    s.start_s = parse_number(cells[1], path, line, "start");
    s.end_s = parse_number(cells[2], path, line, "end");
    if (!std::isfinite(s.start_s) || !std::isfinite(s.end_s)) {
      throw Error(at_line(path, line, "start and end must be finite"));
    }
    if (!(s.end_s > s.start_s)) {
      throw Error(at_line(path, line, "segment " + s.name + " ends before it starts"));
    }
    if (cells.size() >= 5) s.comment = cells[4];
    kept.push_back(s);
  }
  if (rows == 0) throw Error(path + ": no segments after the header");
  if (kept.empty()) throw Error(path + ": every segment is marked keep=false");
  return kept;
}

std::vector<Segment> read_segments_csv(const std::string& path) {
  return with_file_context(path, [&] { return read_segments_csv_unguarded(path); });
}

}  // namespace aloft::host
