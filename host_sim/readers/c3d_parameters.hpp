// The parameter section of a C3D file (C3D User Guide, chapter "The parameter section"):
// a 4-byte header (key, number of 512-byte blocks, processor type) followed by group and
// parameter records chained by "offset to next record" words.
//
// Parsed defensively: every byte is read through ByteView, every length and offset is
// checked against the section and the file, and a record that does not fit, points
// backwards, or has an unknown type stops the walk. The records read before that point
// are kept and `damage` says what went wrong and where; the caller decides whether what
// it needs is there. One flaw is repaired rather than fatal: an offset word that points
// outside the section is replaced by the record's length computed from its contents
// (listed in `repairs`).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "readers/c3d_numbers.hpp"

namespace aloft::host::c3d {

struct Parameter {
  std::string group;  // upper case, as groups are matched case-insensitively
  std::string name;   // upper case
  int type = 0;       // -1 char, 1 byte, 2 int16, 4 float
  std::vector<int> dimensions;
  std::vector<std::uint8_t> data;  // raw bytes, in the file's processor format
};

struct ParameterSection {
  Processor processor = Processor::intel;
  std::vector<Parameter> parameters;
  std::string damage;                // empty when the whole section was read
  std::vector<std::string> repairs;  // records read despite a bad offset word, and how

  const Parameter* find(const std::string& group, const std::string& name) const;
  // The index-th value of a numeric parameter as a double (nullopt: absent, not
  // numeric, or too short).
  std::optional<double> number(const std::string& group, const std::string& name,
                               std::size_t index = 0) const;
  // A char parameter as strings: dimensions [length, count...] give count strings of
  // `length` characters, trailing spaces removed; a one-dimensional one is one string.
  std::vector<std::string> strings(const std::string& group, const std::string& name) const;
};

// Reads the section that starts at 1-based block `first_block` and ends where the
// header (the file's first 512 bytes) says the data start. Throws
// aloft::host::Error (naming `path`) only when not even its 4-byte header is readable
// or the processor type is unknown; later damage is reported in `damage`.
ParameterSection parse_parameter_section(const ByteView& file, std::size_t first_block,
                                         const std::string& path);

}  // namespace aloft::host::c3d
