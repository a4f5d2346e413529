// One flight record: what the onboard check found about one flight, in a fixed-size,
// versioned slot of 128 bytes that a firmware appends to its record ring
// (aloft/records/record_ring.hpp) and `aloft records` reads back from a dump. Every field is
// little-endian and written byte by byte (aloft/records/little_endian.hpp); floats are IEEE-754
// binary32, "bf16" their upper 16 bits rounded (3 significant digits); angles are radians.
// Versions 1 and 2 share one layout and differ only in what the settings hash covers
// (aloft/records/settings_hash.hpp): version 2 walks the settings' one list with the build
// constants; version 1, written before, hashed a shorter list. Version 3 keeps the flight's
// own tensor estimate (aloft/onboard/tensor_estimate.hpp) where versions 1 and 2 kept the
// first seeds' figures, and hashes the settings' list with the tensor estimate's. Version 4
// keeps version 3's layout and hashes the list without `lever_arm.half_block_samples` (the
// lever arm's trust test no longer splits a flight's fit in halves). All four are read, and
// a record says which it is. Layout:
//   offset size field
//        0    4 magic "ALFR" (41 4C 46 52)
//        4    2 version (4; 1 to 3 for records written before)
//        6    2 record size in bytes (128)
//        8    4 sequence number: 1, 2, ... over the life of the ring, across wraps
//       12    4 flight number within its recording (FlightResult::flight_number)
//       16    8 release time, µs on the firmware's clock
//       24    8 landing time, µs (the last sample's time when the flight did not land)
//       32    4 airborne samples fed to the check
//       36    4 gaps while airborne
//       40    4 clipped samples while airborne
//       44    4 flags: bit 0 landed, bit 1 turned, bit 2 IMU position estimated; versions 3, 4:
//                bit 3 tensor determined, bit 4 absolute moments, bits 5-7 its note
//                (TensorEstimateNote)
//       48    4 comparisons behind the overall statistics
//       52    4 RMS deviation angle, overall (rad)
//       56    4 RMS relative error, overall
//       60    4 maximum deviation angle (rad)
//       64    4 maximum relative error
//   versions 1 and 2:
//       68    4 seeds stored below (0 to 4)
//       72   32 the first 4 seeds: RMS deviation angle (rad), RMS relative error; 4+4 each
//      112    4 reserved, 0
//   versions 3 and 4, the tensor estimate:
//       68   12 principal moments, ascending: kg·m² when absolute, else I1/I3, I2/I3, 1
//       80   12 principal axes: x, y, z of the quaternion (w >= 0, the rest of a unit one)
//       92    4 bf16: 95 % half-widths of I1/I3, I2/I3
//       96    6 bf16: 95 % half-widths of the moments (absolute only, else 0)
//      102    2 bf16: the angle within which principal axis 1 is held (95 %)
//      112    4 bf16: the same for axes 2 and 3
//   all versions:
//      104    4 tensor hash (aloft/records/flight_record_from_result.hpp says what is hashed)
//      108    4 settings hash (same)
//      116    4 CRC-32 (aloft/records/crc32.hpp) of bytes 0..115
//      120    4 commit marker "COMT" (43 4F 4D 54), programmed after everything else
//      124    4 left erased (0xFF)
// The body (bytes 0..119) is programmed first, the commit marker last and on its own
// (aloft/records/record_ring.hpp says why); a slot counts only when both are there and the CRC
// matches.
#pragma once

#include <cstddef>
#include <cstdint>

#include "aloft/records/crc32.hpp"
#include "aloft/records/little_endian.hpp"

