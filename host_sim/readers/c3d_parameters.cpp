#include "readers/c3d_parameters.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>

#include "common/commands.hpp"

namespace aloft::host::c3d {

namespace {

constexpr std::size_t kBlockBytes = 512;
// More records than this cannot be meant: stops a walk that a damaged chain could
// otherwise keep going for a very long time.
constexpr std::size_t kMaxRecords = 100000;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string rtrim(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.pop_back();
  return s;
}

// Names as read, with anything unprintable shown as '?': a damaged record's name goes
// into one-line messages.
std::string printable_upper(const std::uint8_t* bytes, std::size_t length) {
  std::string s;
  for (std::size_t i = 0; i < length; ++i) {
    const int c = bytes[i];
    s += std::isprint(c) ? static_cast<char>(std::toupper(c)) : '?';
  }
  return s;
}

// A name for a message: real C3D names are short, a damaged length is cut to "...".
std::string brief(const std::string& name) {
  constexpr std::size_t kShown = 24;
  return name.size() <= kShown ? name : name.substr(0, kShown) + "...";
}

std::string where(std::size_t offset) { return "at byte " + std::to_string(offset); }

// The distance from a record's offset word to the end of its description, computed
// from its contents; nullopt when they do not fit before `end` or exceed an int16.
std::optional<std::size_t> natural_record_length(const ByteView& file, std::size_t body, std::size_t end,
                                                 bool is_group, Processor) {
  std::size_t pos = body;
  if (!is_group) {
    const std::uint8_t* type_dims = file.at(pos, 2);
    if (!type_dims) return std::nullopt;
    const int type = static_cast<std::int8_t>(type_dims[0]);
    if (type != -1 && type != 1 && type != 2 && type != 4) return std::nullopt;
    const std::uint8_t* dims = file.at(pos + 2, type_dims[1]);
    if (!dims) return std::nullopt;
    std::size_t count = 1;
    for (std::size_t d = 0; d < type_dims[1] && count <= end; ++d) count *= dims[d];
    if (count > end) return std::nullopt;
    pos += 2 + type_dims[1] + count * static_cast<std::size_t>(std::abs(type));
  }
  const std::uint8_t* description = file.at(pos, 1);
  if (!description) return std::nullopt;
  pos += 1 + description[0];
  const std::size_t length = pos - (body - 2);
  if (pos > end || length > 32767) return std::nullopt;
  return length;
}

// The parameter section's 4-byte header: where it starts, its own block count and the
// processor whose number formats the rest of the file is written in.
struct SectionHead {
  std::size_t start = 0;
  std::size_t blocks = 0;
  Processor processor = Processor::intel;
};

SectionHead read_section_head(const ByteView& file, std::size_t first_block, const std::string& path) {
  if (first_block == 0) throw Error(path + ": header points to parameter block 0");
  SectionHead section;
  section.start = (first_block - 1) * kBlockBytes;
  const std::uint8_t* head = file.at(section.start, 4);
  if (!head) {
    throw Error(path + ": parameter section (block " + std::to_string(first_block) +
                ") lies beyond the end of the file");
  }
  const int processor = head[3];
  if (processor != 84 && processor != 85 && processor != 86) {
    throw Error(path + ": unknown processor type " + std::to_string(processor) +
                " in the parameter section (expected 84 Intel, 85 DEC or 86 MIPS)");
  }
  section.processor = static_cast<Processor>(processor);
  section.blocks = head[2];
  return section;
}

// The section ends where the data section starts (header word 9). Its own block count is
// only a fallback: writers get it wrong (c3d.org sample13 says 3 blocks and fills 6) or
// leave it 0.
std::size_t section_end(const ByteView& file, std::size_t first_block, const SectionHead& head) {
  const std::uint8_t* data_start_word = file.at(16, 2);
  const std::size_t data_start = data_start_word ? decode_u16(data_start_word, head.processor) : 0;
  std::size_t end = file.size();
  if (data_start > first_block) {
    end = std::min(end, (data_start - 1) * kBlockBytes);
  } else if (head.blocks > 0) {
    end = std::min(end, head.start + head.blocks * kBlockBytes);
  }
  return end;
}

// What a record starts with, common to groups and parameters: its name, its group id
// (negative for a group) and the offset word that chains it to the next record.
struct RecordHead {
  std::string name;
  int group_id = 0;
  std::size_t offset_pos = 0;    // where the offset word lies; offsets count from here
  std::int16_t next_offset = 0;  // 0: the last record
  std::size_t body() const { return offset_pos + 2; }
};

// The head of the record at `pos`, its offset word repaired if need be. nullopt at the end
// of the chain, and also on damage, which `section.damage` then names.
std::optional<RecordHead> read_record_head(const ByteView& file, std::size_t pos, std::size_t end,
                                           ParameterSection& section) {
  const std::uint8_t* record = pos + 2 <= end ? file.at(pos, 2) : nullptr;
  if (!record) {
    section.damage = "record " + where(pos) + " runs past the section's end";
    return std::nullopt;
  }
  const auto name_chars = static_cast<std::int8_t>(record[0]);
  if (name_chars == 0) return std::nullopt;  // the usual end of the chain
  const auto group_id = static_cast<std::int8_t>(record[1]);
  if (group_id == 0) {
    section.damage = "record " + where(pos) + " has group id 0";
    return std::nullopt;
  }
  const std::size_t name_length = static_cast<std::size_t>(std::abs(int{name_chars}));
  RecordHead head;
  head.offset_pos = pos + 2 + name_length;
  const std::uint8_t* name_bytes = head.offset_pos + 2 <= end ? file.at(pos + 2, name_length + 2) : nullptr;
  if (!name_bytes) {
    section.damage = "record name " + where(pos) + " runs past the section's end";
    return std::nullopt;
  }
  head.name = printable_upper(name_bytes, name_length);
  head.group_id = group_id;
  head.next_offset = decode_i16(name_bytes + name_length, section.processor);
  if (head.next_offset < 0 || head.offset_pos + static_cast<std::size_t>(head.next_offset) > end) {
    // Seen in the wild (c3d.org sample02, SGI files): one offset word left in the
    // byte order of another processor. The record's own contents then tell where
    // the next one starts.
    const auto natural = natural_record_length(file, head.body(), end, group_id < 0, section.processor);
    if (!natural) {
      section.damage =
          "record " + brief(head.name) + " " + where(pos) + " points to the next record outside the section";
      return std::nullopt;
    }
    section.repairs.push_back("record " + brief(head.name) + " " + where(pos) + ": offset " +
                              std::to_string(head.next_offset) + " replaced by its length " +
                              std::to_string(*natural));
    head.next_offset = static_cast<std::int16_t>(*natural);
  }
  return head;
}

// A parameter record's type, dimensions and data, all of which must lie before `limit`
// (the next record, or the section's end `end`). nullopt on damage, named in `damage`.
std::optional<Parameter> read_parameter(const ByteView& file, std::size_t pos, const RecordHead& head,
                                        std::size_t limit, std::size_t end, std::string& damage) {
  const std::size_t body = head.body();
  const std::string& name = head.name;
  const std::uint8_t* type_dims = body + 2 <= limit ? file.at(body, 2) : nullptr;
  if (!type_dims) {
    damage = "parameter " + brief(name) + " " + where(pos) + " is cut short";
    return std::nullopt;
  }
  Parameter p;
  p.name = name;
  p.type = static_cast<std::int8_t>(type_dims[0]);
  if (p.type != -1 && p.type != 1 && p.type != 2 && p.type != 4) {
    damage = "parameter " + brief(name) + " " + where(pos) + " has unknown type " + std::to_string(p.type);
    return std::nullopt;
  }
  const std::size_t dimension_count = type_dims[1];
  const std::uint8_t* dims =
      body + 2 + dimension_count <= limit ? file.at(body + 2, dimension_count) : nullptr;
  if (!dims) {
    damage = "parameter " + brief(name) + " " + where(pos) + ": dimensions cut short";
    return std::nullopt;
  }
  std::size_t count = 1;
  for (std::size_t d = 0; d < dimension_count; ++d) {
    p.dimensions.push_back(dims[d]);
    count *= dims[d];  // at most 255^255 in theory: bounded by the check below
    if (count > end) break;
  }
  const std::size_t values_start = body + 2 + dimension_count;
  const std::size_t data_size = count * static_cast<std::size_t>(std::abs(p.type));
  const std::uint8_t* data =
      count <= end && values_start + data_size <= limit ? file.at(values_start, data_size) : nullptr;
  if (!data) {
    damage = "parameter " + brief(name) + " " + where(pos) + ": data runs past the record";
    return std::nullopt;
  }
  p.data.assign(data, data + data_size);
  return p;
}

// The records as read, before each parameter is given its group's name: a group's
// record may come after its parameters'.
struct Records {
  struct Pending {
    int group_id;
    Parameter parameter;
  };
  std::map<int, std::string> group_names;
  std::vector<Pending> pending;
};

// Follows the chain of records from `pos` until its last record or the first damage.
Records walk_records(const ByteView& file, std::size_t pos, std::size_t end, ParameterSection& section) {
  Records records;
  for (std::size_t count = 0;; ++count) {
    if (count == kMaxRecords) {
      section.damage = "too many records (" + std::to_string(kMaxRecords) + ")";
      break;
    }
    const std::optional<RecordHead> head = read_record_head(file, pos, end, section);
    if (!head) break;
    const std::size_t next = head->offset_pos + static_cast<std::size_t>(head->next_offset);
    // The record's contents must lie before the next record (or the section's end).
    const std::size_t limit = head->next_offset == 0 ? end : next;
    if (head->group_id < 0) {
      records.group_names[-head->group_id] = head->name;
    } else {
      std::optional<Parameter> p = read_parameter(file, pos, *head, limit, end, section.damage);
      if (!p) break;
      records.pending.push_back({head->group_id, std::move(*p)});
    }
    if (head->next_offset == 0) break;  // the last record
    pos = next;                         // always forward: next_offset > 0 here
  }
  return records;
}

}  // namespace

const Parameter* ParameterSection::find(const std::string& group, const std::string& name) const {
  const std::string g = upper(group);
  const std::string n = upper(name);
  for (const Parameter& p : parameters) {
    if (p.group == g && p.name == n) return &p;
  }
  return nullptr;
}

std::optional<double> ParameterSection::number(const std::string& group, const std::string& name,
                                               std::size_t index) const {
  const Parameter* p = find(group, name);
  if (!p || p->type <= 0) return std::nullopt;
  const auto width = static_cast<std::size_t>(p->type);
  if ((index + 1) * width > p->data.size()) return std::nullopt;
  const std::uint8_t* bytes = p->data.data() + index * width;
  switch (p->type) {
    case 1: return static_cast<double>(static_cast<std::int8_t>(bytes[0]));
    case 2: return static_cast<double>(decode_i16(bytes, processor));
    case 4: return static_cast<double>(decode_f32(bytes, processor));
    default: return std::nullopt;
  }
}

std::vector<std::string> ParameterSection::strings(const std::string& group, const std::string& name) const {
  const Parameter* p = find(group, name);
  std::vector<std::string> out;
  if (!p || p->type != -1) return out;
  const std::string all(p->data.begin(), p->data.end());
  if (p->dimensions.size() <= 1) {
    out.push_back(rtrim(all));
    return out;
  }
  const auto length = static_cast<std::size_t>(p->dimensions[0]);
  if (length == 0) return out;
  for (std::size_t start = 0; start + length <= all.size(); start += length) {
    out.push_back(rtrim(all.substr(start, length)));
  }
  return out;
}

ParameterSection parse_parameter_section(const ByteView& file, std::size_t first_block,
                                         const std::string& path) {
  const SectionHead head = read_section_head(file, first_block, path);
  ParameterSection section;
  section.processor = head.processor;
  const std::size_t end = section_end(file, first_block, head);
  Records records = walk_records(file, head.start + 4, end, section);
  for (Records::Pending& entry : records.pending) {
    const auto group = records.group_names.find(entry.group_id);
    entry.parameter.group =
        group != records.group_names.end() ? group->second : "GROUP" + std::to_string(entry.group_id);
    section.parameters.push_back(std::move(entry.parameter));
  }
  return section;
}

}  // namespace aloft::host::c3d
