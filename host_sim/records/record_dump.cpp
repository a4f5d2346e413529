#include "records/record_dump.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/commands.hpp"
#include "common/file_error.hpp"

namespace aloft::host {
namespace {

// A record area is a few erase blocks; anything far larger is not one.
constexpr std::uint64_t largest_dump_bytes = 64ull << 20;

std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw Error(path + ": a folder, not a flight record dump");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw FileError(path + ": cannot be opened");
  const std::streamoff size = in.tellg();
  if (size < 0) throw FileError(path + ": cannot be read");
  if (size == 0) throw Error(path + ": empty file, not a flight record dump");
  if (static_cast<std::uint64_t>(size) > largest_dump_bytes)
    throw Error(path + ": " + std::to_string(size) + " bytes, too large to be a flight record dump");
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) throw FileError(path + ": cannot be read");
  return bytes;
}

bool starts_with_magic(const std::uint8_t* p, std::size_t size) {
  return size >= 4 && aloft::bytes_equal(p, flight_record_magic, 4);
}

struct Tally {
  std::uint64_t magic_slots = 0;
  std::uint64_t first_unknown_version_offset = 0;
  std::uint16_t first_unknown_version = 0;
  bool unknown_version_seen = false;
};

void classify_slot(const std::uint8_t* p, std::uint64_t offset, RecordDump& dump, Tally& tally) {
  FlightRecord record;
  const SlotState state = decode_flight_record(p, record);
  if (starts_with_magic(p, flight_record_size)) ++tally.magic_slots;
  if (state == SlotState::valid) {
    dump.records.push_back({offset, record});
  } else if (state == SlotState::erased) {
    ++dump.erased_slots;
  } else if (state == SlotState::unknown_version) {
    const std::uint16_t version = le::get_u16(p + 4);
    if (!tally.unknown_version_seen) {
      tally.unknown_version_seen = true;
      tally.first_unknown_version = version;
      tally.first_unknown_version_offset = offset;
    }
    dump.problems.push_back({offset, "record version " + std::to_string(version) + ", size " +
                                         std::to_string(le::get_u16(p + 6)) + " not known"});
  } else {
    dump.problems.push_back({offset, describe(state)});
  }
}

// The bytes after the last whole slot: nothing if erased, a problem otherwise.
void classify_tail(const std::uint8_t* p, std::size_t size, std::uint64_t offset, RecordDump& dump,
                   Tally& tally) {
  if (std::all_of(p, p + size, [](std::uint8_t b) { return b == 0xFF; })) return;
  if (starts_with_magic(p, size)) ++tally.magic_slots;
  dump.problems.push_back({offset, "truncated record (" + std::to_string(size) + " of " +
                                       std::to_string(flight_record_size) + " bytes)"});
}

}  // namespace

RecordDump read_record_dump(const std::string& path) {
  return with_file_context(path, [&] {
    const std::vector<std::uint8_t> bytes = read_bytes(path);
    RecordDump dump;
    Tally tally;
    std::uint64_t offset = 0;
    for (; offset + flight_record_size <= bytes.size(); offset += flight_record_size, ++dump.slots)
      classify_slot(bytes.data() + offset, offset, dump, tally);
    if (offset < bytes.size())
      classify_tail(bytes.data() + offset, bytes.size() - offset, offset, dump, tally);
    if (dump.records.empty() && tally.unknown_version_seen)
      throw Error(path + ": record version " + std::to_string(tally.first_unknown_version) + " at offset " +
                  std::to_string(tally.first_unknown_version_offset) +
                  " is not one this aloft reads (versions " + std::to_string(flight_record_oldest_version) +
                  " to " + std::to_string(flight_record_version) + ")");
    if (tally.magic_slots == 0 && !dump.problems.empty())
      throw Error(path + ": not a flight record dump (no slot holds a record)");
    std::stable_sort(
        dump.records.begin(), dump.records.end(),
        [](const ListedRecord& a, const ListedRecord& b) { return a.record.sequence < b.record.sequence; });
    return dump;
  });
}

}  // namespace aloft::host