namespace aloft {

constexpr std::uint32_t flight_record_size = 128;
constexpr std::uint32_t flight_record_body_size = 120;  // programmed first: bytes 0..119
constexpr std::uint32_t flight_record_crc_offset = 116;
constexpr std::uint32_t flight_record_commit_offset = 120;
constexpr std::uint16_t flight_record_version = 4;         // the version written
constexpr std::uint16_t flight_record_oldest_version = 1;  // the oldest one read
constexpr std::uint32_t flight_record_seeds = 4;
constexpr std::uint8_t flight_record_magic[4] = {0x41, 0x4C, 0x46, 0x52};   // "ALFR"
constexpr std::uint8_t flight_record_commit[4] = {0x43, 0x4F, 0x4D, 0x54};  // "COMT"

struct FlightRecordSeed {
  float rms_da_rad = 0.0f;
  float rms_rel_err = 0.0f;
};

// The tensor estimate a version 3 record keeps (TensorEstimate's figures, in float).
struct FlightRecordTensor {
  bool determined = false;
  bool absolute = false;
  std::uint8_t note = 0;       // TensorEstimateNote
  float principal[3] = {};     // kg·m² when absolute, else I1/I3, I2/I3, 1
  float axes_xyz[3] = {};      // quaternion x, y, z; w = sqrt(1 - x² - y² - z²) >= 0
  float ratios_95[2] = {};     // half-widths
  float principal_95[3] = {};  // half-widths, absolute only
  float axes_95_rad[3] = {};
};

struct FlightRecord {
  std::uint16_t version = flight_record_version;  // as read; encoding writes flight_record_version
  std::uint32_t sequence = 0;
  std::uint32_t flight_number = 0;
  std::uint64_t release_us = 0;
  std::uint64_t landing_us = 0;
  std::uint32_t samples = 0;
  std::uint32_t gaps = 0;
  std::uint32_t clipped_samples = 0;
  bool landed = false;
  bool turned = false;
  bool imu_position_estimated = false;
  std::uint32_t comparisons = 0;
  float rms_da_rad = 0.0f;
  float rms_rel_err = 0.0f;
  float max_da_rad = 0.0f;
  float max_rel_err = 0.0f;
  std::uint32_t seeds_stored = 0;
  FlightRecordSeed seeds[flight_record_seeds] = {};  // versions 1 and 2
  FlightRecordTensor tensor;                         // version 3
  std::uint32_t tensor_hash = 0;
  std::uint32_t settings_hash = 0;
};

// What a 128-byte slot holds.
enum class SlotState : std::uint8_t {
  valid,            // a committed record whose CRC matches
  erased,           // every byte 0xFF: free
  no_magic,         // not a record's first bytes: torn before the magic, or foreign bytes
  unknown_version,  // the magic, but a version (or size) this code does not read
  not_committed,    // no commit marker: the write was cut (a torn record)
  crc_mismatch,     // committed, but the bytes changed since (or a torn erase left them)
};

constexpr const char* describe(SlotState s) {
  switch (s) {
    case SlotState::valid: return "valid record";
    case SlotState::erased: return "erased";
    case SlotState::no_magic: return "no record magic (torn or foreign bytes)";
    case SlotState::unknown_version: return "record version not known";
    case SlotState::not_committed: return "torn record (no commit marker)";
    case SlotState::crc_mismatch: return "CRC-32 mismatch (corrupt record)";
  }
  return "unknown slot state";
}

// The record's 128 bytes: body, CRC, commit marker, and the erased tail.
inline void encode_flight_record(const FlightRecord& r, std::uint8_t (&slot)[flight_record_size]) {
  std::uint8_t* p = slot;
  for (std::uint32_t i = 0; i < flight_record_size; ++i) p[i] = 0xFF;
  for (int i = 0; i < 4; ++i) p[i] = flight_record_magic[i];
  le::put_u16(p + 4, flight_record_version);
  le::put_u16(p + 6, static_cast<std::uint16_t>(flight_record_size));
  le::put_u32(p + 8, r.sequence);
  le::put_u32(p + 12, r.flight_number);
  le::put_u64(p + 16, r.release_us);
  le::put_u64(p + 24, r.landing_us);
  le::put_u32(p + 32, r.samples);
  le::put_u32(p + 36, r.gaps);
  le::put_u32(p + 40, r.clipped_samples);
  const FlightRecordTensor& t = r.tensor;
  le::put_u32(p + 44, (r.landed ? 1u : 0u) | (r.turned ? 2u : 0u) | (r.imu_position_estimated ? 4u : 0u) |
                          (t.determined ? 8u : 0u) | (t.absolute ? 16u : 0u) | ((t.note & 7u) << 5));
  le::put_u32(p + 48, r.comparisons);
  le::put_f32(p + 52, r.rms_da_rad);
  le::put_f32(p + 56, r.rms_rel_err);
  le::put_f32(p + 60, r.max_da_rad);
  le::put_f32(p + 64, r.max_rel_err);
  for (int i = 0; i < 3; ++i) {
    le::put_f32(p + 68 + 4 * i, t.principal[i]);
    le::put_f32(p + 80 + 4 * i, t.axes_xyz[i]);
    le::put_bf16(p + 96 + 2 * i, t.principal_95[i]);
  }
  le::put_bf16(p + 92, t.ratios_95[0]);
  le::put_bf16(p + 94, t.ratios_95[1]);
  le::put_bf16(p + 102, t.axes_95_rad[0]);
  le::put_bf16(p + 112, t.axes_95_rad[1]);
  le::put_bf16(p + 114, t.axes_95_rad[2]);
  le::put_u32(p + 104, r.tensor_hash);
  le::put_u32(p + 108, r.settings_hash);
  le::put_u32(p + flight_record_crc_offset, crc32(p, flight_record_crc_offset));
  for (std::uint32_t i = 0; i < 4; ++i) p[flight_record_commit_offset + i] = flight_record_commit[i];
}

// Versions 1 and 2: the first seeds' figures.
inline void decode_seeds(const std::uint8_t* p, FlightRecord& r) {
  const std::uint32_t seeds = le::get_u32(p + 68);
  r.seeds_stored = seeds < flight_record_seeds ? seeds : flight_record_seeds;
  for (std::uint32_t i = 0; i < flight_record_seeds; ++i) {
    r.seeds[i].rms_da_rad = le::get_f32(p + 72 + 8 * i);
    r.seeds[i].rms_rel_err = le::get_f32(p + 76 + 8 * i);
  }
}

// Version 3: the tensor estimate.
inline void decode_tensor(const std::uint8_t* p, std::uint32_t flags, FlightRecordTensor& t) {
  t.determined = (flags & 8u) != 0;
  t.absolute = (flags & 16u) != 0;
  t.note = static_cast<std::uint8_t>((flags >> 5) & 7u);
  for (int i = 0; i < 3; ++i) {
    t.principal[i] = le::get_f32(p + 68 + 4 * i);
    t.axes_xyz[i] = le::get_f32(p + 80 + 4 * i);
    t.principal_95[i] = le::get_bf16(p + 96 + 2 * i);
  }
  t.ratios_95[0] = le::get_bf16(p + 92);
  t.ratios_95[1] = le::get_bf16(p + 94);
  t.axes_95_rad[0] = le::get_bf16(p + 102);
  t.axes_95_rad[1] = le::get_bf16(p + 112);
  t.axes_95_rad[2] = le::get_bf16(p + 114);
}

// The fields of a slot whose state is `valid` (left untouched otherwise).
inline void decode_flight_record_fields(const std::uint8_t* p, FlightRecord& r) {
  r.version = le::get_u16(p + 4);
  r.sequence = le::get_u32(p + 8);
  r.flight_number = le::get_u32(p + 12);
  r.release_us = le::get_u64(p + 16);
  r.landing_us = le::get_u64(p + 24);
  r.samples = le::get_u32(p + 32);
  r.gaps = le::get_u32(p + 36);
  r.clipped_samples = le::get_u32(p + 40);
  const std::uint32_t flags = le::get_u32(p + 44);
  r.landed = (flags & 1u) != 0;
  r.turned = (flags & 2u) != 0;
  r.imu_position_estimated = (flags & 4u) != 0;
  r.comparisons = le::get_u32(p + 48);
  r.rms_da_rad = le::get_f32(p + 52);
  r.rms_rel_err = le::get_f32(p + 56);
  r.max_da_rad = le::get_f32(p + 60);
  r.max_rel_err = le::get_f32(p + 64);
  if (r.version <= 2) {
    decode_seeds(p, r);
  } else {
    decode_tensor(p, flags, r.tensor);
  }
  r.tensor_hash = le::get_u32(p + 104);
  r.settings_hash = le::get_u32(p + 108);
}

inline bool bytes_equal(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (a[i] != b[i]) return false;
  return true;
}

// Classifies a 128-byte slot. The checks run from the cheapest to the CRC; a version
// this code does not know is named as such before its commit marker or CRC is looked at,
// since a later layout may place them elsewhere.
inline SlotState classify_slot(const std::uint8_t* slot) {
  bool erased = true;
  for (std::uint32_t i = 0; i < flight_record_size && erased; ++i) erased = slot[i] == 0xFF;
  if (erased) return SlotState::erased;
  if (!bytes_equal(slot, flight_record_magic, 4)) return SlotState::no_magic;
  const std::uint16_t version = le::get_u16(slot + 4);
  if (version < flight_record_oldest_version || version > flight_record_version ||
      le::get_u16(slot + 6) != flight_record_size)
    return SlotState::unknown_version;
  if (!bytes_equal(slot + flight_record_commit_offset, flight_record_commit, 4))
    return SlotState::not_committed;
  if (le::get_u32(slot + flight_record_crc_offset) != crc32(slot, flight_record_crc_offset))
    return SlotState::crc_mismatch;
  return SlotState::valid;
}

// The sequence number of a slot classified valid.
inline std::uint32_t flight_record_sequence(const std::uint8_t* slot) { return le::get_u32(slot + 8); }

// Classifies a slot and fills `out` when it holds a valid record.
inline SlotState decode_flight_record(const std::uint8_t* slot, FlightRecord& out) {
  const SlotState state = classify_slot(slot);
  if (state == SlotState::valid) decode_flight_record_fields(slot, out);
  return state;
}

}  // namespace aloft
