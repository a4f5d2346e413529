// Reading a raw dump of the flight-record area (the bytes of the record ring's erase
// blocks, aloft/records/record_ring.hpp) as `aloft records` does: every 128-byte slot from
// offset 0 is classified (aloft/records/flight_record.hpp). Valid records are listed in sequence
// order; each slot that is neither erased nor valid is a problem named by its offset and
// reason, and the dump is still read. Refused with aloft::host::Error (one line naming the
// file): a file that cannot be read, an empty file, a file in which no slot holds a
// record's magic (foreign bytes), or one whose only records are of a version this code
// does not know.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "aloft/records/flight_record.hpp"

namespace aloft::host {

struct ListedRecord {
  std::uint64_t offset = 0;  // of its slot in the dump
  FlightRecord record;
};

struct DumpProblem {
  std::uint64_t offset = 0;
  std::string reason;
};

struct RecordDump {
  std::vector<ListedRecord> records;  // by sequence number
  std::vector<DumpProblem> problems;  // by offset
  std::uint64_t slots = 0;            // whole 128-byte slots in the dump
  std::uint64_t erased_slots = 0;
};

RecordDump read_record_dump(const std::string& path);

}  // namespace aloft::host
