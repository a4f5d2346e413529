// Line-oriented text input shared by the text readers (IMU CSV, segments, TRC, .mot/.sto,
// pose CSV): whole-file reading, splitting a line into cells, strict number parsing, and
// the one-line error format "FILE:LINE: problem" used by every reader.
//
// Written by hand rather than with a packaged CSV library: Debian's parsers (libcsv,
// fast-cpp-csv-parser) cover comma-separated rows of a fixed column count, while these
// formats need multi-line headers (TRC, .mot), tab- and whitespace-separated rows, a
// variable number of columns recognised by name, and errors that name the file line.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace aloft::host {

// A text file split into lines (without their '\n' or "\r\n"). Line numbers in messages
// are 1-based: lines[i] is line i + 1.
struct TextFile {
  std::string path;
  std::vector<std::string> lines;
};

// Sees the first non-blank line of a file (1-based line number) and throws
// aloft::host::Error when it is not the header the reader expects.
using FirstLineCheck = std::function<void(const std::string& line, std::size_t line_number)>;

// Reads the whole file, in chunks. A UTF-8 byte order mark (what Excel and many Windows
// tools put first) is dropped. Throws aloft::host::Error if it cannot be opened, is
// empty (no non-blank line), or holds NUL bytes (a binary file given to a text reader).
// Both checks that can be made early are made early — a NUL byte as soon as its chunk is
// read, `check_first_line` as soon as the first line is complete — so that a large file
// of something else is refused without being read whole.
TextFile read_text_file(const std::string& path, const FirstLineCheck& check_first_line = {});

// "PATH:LINE: problem" (LINE is 1-based), for aloft::host::Error.
std::string at_line(const std::string& path, std::size_t line_number, const std::string& problem);

// Splits a CSV line at commas. Cells are trimmed of spaces and tabs; a cell in double
// quotes may hold commas, and "" inside quotes is one quote. An unterminated quote
// throws (with the line number). With max_cells > 0 the last cell takes the rest of the
// line, commas included (a free-text comment column).
// `delimiter` is ',' unless a file says otherwise (csv_delimiter).
std::vector<std::string> split_csv_line(const std::string& line, const std::string& path,
                                        std::size_t line_number, std::size_t max_cells = 0,
                                        char delimiter = ',');

// The cell delimiter a CSV header row uses: ',' when it holds one outside quotes, else
// ';' or a tab (phyphox's and spreadsheets' other exports), else ','.
char csv_delimiter(const std::string& header_line);

// "1,5" -> "1.5": a number written with a decimal comma, as files delimited by ';' or tabs
// in many locales are (phyphox's "decimal comma" exports).
std::string with_decimal_point(std::string cell);

// The text without a leading UTF-8 byte order mark.
std::string without_byte_order_mark(const std::string& text);

// Splits at each tab, keeping empty cells (TRC: an empty cell is an occluded marker).
// Cells are trimmed of spaces.
std::vector<std::string> split_tab_line(const std::string& line);

// Splits at runs of spaces and tabs (OpenSim .mot/.sto rows); no empty cells.
std::vector<std::string> split_whitespace(const std::string& line);

// Trims spaces, tabs and '\r' from both ends.
std::string trim(const std::string& text);

// Lower-case copy (ASCII), for recognising header names.
std::string to_lower(const std::string& text);

// True for a line holding nothing but whitespace.
bool is_blank(const std::string& line);

// Parses a whole cell as a decimal number ("1.5", "-2e-3", "+4"). "nan" and "inf" parse
// to NaN and infinity; callers that do not accept them check std::isfinite. Anything
// else (empty, trailing text) throws "PATH:LINE: column NAME: 'cell' is not a number".
double parse_number(const std::string& cell, const std::string& path, std::size_t line_number,
                    const std::string& column_name);

// The same without throwing: false when the cell is not a whole number.
bool try_parse_number(const std::string& cell, double& out);

}  // namespace aloft::host
