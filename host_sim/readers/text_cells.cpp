#include "readers/text_cells.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>

#include "common/commands.hpp"

namespace aloft::host {

namespace {

// No header is this long: a first line still without its end after this many bytes is
// judged as it stands (and refused), rather than read on to the end of a large file.
constexpr std::size_t kLongestHeader = 1u << 20;

// The first non-blank complete line of `content` and its 1-based number, if any.
bool first_complete_line(const std::string& content, bool at_end, std::string& line, std::size_t& number) {
  std::size_t start = 0;
  number = 1;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string::npos) {
      if (!at_end && content.size() - start < kLongestHeader) return false;
      end = content.size();
    }
    line = content.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!is_blank(line)) return true;
    start = end + 1;
    ++number;
  }
  return false;
}

}  // namespace

TextFile read_text_file(const std::string& path, const FirstLineCheck& check_first_line) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot open file");
  constexpr std::size_t kChunk = 1u << 20;  // 1 MiB
  std::string content;
  std::string chunk(kChunk, '\0');
  bool first_line_checked = !check_first_line;
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (std::char_traits<char>::find(chunk.data(), got, '\0') != nullptr) {
      throw Error(path + ": holds binary data, not text");
    }
    content.append(chunk.data(), got);
    if (content.size() == got) content = without_byte_order_mark(content);
    if (!first_line_checked) {
      std::string line;
      std::size_t number = 0;
      if (first_complete_line(content, !in, line, number)) {
        check_first_line(line, number);
        first_line_checked = true;
      }
    }
  }
  TextFile file;
  file.path = path;
  std::size_t start = 0;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string::npos) end = content.size();
    std::string line = content.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    file.lines.push_back(std::move(line));
    start = end + 1;
  }
  if (std::all_of(file.lines.begin(), file.lines.end(), is_blank)) {
    throw Error(path + ": file is empty");
  }
  return file;
}

std::string at_line(const std::string& path, std::size_t line_number, const std::string& problem) {
  return path + ":" + std::to_string(line_number) + ": " + problem;
}

std::vector<std::string> split_csv_line(const std::string& line, const std::string& path,
                                        std::size_t line_number, std::size_t max_cells, char delimiter) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  bool cell_was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          cell += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        cell += c;
      }
    } else if (c == '"' && trim(cell).empty() && !cell_was_quoted) {
      quoted = true;
      cell_was_quoted = true;
      cell.clear();  // spaces before the opening quote are not content
    } else if (c == delimiter) {
      cells.push_back(cell_was_quoted ? cell : trim(cell));
      cell.clear();
      cell_was_quoted = false;
      if (max_cells > 0 && cells.size() + 1 == max_cells) {
        const std::string rest = trim(line.substr(i + 1));
        // A wholly quoted remainder is one quoted cell; anything else is kept verbatim.
        const std::vector<std::string> unquoted = !rest.empty() && rest.front() == '"'
                                                      ? split_csv_line(rest, path, line_number, 0, delimiter)
                                                      : std::vector<std::string>{};
        cells.push_back(unquoted.size() == 1 ? unquoted[0] : rest);
        return cells;
      }
    } else if (cell_was_quoted) {
      if (c != ' ' && c != '\t') {
        throw Error(at_line(path, line_number, "text after a closing quote in a CSV cell"));
      }
    } else {
      cell += c;
    }
  }
  if (quoted) throw Error(at_line(path, line_number, "unterminated quote"));
  cells.push_back(cell_was_quoted ? cell : trim(cell));
  return cells;
}

char csv_delimiter(const std::string& header_line) {
  bool quoted = false;
  bool semicolon = false, tab = false;
  for (const char c : header_line) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == ',') return ',';
    semicolon = semicolon || c == ';';
    tab = tab || c == '\t';
  }
  return semicolon ? ';' : tab ? '\t' : ',';
}

std::string with_decimal_point(std::string cell) {
  for (char& c : cell) {
    if (c == ',') c = '.';
  }
  return cell;
}

std::string without_byte_order_mark(const std::string& text) {
  return text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text;
}

std::vector<std::string> split_tab_line(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = line.find('\t', start);
    if (tab == std::string::npos) {
      cells.push_back(trim(line.substr(start)));
      return cells;
    }
    cells.push_back(trim(line.substr(start, tab - start)));
    start = tab + 1;
  }
}

std::vector<std::string> split_whitespace(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  std::string cell;
  while (in >> cell) cells.push_back(cell);
  return cells;
}

std::string trim(const std::string& text) {
  const char* space = " \t\r";
  const std::size_t first = text.find_first_not_of(space);
  if (first == std::string::npos) return {};
  const std::size_t last = text.find_last_not_of(space);
  return text.substr(first, last - first + 1);
}

std::string to_lower(const std::string& text) {
  std::string out = text;
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool is_blank(const std::string& line) { return trim(line).empty(); }

bool try_parse_number(const std::string& cell, double& out) {
  const char* first = cell.data();
  const char* last = cell.data() + cell.size();
  // std::from_chars takes no leading '+', which some writers put on exponents' mantissas.
  if (first != last && *first == '+') ++first;
  if (first == last) return false;
  const auto result = std::from_chars(first, last, out);
  return result.ec == std::errc() && result.ptr == last;
}

double parse_number(const std::string& cell, const std::string& path, std::size_t line_number,
                    const std::string& column_name) {
  double value = 0.0;
  if (!try_parse_number(cell, value)) {
    const std::string shown = cell.empty() ? "empty cell" : "'" + cell + "' is not a number";
    throw Error(at_line(path, line_number, "column " + column_name + ": " + shown));
  }
  return value;
}

}  // namespace aloft::host
